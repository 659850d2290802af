#include "tone/density_histogram.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace gridifs {

std::int64_t DensityHistogram::total() const {
  std::int64_t n = empty;
  for (std::int64_t b : bins) n += b;
  return n;
}

DensityHistogram densityHistogram(const std::uint32_t* hits, std::size_t count) {
  DensityHistogram h;
  h.bins.assign(32, 0);
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t n = hits[i];
    if (n == 0) {
      ++h.empty;
      continue;
    }
    ++h.bins[std::size_t(std::bit_width(n) - 1)];  // floor(log2 n)
    h.maxHits = std::max(h.maxHits, n);
  }
  h.bins.resize(h.maxHits ? std::size_t(std::bit_width(h.maxHits)) : 0);
  return h;
}

double hitsForAlpha(const LogDensityScale& scale, double alpha) {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  if (!(alpha > 0.0)) return 0.0;
  switch (scale.display) {
    case DensityDisplay::Binary:
      return 1.0;
    case DensityDisplay::Linear:
      return scale.linearScale > 0.0 ? alpha / scale.linearScale : kNever;
    default:
      // alpha = k1·log(1 + hits·k2)  ⇒  hits = (e^(alpha/k1) − 1)/k2.
      if (!(scale.k1 > 0.0) || !(scale.k2 > 0.0)) return kNever;
      return std::expm1(alpha / scale.k1) / scale.k2;
  }
}

double toneCurve(const LogDensityScale& scale, double gamma, double gammaThreshold, double hits) {
  return std::min(1.0, gammaAlpha(scale.alpha(hits), 1.0 / gamma, gammaThreshold));
}

}  // namespace gridifs
