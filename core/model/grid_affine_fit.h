#pragma once
// The least-squares affine map of a grid's nodes in the plane: what a flame xform's pre-affine
// coefficients are for a grid (the dependent variations read them; export-flame writes them).
// Pure function: thread-safe.
#include "model/grid.h"
#include "variations/flame_variations.h"

namespace gridifs {

/// The least-squares affine map (x, y) → (x', y') through every node of `evaluated`, in X
/// coordinates (x' = a·x + b·y + c, y' = d·x + e·y + f). `maxError` receives the largest
/// distance between a node and the fit (including the node's z), 0 up to rounding for an affine
/// grid that keeps z at 0.
FlameAffine fitAffine(const Grid& evaluated, double& maxError);

}  // namespace gridifs
