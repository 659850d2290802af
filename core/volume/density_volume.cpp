#include "volume/density_volume.h"

#include <algorithm>

namespace gridifs {

void normalizeDensity(DensityVolume& volume) {
  float largest = 0.0f;
  double total = 0.0;
  for (float v : volume.density) {
    largest = std::max(largest, v);
    total += v;
  }
  volume.totalMass = total;
  if (!volume.color.empty())
    for (std::size_t v = 0; v < volume.density.size(); ++v) {
      const float n = volume.density[v];
      for (int c = 0; c < 3; ++c)
        volume.color[3 * v + std::size_t(c)] = n > 0.0f ? volume.color[3 * v + std::size_t(c)] / n : 0.0f;
    }
  if (largest > 0.0f)
    for (float& v : volume.density) v /= largest;
}

}  // namespace gridifs
