#pragma once
// A fractal field over a density volume (Colonna, "Animation of fractal objects", §3.2: clouds
// whose density is a fractal field, drifting with the wind): the density at voxel centre p is
// weighted by max(0, 1 + strength · F_seed(p + wind·t, t)) and the volume divided by its new
// largest value, so it stays in [0, 1] with max 1. Unvisited voxels stay empty: the field shapes
// the measure attractor's cloud, it does not add density outside it.
#include "model/volume_settings.h"
#include "volume/density_volume.h"

namespace gridifs {

/// The weight the field gives the voxel centre p at time t (≥ 0).
double densityFieldWeight(const VolumeDensityField& field, const Vec3& p, double t);

/// Weights every visited voxel of `volume` (normalised, max 1) by the field at time t and
/// normalises again. Uses up to `threads` workers (≤ 0: all); no value depends on the count.
void modulateDensity(DensityVolume& volume, const VolumeDensityField& field, double t, int threads);

}  // namespace gridifs
