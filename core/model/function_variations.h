#pragma once
// A function's flame variations (Draves & Reckase 2003, §3, §3.1): f(p) = post(Σ w_i V_i(g(p))), g
// the function's grid map (its stack and placement). Without variations and post, f = g.
//
// The grid map of a function with variations extrapolates: beyond X it continues each border
// cell's trilinear map instead of clamping the point to X, so that an affine grid (2×2×2 nodes
// that are an affine image of X's corners) is exactly that affine map on the whole space, as a
// flame's pre-affine transform is on the whole plane. The dependent variations (waves, popcorn,
// rings, fan) read the affine coefficients of g: the least-squares affine fit of its nodes in x
// and y (for an affine grid, g itself).
#include <array>
#include <map>
#include <optional>
#include <string>

#include "base/types.h"
#include "model/placement.h"

namespace gridifs {

/// The affine map applied after the variations' sum: T + R·(S·q) with the placement's
/// conventions, or a general 3×4 matrix (rows x, y, z of [m0 m1 m2 t]) when one is given
/// (a flame's post transform may shear).
struct PostTransform {
  Placement placement;
  std::optional<std::array<std::array<double, 4>, 3>> matrix;
  /// The map as a 3×4 matrix.
  std::array<std::array<double, 4>, 3> affine() const;
  bool operator==(const PostTransform&) const = default;
};

/// The affine coefficients of a flame map in flam3's naming: x' = a·x + b·y + c, y' = d·x + e·y + f.
struct VariationCoefficients {
  double a = 1.0, b = 0.0, c = 0.0, d = 0.0, e = 1.0, f = 0.0;
};

/// Throws ModelError (with a path relative to the function) for an unknown variation or parameter, a
/// non-finite weight or parameter, or a parameter of a variation the function does not use.
void validateFunctionVariations(const std::map<std::string, double>& variations,
                                const std::map<std::string, double>& params);

}  // namespace gridifs
