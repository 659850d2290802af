#pragma once
// The flame display's accumulation buffer (Draves & Reckase 2003, §5): per bucket the sums of the palette
// colors of every sample that landed there, and the hit count ("alpha" before log scaling).
// Buckets sit at supersample× the output resolution (Draves & Reckase 2003, §8).
// Not synchronised: give each worker its own histogram and merge() them.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "tone/palette.h"

namespace gridifs {

struct FlameHistogram {
  int width = 0, height = 0;   // in buckets
  std::vector<float> buckets;  // 4 floats per bucket: r, g, b sums and hit count

  FlameHistogram() = default;
  FlameHistogram(int w, int h) : width(w), height(h), buckets(std::size_t(w) * std::size_t(h) * 4, 0.f) {}

  /// One sample with palette color `c` at bucket (x, y); the caller has bounds-checked.
  void add(int x, int y, const Rgb& c) {
    float* b = &buckets[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
    b[0] += c.r;
    b[1] += c.g;
    b[2] += c.b;
    b[3] += 1.f;
  }
  const float* bucket(int x, int y) const {
    return &buckets[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
  }
  void clear() { std::fill(buckets.begin(), buckets.end(), 0.f); }
  /// Adds another histogram of the same size (merging per-worker buffers).
  void merge(const FlameHistogram& other) {
    const std::size_t n = std::min(buckets.size(), other.buckets.size());
    for (std::size_t i = 0; i < n; ++i) buckets[i] += other.buckets[i];
  }
  double totalHits() const {
    double t = 0.0;
    for (std::size_t i = 3; i < buckets.size(); i += 4) t += buckets[i];
    return t;
  }
};

}  // namespace gridifs
