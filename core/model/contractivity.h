#pragma once
// An upper bound of the Lipschitz constant of a grid's trilinear map (Gröller & Wegenkittl 1994, §1.1:
// an IFS function must be contractive, s_i < 1).
#include "model/grid.h"

namespace gridifs {

struct ContractivityEstimate {
  double bound = 0.0;         // max over cells of the cell's Lipschitz bound
  Index3 worstCell{0, 0, 0};  // the cell attaining it
};

/// Inside one cell the Jacobian's column along x is a bilinear blend of the cell's
/// four x-edges divided by the cell width (likewise y, z), so it lies in the convex
/// hull of those edge vectors. The spectral norm is convex, so its maximum over the
/// cell is attained at one of the 4×4×4 edge combinations; the maximum over cells
/// bounds the map on X (X is convex, clamping is 1-Lipschitz). Exact for affine grids.
ContractivityEstimate estimateContractivity(const Grid& grid);

/// Largest singular value of the 3×3 matrix with columns a, b, c.
double spectralNorm(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace gridifs
