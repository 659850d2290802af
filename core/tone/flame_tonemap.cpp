#include "tone/flame_tonemap.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "base/parallel.h"
#include "tone/density_filter.h"

namespace gridifs {
namespace {

// flam3 scales by 256 where its buffers are 0..255: output = 256/255 × the normalised value.
// Kept so that a flam3 genome and a GridIFS project with the same settings match.
constexpr double kWhiteScale = 256.0 / 255.0;
// flam3's k1 = contrast·brightness·PREFILTER_WHITE·268/256 (an empirical constant of flam3).
constexpr double kBrightnessScale = 268.0 / 256.0;

void rgbToHsv(const double rgb[3], double hsv[3]) {
  const double mx = std::max({rgb[0], rgb[1], rgb[2]}), mn = std::min({rgb[0], rgb[1], rgb[2]});
  const double delta = mx - mn;
  hsv[2] = mx;
  hsv[1] = mx > 0.0 ? delta / mx : 0.0;
  double h = 0.0;
  if (hsv[1] > 0.0 && delta > 0.0) {
    if (rgb[0] == mx)
      h = (rgb[1] - rgb[2]) / delta;
    else if (rgb[1] == mx)
      h = 2.0 + (rgb[2] - rgb[0]) / delta;
    else
      h = 4.0 + (rgb[0] - rgb[1]) / delta;
    if (h < 0.0) h += 6.0;
  }
  hsv[0] = h;  // in [0, 6)
}

void hsvToRgb(const double hsv[3], double rgb[3]) {
  const double h = hsv[0], s = hsv[1], v = hsv[2];
  const int i = int(std::floor(h)) % 6;
  const double f = h - std::floor(h);
  const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  switch (i) {
    case 0:
      rgb[0] = v, rgb[1] = t, rgb[2] = p;
      break;
    case 1:
      rgb[0] = q, rgb[1] = v, rgb[2] = p;
      break;
    case 2:
      rgb[0] = p, rgb[1] = v, rgb[2] = t;
      break;
    case 3:
      rgb[0] = p, rgb[1] = q, rgb[2] = v;
      break;
    case 4:
      rgb[0] = t, rgb[1] = p, rgb[2] = v;
      break;
    default:
      rgb[0] = v, rgb[1] = p, rgb[2] = q;
      break;
  }
}

}  // namespace

bool parseDensityDisplay(const std::string& text, DensityDisplay& out) {
  if (text == "log")
    out = DensityDisplay::Log;
  else if (text == "linear")
    out = DensityDisplay::Linear;
  else if (text == "binary")
    out = DensityDisplay::Binary;
  else
    return false;
  return true;
}

double LogDensityScale::alpha(double hits) const {
  if (!(hits > 0.0)) return 0.0;
  switch (display) {
    case DensityDisplay::Linear:
      return hits * linearScale;  // Draves & Reckase 2003, figure 3b
    case DensityDisplay::Binary:
      return 1.0;  // figure 3a: membership only
    default:
      return k1 * std::log1p(hits * k2);
  }
}
double LogDensityScale::factor(double hits) const { return hits > 0.0 ? alpha(hits) / hits : 0.0; }

LogDensityScale logDensityScale(double brightness, double samples, double pixelsPerUnit, int supersample) {
  LogDensityScale s;
  s.k1 = brightness * kBrightnessScale;
  const double bucketsPerUnit = double(std::max(1, supersample)) * pixelsPerUnit;
  s.k2 = samples > 0.0 ? bucketsPerUnit * bucketsPerUnit / samples : 0.0;
  return s;
}

LogDensityScale densityScale(const FlameSettings& settings, double samples, double pixelsPerUnit, double maxHits) {
  LogDensityScale s = logDensityScale(settings.brightness, samples, pixelsPerUnit, settings.supersample);
  if (!parseDensityDisplay(settings.density_display, s.display)) s.display = DensityDisplay::Log;
  s.linearScale = maxHits > 0.0 ? settings.brightness / maxHits : 0.0;
  return s;
}

double gammaAlpha(double density, double inverseGamma, double threshold) {
  if (!(density > 0.0)) return 0.0;
  if (threshold > 0.0 && density < threshold) {
    // Blend from linear (slope threshold^(g-1)) at 0 to the power curve at the threshold.
    const double frac = density / threshold;
    const double linear = density * std::pow(threshold, inverseGamma) / threshold;
    return (1.0 - frac) * linear + frac * std::pow(density, inverseGamma);
  }
  return std::pow(density, inverseGamma);
}

ToneMapParams ToneMapParams::from(const FlameSettings& s, const Vec3& background, bool transparent) {
  ToneMapParams p;
  p.gamma = s.gamma;
  p.gamma_threshold = s.gamma_threshold;
  p.vibrancy = s.vibrancy;
  p.highlight_power = s.highlight_power;
  p.background = background;
  p.transparent = transparent;
  return p;
}

void toneMapPixel(const float in[4], const ToneMapParams& params, float out[4]) {
  const double density = in[3];
  const double g = 1.0 / params.gamma;
  const double vib = params.vibrancy;
  double alpha = 0.0, ls = 0.0;
  if (density > 0.0) {
    alpha = gammaAlpha(density, g, params.gamma_threshold);
    // Draves & Reckase 2003, §6 vibrancy: the alpha channel's gamma ratio applied to all three channels.
    ls = vib * kWhiteScale * alpha / density;
    alpha = std::clamp(alpha, 0.0, 1.0);
  }
  double rgb[3];
  // Highlights (flam3_calc_newrgb): if the brightest channel would exceed 1, either keep the
  // hue and desaturate toward white by (1/overshoot)^power, or (power < 0) clip per channel.
  double maxA = -1.0, maxC = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double a = ls * in[c];
    if (a > maxA) maxA = a, maxC = in[c];
  }
  const double hp = params.highlight_power;
  if (maxA > 1.0 && hp >= 0.0) {
    const double newLs = 1.0 / maxC;
    const double ratio = std::pow(newLs / ls, hp);
    for (int c = 0; c < 3; ++c) rgb[c] = newLs * in[c];
    double hsv[3];
    rgbToHsv(rgb, hsv);
    hsv[1] *= ratio;
    hsvToRgb(hsv, rgb);
  } else {
    const double newLs = maxC > 0.0 ? 1.0 / maxC : 0.0;
    double adjust = std::min(1.0, -hp);
    if (maxA <= 1.0) adjust = 1.0;
    for (int c = 0; c < 3; ++c) rgb[c] = ((1.0 - adjust) * newLs + adjust * ls) * in[c];
  }
  for (int c = 0; c < 3; ++c) {
    double a = rgb[c];
    // vibrancy 0: classic per-channel gamma (Draves & Reckase 2003, §6), which washes colors out.
    if (vib < 1.0 && in[c] > 0.0) a += (1.0 - vib) * kWhiteScale * std::pow(double(in[c]), g);
    // (flam3 also scales the background by 256/255; we keep it exact so empty pixels are the background.)
    if (!params.transparent) a += (1.0 - alpha) * params.background[c];
    out[c] = float(std::clamp(a, 0.0, 1.0));
  }
  out[3] = params.transparent ? float(alpha) : 1.f;
  if (params.transparent)  // premultiplied: color never exceeds alpha
    for (int c = 0; c < 3; ++c) out[c] = std::min(out[c], out[3]);
}

