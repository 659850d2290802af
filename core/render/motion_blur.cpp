#include "render/motion_blur.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

namespace gridifs {

std::vector<double> motionBlurWeights(int n, double fade) {
  n = std::max(1, n);
  std::vector<double> w(std::size_t(n), 1.0);
  if (!(fade > 0.0)) return w;
  double total = 0.0;
  for (int i = 0; i < n; ++i) total += w[std::size_t(i)] = std::pow((i + 1.0) / n, fade);
  for (double& v : w) v *= n / total;
  return w;
}

void addTimeSample(TimeSampleSum& sum, RenderImage&& sample, double weight) {
  ++sum.count;
  if (sum.count == 1) {
    sum.image = std::move(sample);
    sum.firstWeight = weight;
    if (weight != 1.0)
      for (std::size_t i = 0; i < sum.image.colorSums.size(); ++i)
        if (i % 4 != 3) sum.image.colorSums[i] = float(weight * sum.image.colorSums[i]);
    return;
  }
  if (sum.rgbaSum.empty()) {
    sum.rgbaSum.resize(sum.image.rgba.size());
    for (std::size_t i = 0; i < sum.image.rgba.size(); ++i) sum.rgbaSum[i] = sum.firstWeight * sum.image.rgba[i];
  }
  RenderImage& image = sum.image;
  if (sample.rgba.size() != image.rgba.size() || sample.density.size() != image.density.size() ||
      sample.colorSums.size() != image.colorSums.size())
    throw std::invalid_argument("the time samples of a frame differ in size");
  for (std::size_t i = 0; i < sample.rgba.size(); ++i) sum.rgbaSum[i] += weight * sample.rgba[i];
  for (std::size_t i = 0; i < sample.depth.size(); ++i) image.depth[i] = std::min(image.depth[i], sample.depth[i]);
  for (std::size_t i = 0; i < sample.density.size(); ++i)
    image.density[i] =
        std::uint32_t(std::min<std::uint64_t>(std::uint64_t(image.density[i]) + sample.density[i], UINT32_MAX));
  // Draves & Reckase 2003, §9, directional motion blur: the colour is scaled, the density is not
  // (varying the density made the density estimation look unnatural, as the paper found).
  for (std::size_t i = 0; i < sample.colorSums.size(); ++i)
    image.colorSums[i] += i % 4 == 3 ? sample.colorSums[i] : float(weight * sample.colorSums[i]);
  image.stats.samples += sample.stats.samples;
  image.stats.badSamples += sample.stats.badSamples;
  image.stats.plotted += sample.stats.plotted;
  image.stats.budget += sample.stats.budget;
}

void addTimeSample(TimeSampleSum& sum, const RenderImage& sample, double weight) {
  addTimeSample(sum, RenderImage(sample), weight);
}

RenderImage finishTimeSamples(TimeSampleSum&& sum) {
  RenderImage image = std::move(sum.image);
  if (sum.count <= 1) return image;  // one time sample: its weight is 1, the image is the sample's
  const double n = double(std::max(1, sum.count));
  image.hitPixels = 0;
  for (std::size_t i = 0; i < sum.rgbaSum.size(); ++i) {
    image.rgba[i] = std::uint8_t(std::clamp(std::lround(sum.rgbaSum[i] / n), 0l, 255l));
    if (i % 4 == 3 && sum.rgbaSum[i] > 0.0) {
      image.rgba[i] = 255;  // plotted in at least one time sample
      ++image.hitPixels;
    }
  }
  return image;
}

}  // namespace gridifs
