#pragma once
// The measure attractor as a density volume (Sokolov & Gentil, §3.4: P / max P), with an optional
// colour volume holding the mean structural colour of the visits per voxel.
#include <vector>

#include "volume/voxel_set.h"

namespace gridifs {

struct DensityVolume {
  VoxelLattice lattice;
  std::vector<float> density;  // N³ values in [0, 1], max 1 (all 0 when nothing was visited)
  std::vector<float> color;    // empty, or 3 per voxel: mean r g b of the visits
  double totalMass = 0.0;      // Σ P before normalisation (visits)

  float at(int i, int j, int k) const { return density[lattice.index(i, j, k)]; }
};

/// Divides by the largest value (Sokolov & Gentil, §3.4: a grey level from the visit counts) and
/// turns colour sums into means. `counts` becomes the density.
void normalizeDensity(DensityVolume& volume);

}  // namespace gridifs
