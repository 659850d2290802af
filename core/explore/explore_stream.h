#pragma once
// The one seeded stream every draw of exploring takes its numbers from (splitmix64, as the chaos
// game's streams), so the same seed and options give the same project, byte for byte, on every
// machine: no std:: distributions, whose results the standard leaves to each library.
//
// Thread-safety: a plain value; one stream per thread.
#include <cmath>
#include <cstdint>

#include "base/hash.h"

namespace gridifs {

class ExploreStream {
 public:
  explicit ExploreStream(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    state_ += 0x9E3779B97F4A7C15ull;
    return splitmix64(state_);
  }
  /// Uniform in [0, 1).
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform in [0, n).
  std::size_t index(std::size_t n) { return n == 0 ? 0 : std::size_t(uniform() * double(n)) % n; }
  bool chance(double p) { return uniform() < p; }
  /// A standard normal number (Box–Muller).
  double normal() {
    const double u = 1.0 - uniform(), v = uniform();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * v);
  }

 private:
  std::uint64_t state_;
};

}  // namespace gridifs
