#include "tone/density_filter.h"

#include "base/parallel.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace gridifs {
namespace {

// flam3's Gaussian filter and its support (filters.c); the scale of the Gaussian does not
// matter since every kernel is normalised.
constexpr double kGaussianSupport = 1.5;
double gaussian(double x) { return std::exp(-2.0 * x * x); }

// flam3: below this many hits every integer count gets its own kernel; above it, kernels are
// spaced by count^curve so that their number stays small.
constexpr double kDeThreshold = 100.0;
constexpr int kKeepThreshold = 100;

// Rows are independent (each output row reads the input, writes only itself), so any split
// gives the same image.
template <class Body>
void forRows(int rows, int threads, const Body& body) {
  constexpr std::size_t kRowsPerChunk = 8;
  parallelFor(std::size_t(std::max(rows, 0)), rows < 64 ? 1 : std::clamp(threads, 1, 64), kRowsPerChunk,
              [&](std::size_t begin, std::size_t end) { body(int(begin), int(end)); });
}

}  // namespace

DensityEstimator::DensityEstimator(double radius, double minimum, double curve, int supersample)
    : supersample_(supersample), curve_(curve) {
  if (!(radius > 0.0) || !(minimum >= 0.0) || minimum > radius || !(curve > 0.0) || supersample < 1 || radius > 1000.0)
    throw std::invalid_argument("density estimator: need 0 <= minimum <= radius <= 1000, curve > 0, supersample >= 1");
  // Draves & Reckase 2003, §8: the kernel is scaled by the supersampling; the +1 is flam3's assumed
  // distance to the first neighbouring bucket.
  const double compMax = radius * supersample + 1.0;
  const double compMin = minimum * supersample + 1.0;
  const double countD = std::pow(compMax / compMin, 1.0 / curve);
  if (countD > 1e7) throw std::invalid_argument("density estimator: too many kernels (curve too small)");
  const int count = int(std::ceil(countD));
  int maxIndex;
  if (count > kKeepThreshold) {
    maxIndex = int(std::ceil(kDeThreshold + std::pow(count - kDeThreshold, curve))) + 1;
    maxFilteredCounts_ = int(std::pow(double(maxIndex - kDeThreshold), 1.0 / curve)) + kDeThreshold;
  } else {
    maxIndex = count;
    maxFilteredCounts_ = maxIndex;
  }
  const int half = int(std::ceil(compMax)) - 1;
  maxFilterIndex_ = 0;
  for (int k = 0; k < maxIndex; ++k) {
    double h;
    if (k < kKeepThreshold) {
      h = compMax / std::pow(k + 1.0, curve);
    } else {
      const double adjusted = std::pow(double(k - kKeepThreshold), 1.0 / curve) + kKeepThreshold;
      h = compMax / std::pow(adjusted + 1.0, curve);
    }
    bool last = false;
    if (h <= compMin) {
      h = compMin;
      maxFilterIndex_ = k;
      last = true;
    }
    // flam3 normalises the kernel over every offset with |d| <= h but applies only the offsets
    // with |dx|, |dy| <= ceil(h) - 1 (the "+1" above is the distance to the first neighbour):
    // the narrowest kernel (h = 1) keeps a dense bucket in place and drops ~4% of its energy.
    // We do the same so that dense regions stay as crisp (and as bright) as flam3's.
    const int reach = int(std::ceil(h)) - 1;
    std::vector<Tap> taps;
    double sum = 0.0;
    for (int dy = -half; dy <= half; ++dy)
      for (int dx = -half; dx <= half; ++dx) {
        const double d = std::sqrt(double(dx * dx + dy * dy)) / h;
        if (d > 1.0) continue;
        const double w = gaussian(kGaussianSupport * d);
        sum += w;
        if (std::abs(dx) <= reach && std::abs(dy) <= reach) taps.push_back({dx, dy, float(w)});
      }
    for (Tap& t : taps) t.weight = float(t.weight / sum);
    widths_.push_back(h);
    taps_.push_back(std::move(taps));
    if (last) break;
  }
  if (maxFilterIndex_ == 0) maxFilterIndex_ = int(widths_.size()) - 1;
}

int DensityEstimator::kernelIndex(double hits) const {
  int index;
  if (hits > maxFilteredCounts_)
    index = maxFilterIndex_;
  else if (hits <= kDeThreshold)
    index = int(std::ceil(hits)) - 1;
  else
    index = int(kDeThreshold) + int(std::floor(std::pow(hits - kDeThreshold, curve_)));
  return std::clamp(index, 0, maxFilterIndex_);
}

