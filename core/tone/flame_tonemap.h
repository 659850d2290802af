#pragma once
// Tone mapping of the flame display (Draves & Reckase 2003, §4 log-density display, §6 gamma and vibrancy),
// following flam3's normalisation so that exposure depends neither on the sample count nor on
// the supersampling, only on the attractor's density per unit of image-plane area.
//
// Units: "accumulated" values are flam3's accumulation buffer divided by its PREFILTER_WHITE
// (255), so a log-scaled alpha of 1 is flam3's 255. Output colors are floats in [0, 1].
// All functions are pure (thread-safe); none throws.
#include <string>
#include <vector>

#include "base/types.h"
#include "model/flame_settings.h"
#include "tone/flame_histogram.h"

namespace gridifs {

/// How hit counts become the alpha channel (FlameSettings::density_display).
enum class DensityDisplay { Log, Linear, Binary };
/// Parses "log" / "linear" / "binary"; false for anything else.
bool parseDensityDisplay(const std::string& text, DensityDisplay& out);

/// Draves & Reckase 2003, §4: every bucket is scaled by log(α)/α. flam3 writes this as
/// ls = k1·log(1 + α·k2)/α with k1 = brightness·268/256 and k2 the inverse of the number of
/// hits a bucket gets when `samples` points spread evenly over one unit² of the image plane:
/// k2 = (supersample·pixelsPerUnit)² / samples. Doubling the samples doubles α and halves k2,
/// so the picture's exposure does not change.
struct LogDensityScale {
  double k1 = 1.0, k2 = 1.0;
  /// Draves & Reckase 2003, figure 3: log density (c, the flame display), linear (b) or binary (a).
  DensityDisplay display = DensityDisplay::Log;
  /// Linear display: alpha = hits·linearScale (brightness over the densest bucket's hits).
  double linearScale = 0.0;
  /// The scaled alpha of a bucket with `hits` hits: k1·log(1 + hits·k2) (log), hits·linearScale
  /// (linear), 1 for any hit (binary).
  double alpha(double hits) const;
  /// ls = alpha(hits)/hits, the factor applied to all four channels (0 for no hits).
  double factor(double hits) const;
};

/// k1, k2 as above. `samples` counts every iteration that was plotted or fell outside the
/// frame (flam3's nsamples); `pixelsPerUnit` is output pixels per unit of the image plane.
LogDensityScale logDensityScale(double brightness, double samples, double pixelsPerUnit, int supersample);
/// The scale of `settings.density_display`: logDensityScale for "log"; for "linear",
/// linearScale = brightness / `maxHits` (the densest bucket's hits), so brightness 1 maps the
/// densest bucket to white; "binary" needs nothing else.
LogDensityScale densityScale(const FlameSettings& settings, double samples, double pixelsPerUnit, double maxHits);

/// flam3_calc_alpha: density^(1/gamma), made linear below `threshold` so that the infinite
/// slope of the power at 0 does not amplify sparse noise (Draves & Reckase 2003, §6).
double gammaAlpha(double density, double inverseGamma, double threshold);

/// What the final mapping needs (a view of FlameSettings plus background and transparency).
struct ToneMapParams {
  double gamma = 4.0, gamma_threshold = 0.01, vibrancy = 1.0, highlight_power = 1.0;
  Vec3 background{0.0};
  bool transparent = false;  // true: no background, rgb premultiplied by alpha (for EXR/PNG alpha)
  static ToneMapParams from(const FlameSettings& s, const Vec3& background, bool transparent);
};

/// Maps one filtered, log-scaled pixel (r, g, b, a in accumulated units) to output RGBA:
/// alpha = gammaAlpha(a); colors get alpha/a (vibrancy 1, "gamma through alpha") blended with
/// per-channel gamma (vibrancy 0); highlights that exceed 1 are desaturated toward white by
/// highlight_power (>= 0) or clipped per channel (< 0); then composited over the background
/// (opaque) or left premultiplied (transparent).
void toneMapPixel(const float in[4], const ToneMapParams& params, float out[4]);

/// An output image: float RGBA, row-major, top row first.
struct FlameImage {
  int width = 0, height = 0;
  std::vector<float> rgba;
  const float* pixel(int x, int y) const { return &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4]; }
};

/// Develops a histogram into an image (Draves & Reckase 2003, §4–8): log-density scaling with the
/// density-estimation filter at bucket resolution, the Gaussian spatial filter down by
/// `settings.supersample`, then toneMapPixel. The histogram must be
/// (width·ss) × (height·ss) buckets; the output is width × height. `threads` ≥ 1 splits the
/// filter and mapping stages by rows. Throws std::invalid_argument on inconsistent sizes or
/// settings the filters cannot build.
FlameImage developFlame(const FlameHistogram& histogram, const FlameSettings& settings, const Vec3& background,
                        bool transparent, double samples, double pixelsPerUnit, int threads = 1);

}  // namespace gridifs
