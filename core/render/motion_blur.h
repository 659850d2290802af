#pragma once
// Motion blur (Draves & Reckase 2003, §9): one frame is the sum of several time samples of the
// chaos game, spread over the shutter, accumulated into one histogram. The directional form
// draws the samples of earlier times dimmer: "the color of points accumulated during earlier
// time steps are scaled in intensity, with the scaling constant approaching 1.0 as the time steps
// progress", so a moving shape trails off behind itself.
//
// Pure functions on values the caller owns: thread-safe; nothing throws except on mismatched sizes
// (std::invalid_argument).
#include <vector>

#include "render/chaos_renderer.h"

namespace gridifs {

/// The most time samples one frame takes (the range of animation.motion_blur and --motion-blur).
constexpr int kMaxMotionBlurSamples = 256;

/// The colour weights of `n` time samples, earliest first: w_i ∝ ((i + 1)/n)^fade (flam3's
/// exponential temporal filter), scaled so that they average 1: a shape that does not move looks
/// the same at any fade, and fade 0 is the uniform blur. n ≥ 1, fade ≥ 0.
std::vector<double> motionBlurWeights(int n, double fade);

/// One motion-blurred frame being summed: the image so far and its display colours' weighted sums.
struct TimeSampleSum {
  RenderImage image;
  /// 4 per pixel: Σ w·rgba of the display image; made when the second sample comes, so that a
  /// frame of one time sample (every render without motion blur) costs no copy of its buffers.
  std::vector<double> rgbaSum;
  double firstWeight = 1.0;
  int count = 0;
};

/// Adds time sample `sample` with colour weight `weight`: hit counts add (saturating), the flame
/// colour sums (Σr, Σg, Σb) add scaled by the weight and Σc unscaled, the nearest depth is kept,
/// the display colour is summed with the weight, the statistics add up.
void addTimeSample(TimeSampleSum& sum, RenderImage&& sample, double weight);
void addTimeSample(TimeSampleSum& sum, const RenderImage& sample, double weight);

/// The summed frame: the display colour is the weighted mean of the samples' (alpha 255 where any
/// sample plotted), the hit-pixel count recounted. With one sample the image is that sample's.
RenderImage finishTimeSamples(TimeSampleSum&& sum);

}  // namespace gridifs