FlameImage developFlame(const FlameHistogram& histogram, const FlameSettings& settings, const Vec3& background,
                        bool transparent, double samples, double pixelsPerUnit, int threads) {
  const int ss = settings.supersample;
  if (ss < 1 || histogram.width % ss != 0 || histogram.height % ss != 0)
    throw std::invalid_argument("developFlame: the histogram is not a multiple of the supersampling");
  const int width = histogram.width / ss, height = histogram.height / ss;
  double maxHits = 0.0;
  if (settings.density_display == "linear")
    for (std::size_t i = 3; i < histogram.buckets.size(); i += 4)
      maxHits = std::max(maxHits, double(histogram.buckets[i]));
  const LogDensityScale scale = densityScale(settings, samples, pixelsPerUnit, maxHits);
  std::unique_ptr<DensityEstimator> estimator;
  if (settings.estimator_radius > 0.0)
    estimator = std::make_unique<DensityEstimator>(settings.estimator_radius, settings.estimator_minimum,
                                                   settings.estimator_curve, ss);
  // The log-scaled buffer moves into the filter, which frees it once its first pass has read it.
  AccumBuffer filtered = spatialFilterDown(logScaleAndEstimate(histogram, scale, estimator.get()), ss,
                                           settings.filter_radius, width, height, threads);
  FlameImage image;
  image.width = width;
  image.height = height;
  // Tone-mapped in place: the filtered buffer becomes the image, one full buffer fewer.
  image.rgba = std::move(filtered.data);
  const ToneMapParams params = ToneMapParams::from(settings, background, transparent);
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  constexpr std::size_t kPixelsPerChunk = 4096;
  parallelFor(pixels, std::clamp(threads, 1, 64), kPixelsPerChunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      float in[4];
      std::memcpy(in, &image.rgba[i * 4], sizeof in);
      toneMapPixel(in, params, &image.rgba[i * 4]);
    }
  });
  return image;
}

}  // namespace gridifs
