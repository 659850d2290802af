#pragma once
// The filters of the flame display (Draves & Reckase 2003, §8):
//  - the density-estimation filter: each bucket's log-scaled color is spread with a Gaussian
//    kernel whose radius shrinks as the bucket's density grows (flam3's estimator radius,
//    minimum and curve: radius ≈ (R·ss + 1)/hits^curve, never below minimum·ss + 1), so sparse
//    regions are smoothed while dense ones stay sharp;
//  - the spatial filter: a Gaussian over the supersampled buckets that brings the histogram
//    down to the output size (flam3's spatial filter, support 1.5, width 2·1.5·ss·radius).
// Kernels are immutable after construction (thread-safe to share). Constructors throw
// std::invalid_argument for settings that cannot make a kernel.
#include <vector>

#include "tone/flame_histogram.h"
#include "tone/flame_tonemap.h"

namespace gridifs {

/// Log-scaled, filtered accumulation: 4 floats per pixel (r, g, b, alpha) in accumulated units.
struct AccumBuffer {
  int width = 0, height = 0;
  std::vector<float> data;
  AccumBuffer() = default;
  AccumBuffer(int w, int h) : width(w), height(h), data(std::size_t(w) * std::size_t(h) * 4, 0.f) {}
  float* at(int x, int y) { return &data[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4]; }
  const float* at(int x, int y) const { return &data[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4]; }
};

/// The family of density-estimation kernels (flam3_create_de_filters).
class DensityEstimator {
 public:
  struct Tap {
    int dx, dy;
    float weight;
  };
  /// radius, minimum in output pixels (radius > 0, minimum ≤ radius), curve > 0, supersample ≥ 1.
  DensityEstimator(double radius, double minimum, double curve, int supersample);

  int supersample() const { return supersample_; }
  int kernelCount() const { return int(widths_.size()); }
  /// Kernel for a bucket whose (supersample-corrected) neighbourhood holds `hits` hits.
  int kernelIndex(double hits) const;
  /// Radius h of kernel `index` in buckets (taps satisfy |d| ≤ h).
  double kernelWidth(int index) const { return widths_[std::size_t(index)]; }
  /// Non-zero taps of kernel `index` (|dx|, |dy| <= ceil(width) - 1, as flam3 applies them);
  /// their weights sum to at most 1 (exactly 1 for the wide kernels, ~0.96 for width 1).
  const std::vector<Tap>& taps(int index) const { return taps_[std::size_t(index)]; }
  /// Hits counted for the bucket at (x, y): the (2⌊ss/2⌋+1)² neighbourhood, scaled by
  /// (ss/(ss+1))² for even ss so that the count does not depend on the supersampling.
  double neighbourhoodHits(const FlameHistogram& histogram, int x, int y) const;

 private:
  int supersample_;
  double curve_;
  int maxFilterIndex_ = 0;
  double maxFilteredCounts_ = 0;
  std::vector<double> widths_;
  std::vector<std::vector<Tap>> taps_;
};

/// Draves & Reckase 2003, §4 + §8: log-scales every bucket (LogDensityScale::factor) and, when `estimator`
/// is given, spreads it with the density-estimation kernels. Output has the histogram's size.
AccumBuffer logScaleAndEstimate(const FlameHistogram& histogram, const LogDensityScale& scale,
                                const DensityEstimator* estimator);

/// The spatial filter's 1D taps (the 2D kernel is their outer product, as flam3's Gaussian):
/// an odd/even width matching the supersampling's parity, normalised to sum 1.
std::vector<double> spatialFilterTaps(int supersample, double radius);

/// Filters `accum` (outWidth·ss × outHeight·ss) down to outWidth × outHeight with the separable
/// spatial filter centred on each output pixel's ss×ss block; taps outside the buffer count
/// as empty. `threads` ≥ 1 splits rows. `accum` is freed once the first (horizontal) pass has
/// read it, so a caller that moves it in holds one full-size buffer fewer while the output fills.
AccumBuffer spatialFilterDown(AccumBuffer accum, int supersample, double radius, int outWidth, int outHeight,
                              int threads = 1);

}  // namespace gridifs
