#pragma once
// Symmetry helpers (Draves & Reckase 2003, §7): n-way rotational or dihedral symmetry about the view axis,
// added as extra functions. Each added function gets weight equal to the sum of the weights of
// the (unmuted) original functions, so that every branch has the same density, and color speed 0
// so that it does not change the color coordinate (the colors stay symmetric and do not wash
// out). A GridIFS function is a grid, so a symmetry function is an affine grid: 2×2×2 nodes,
// moved by one `nodes` op onto M·u + t (trilinear interpolation reproduces an affine map exactly
// inside X; points outside X are clamped first, as for every function).
// Pure functions; thread-safe.
#include <glm/mat3x3.hpp>
#include <vector>

#include "model/project.h"

namespace gridifs {

/// The symmetry axis of a view: the line through `camera.target` along the viewing direction,
/// and the image's horizontal direction (for the dihedral mirror). Uses OrbitCamera's conventions.
struct SymmetryFrame {
  Vec3 center{0.0};
  Vec3 axis{0.0, 0.0, 1.0};    // unit
  Vec3 mirror{1.0, 0.0, 0.0};  // unit, ⟂ axis: the dihedral mirror flips this direction
};
SymmetryFrame symmetryFrameForView(const Camera& camera);

/// An affine function p ↦ m·p + t as a 2×2×2 grid with one nodes op (color speed 0).
Function affineFunction(const std::string& name, const glm::dmat3& m, const Vec3& t, double weight);

/// The functions that give `symmetry`: n ≥ 2 → n−1 rotations by 360°·k/n about the axis;
/// n ≤ −1 → a mirror (x̂ flipped) plus |n|−1 rotations (flam3's convention: −1 bilateral,
/// −6 snowflake); 0 and 1 → none. Weights = the sum of the unmuted functions' weights in `project`.
/// Throws ModelError when |symmetry| > 32 or the frame is degenerate.
std::vector<Function> symmetryFunctions(const Project& project, int symmetry, const SymmetryFrame& frame);

/// Appends symmetryFunctions(...) to the project. Throws ModelError when the project would exceed
/// the function limit.
void addSymmetry(Project& project, int symmetry, const SymmetryFrame& frame);

}  // namespace gridifs
