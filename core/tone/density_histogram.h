#pragma once
// The distribution of densities in a flame histogram (Draves & Reckase 2003, §4, figure 4): how
// many pixels have each density, in power-of-two bins, which a log–log plot shows as a plateau
// and then a nearly straight line (a power law). With the tone curve drawn over it the artist
// sees which densities the gamma threshold keeps linear and where the brightest pixels saturate.
//
// Pure functions: thread-safe; nothing throws.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "tone/flame_tonemap.h"

namespace gridifs {

/// Pixels by density: bins[k] counts the pixels whose hit count is in [2^k, 2^(k+1)) (figure 4's
/// "number of pixels with that density, or up to the next power of two"); `empty` counts those
/// with no hit. The last bin holds the densest pixel.
struct DensityHistogram {
  std::vector<std::int64_t> bins;
  std::int64_t empty = 0;
  std::uint32_t maxHits = 0;
  std::int64_t total() const;  // every pixel, empty ones included
};

/// The histogram of `count` hit counts.
DensityHistogram densityHistogram(const std::uint32_t* hits, std::size_t count);
inline DensityHistogram densityHistogram(const std::vector<std::uint32_t>& hits) {
  return densityHistogram(hits.data(), hits.size());
}

/// The hit count at which `scale` gives `alpha` (the inverse of LogDensityScale::alpha for the
/// log and linear displays): where the gamma threshold and saturation (alpha 1) fall on the
/// density axis. Infinity when no hit count reaches it; 1 for the binary display.
double hitsForAlpha(const LogDensityScale& scale, double alpha);

/// The tone curve: the brightness of a pixel with `hits` hits before filtering,
/// min(1, gammaAlpha(scale.alpha(hits), 1/gamma, threshold)).
double toneCurve(const LogDensityScale& scale, double gamma, double gammaThreshold, double hits);

}  // namespace gridifs