double DensityEstimator::neighbourhoodHits(const FlameHistogram& histogram, int x, int y) const {
  const int r = supersample_ / 2;
  double hits = 0.0;
  for (int j = std::max(0, y - r); j <= std::min(histogram.height - 1, y + r); ++j)
    for (int i = std::max(0, x - r); i <= std::min(histogram.width - 1, x + r); ++i) hits += histogram.bucket(i, j)[3];
  if (supersample_ % 2 == 0) hits *= std::pow(supersample_ / (supersample_ + 1.0), 2.0);
  return hits;
}

AccumBuffer logScaleAndEstimate(const FlameHistogram& histogram, const LogDensityScale& scale,
                                const DensityEstimator* estimator) {
  AccumBuffer out(histogram.width, histogram.height);
  const int w = histogram.width, h = histogram.height;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const float* b = histogram.bucket(x, y);
      const double hits = b[3];
      if (hits <= 0.0) continue;
      // Draves & Reckase 2003, §4: scale all four channels by log(α)/α (flam3's k1·log(1 + α·k2)/α).
      const float ls = float(scale.factor(hits));
      const float c[4] = {b[0] * ls, b[1] * ls, b[2] * ls, b[3] * ls};
      if (!estimator) {
        float* o = out.at(x, y);
        for (int k = 0; k < 4; ++k) o[k] += c[k];
        continue;
      }
      // Draves & Reckase 2003, §8: a kernel whose width is inversely related to the density.
      const auto& taps = estimator->taps(estimator->kernelIndex(estimator->neighbourhoodHits(histogram, x, y)));
      for (const auto& t : taps) {
        const int tx = x + t.dx, ty = y + t.dy;
        if (tx < 0 || ty < 0 || tx >= w || ty >= h) continue;
        float* o = out.at(tx, ty);
        for (int k = 0; k < 4; ++k) o[k] += t.weight * c[k];
      }
    }
  }
  return out;
}

std::vector<double> spatialFilterTaps(int supersample, double radius) {
  if (supersample < 1 || !(radius >= 0.0) || radius > 100.0)
    throw std::invalid_argument("spatial filter: need supersample >= 1 and 0 <= radius <= 100");
  // flam3_create_spatial_filter with the Gaussian kernel (support 1.5).
  const double fw = 2.0 * kGaussianSupport * supersample * radius;
  int width = int(fw) + 1;
  if ((width ^ supersample) & 1) ++width;  // same parity as the supersampling: centred on the block
  const double adjust = fw > 0.0 ? kGaussianSupport * width / fw : 1.0;
  std::vector<double> taps(std::size_t(width), 0.0);
  double sum = 0.0;
  for (int i = 0; i < width; ++i) {
    const double x = ((2.0 * i + 1.0) / width - 1.0) * adjust;
    taps[std::size_t(i)] = gaussian(x);
    sum += taps[std::size_t(i)];
  }
  for (double& t : taps) t /= sum;
  return taps;
}

AccumBuffer spatialFilterDown(AccumBuffer accum, int supersample, double radius, int outWidth, int outHeight,
                              int threads) {
  if (accum.width != outWidth * supersample || accum.height != outHeight * supersample)
    throw std::invalid_argument("spatial filter: the buffer is not supersample× the output size");
  const std::vector<double> taps = spatialFilterTaps(supersample, radius);
  const int width = int(taps.size());
  const int offset = (width - supersample) / 2;  // first tap relative to the pixel's block
  // Separable: first along x (full bucket rows → output columns), then along y.
  AccumBuffer horizontal(outWidth, accum.height);
  forRows(accum.height, threads, [&](int begin, int end) {
    for (int y = begin; y < end; ++y)
      for (int x = 0; x < outWidth; ++x) {
        double t[4] = {0, 0, 0, 0};
        const int x0 = x * supersample - offset;
        for (int i = 0; i < width; ++i) {
          const int sx = x0 + i;
          if (sx < 0 || sx >= accum.width) continue;
          const float* a = accum.at(sx, y);
          if (a[3] == 0.f && a[0] == 0.f) continue;
          for (int k = 0; k < 4; ++k) t[k] += taps[std::size_t(i)] * a[k];
        }
        float* o = horizontal.at(x, y);
        for (int k = 0; k < 4; ++k) o[k] = float(t[k]);
      }
  });
  // The full-size buffer is done with: let it go before the output is allocated.
  std::vector<float>().swap(accum.data);
  AccumBuffer out(outWidth, outHeight);
  forRows(outHeight, threads, [&](int begin, int end) {
    for (int y = begin; y < end; ++y) {
      const int y0 = y * supersample - offset;
      for (int j = 0; j < width; ++j) {
        const int sy = y0 + j;
        if (sy < 0 || sy >= horizontal.height) continue;
        const float wj = float(taps[std::size_t(j)]);
        const float* row = horizontal.at(0, sy);
        float* o = out.at(0, y);
        for (int i = 0; i < outWidth * 4; ++i) o[i] += wj * row[i];
      }
    }
  });
  return out;
}

}  // namespace gridifs
