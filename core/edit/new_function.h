#pragma once
// What a new function of the IFS starts as: its name, colour, palette index and shape. The
// modeller's Add buttons and a test build the same function from the same project, so the
// defaults live here and not in a panel.
//
// Thread-safety: pure functions of their arguments; never throw.
#include <string>

#include "model/project.h"

namespace gridifs {

/// `base` followed by the smallest number n ≥ 1 that no function of `project` is named after
/// ("f1", "f2", ...).
std::string uniqueFunctionName(const Project& project, const std::string& base);

/// The colour of the function added at `index`: eight hues spread around the circle, repeating.
Vec3 newFunctionColor(std::size_t index);

/// The function "Add" appends: an undistorted 6×6×6 grid placed at half size, named f<n>, with the
/// next colour and palette index. In a free-form IFS it is a matrix function instead, "halfway to
/// the centroid of the control points" (Thollot et al. 1997, §3.1), a contraction to edit further.
Function newGridFunction(const Project& project);

/// A new condensation or median function (Sokolov & Gentil, §3.1–3.2): a ball of radius 0.3 at
/// the origin, well inside X and visible at once; the box and torus sizes start at the ball's, so
/// switching the shape keeps the set in place. Named cond<n> or median<n>.
Function newSetFunction(const Project& project, FunctionKind kind);

}  // namespace gridifs
