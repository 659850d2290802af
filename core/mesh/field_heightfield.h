#pragma once
// Colonna's mountains ("Animation of fractal objects", §1 and fig. 5, the earthquake): a fractal
// field op applied to a flat sheet, written as a heightfield mesh.
#include "field/fractal_field.h"
#include "mesh/ifs_mesh.h"

namespace gridifs {

inline constexpr int kMinHeightfieldSize = 2;
inline constexpr int kMaxHeightfieldSize = 4096;

/// A size×size grid of vertices over the square [-1, 1]² of the z = 0 plane (the grid domain X
/// seen from above), each moved by the field's displacement at time t exactly as the field op moves
/// a node there, joined by quads. Vertex colors run from dark (lowest) to light (highest).
/// Expects size in [kMinHeightfieldSize, kMaxHeightfieldSize].
IfsMesh fieldHeightfield(const FractalField& field, double t, int size);

}  // namespace gridifs
