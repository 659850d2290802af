#pragma once
// Self-shadowing of a density volume lit by one directional light: for every voxel, the optical
// depth ∫ density ds along the ray towards the light (the unscaled exponent of Beer–Lambert
// transmittance, T = exp(-σ · depth)). Precomputed once per volume and light direction, so the
// preview's ray march reads a voxel's shadow with one texture fetch instead of a second march,
// and a change of the density scale σ needs no recomputation. Pure: thread-safe.
#include <vector>

#include "base/types.h"

namespace gridifs {

/// Optical depth towards the light of each voxel centre of an n³ volume covering X = [-1, 1]³
/// (`density` indexed x + n·(y + n·z), interpolated between voxel centres), in world units: a
/// uniform density 1 over a path of length L gives L. One sweep of slices along the light's
/// dominant axis (bilinear between slices, trapezoid rule along the ray): exact for lights along
/// an axis, O(n³). `towardLight` need not be unit
/// length (zero: no shadowing, all 0). Voxels far from any density (more than one voxel) are
/// left 0: a ray march never weighs them. `threads` ≤ 0: every hardware thread.
std::vector<float> lightOpticalDepth(const std::vector<float>& density, int n, const Vec3& towardLight, int threads);

}  // namespace gridifs
