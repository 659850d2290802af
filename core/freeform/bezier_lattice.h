#pragma once
// Sederberg & Parry's free-form deformation (1986) of the final function's lattice: the distorted
// nodes are the control points of a tensor-product Bézier volume over X,
// F(p) = Σ_ijk B_i(u) B_j(v) B_k(w) node(i, j, k), (u, v, w) = (p + 1)/2, with Bernstein
// polynomials of degree N − 1 per axis (at most kMaxBezierLatticeNodes nodes). The deformation is
// smooth everywhere, not only inside cells, and an undistorted lattice is the identity (the
// Bernstein basis reproduces linear functions). This is the polynomial deformation of an attractor
// that Thollot, Zair, Tosan & Vandorpe (1997, §5.5) build from control points.
//
// Thread-safety: pure functions of their arguments.
#include <memory>

#include "model/grid.h"

namespace gridifs {

/// F(p) for a lattice of at most kMaxBezierLatticeNodes nodes per axis; p is clamped to X first
/// (NaN → −1), as Grid::evaluate does. Throws ModelError for a larger lattice.
Vec3 evaluateBezierLattice(const Grid& lattice, Vec3 p);

/// Nodes per axis of the grid the renderers sample F on (their kernels interpolate trilinearly).
inline constexpr int kBezierSamplingNodes = 33;

/// F sampled on a grid of `nodes`³ nodes at the undistorted positions: the trilinear map of the
/// result follows F to within the sampling error (exact for an undistorted lattice).
std::shared_ptr<const Grid> sampleBezierLattice(const Grid& lattice, int nodes = kBezierSamplingNodes);

}  // namespace gridifs
