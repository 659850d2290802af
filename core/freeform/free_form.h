#pragma once
// Free-form IFS (Thollot, Zair, Tosan & Vandorpe 1997, §3.1): the iterative space is the simplex
// of m barycentric coordinates, the functions are m×m matrices whose rows sum to 1 (Markov
// matrices when no entry is negative), λ ← λ·T, and the attractor is plotted through the
// project's control points, P·λ = Σ_j λ_j p_j. With non-negative matrices the attractor lies in
// the convex hull of the control points; negative entries are allowed but lose that property.
//
// Thread-safety: pure functions of their arguments.
#include <string>
#include <vector>

#include "model/project.h"

namespace gridifs {

using BarycentricMatrix = std::vector<std::vector<double>>;

/// How far a matrix row's sum may be from 1.
inline constexpr double kRowSumTolerance = 1e-9;

/// Checks the free-form rules: m = 2..64 control points, every loop function a Matrix function
/// with an m×m finite matrix whose rows sum to 1 (within kRowSumTolerance) when the project has
/// a space, no Matrix function without one, a grid final function, and the final function's
/// `bezier` lattice at most 8 nodes per axis. Throws ModelError with a JSON path.
void checkFreeForm(const Project& project);

/// Non-fatal remarks for `info`: matrices with negative entries (the attractor may leave the
/// convex hull of the control points).
std::vector<std::string> freeFormWarnings(const Project& project);

/// Dobrushin's ergodicity coefficient, max over row pairs of ½·Σ_j |T_ij − T_kj|: the factor by
/// which λ·T contracts differences of barycentric coordinates (ℓ1 norm). Below 1, the matrix is
/// a contraction of the simplex; the plotted map then contracts too (P is linear).
double simplexContraction(const BarycentricMatrix& matrix);

/// λ·T (row vector times matrix), in double.
std::vector<double> applyMatrix(const std::vector<double>& lambda, const BarycentricMatrix& matrix);

/// Σ_j λ_j p_j.
Vec3 projectBarycentric(const std::vector<Vec3>& controlPoints, const std::vector<double>& lambda);

/// The m×m identity, and the Kronecker (tensor) product A ⊗ B of Markov matrices: row (i, k),
/// column (j, l) = A_ij · B_kl, indices i·size(B) + k (Thollot et al. 1997, §5.4.2).
BarycentricMatrix identityMatrix(std::size_t m);
BarycentricMatrix kroneckerProduct(const BarycentricMatrix& a, const BarycentricMatrix& b);

/// Whether `project` is a free-form one (has control points).
inline bool isFreeForm(const Project& project) { return project.space.has_value(); }

}  // namespace gridifs
