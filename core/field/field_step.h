#pragma once
// One time step of a fractal field over many nodes (Colonna, "Animation of fractal objects",
// §2, §3.2 and the second appendix): the values FractalField::displacement gives node by node,
// up to single-precision rounding, at a fraction of the cost.
//
// Why it is faster:
// - Time is the same for every node of a step, so each level's 4D mesh collapses to a 3D one
//   once: a vertex's values at the four time steps around t give, by linearity of the
//   pseudo-cubic, one value g for the spatial reduction and one value e for the time slopes
//   (trilinear, as the appendix carries slopes linearly through the later dimensions).
// - Coarse meshes, whose vertices many nodes share, are collapsed once for the box of vertices
//   the nodes reach and read from there; fine meshes, whose vertices no two nodes share, are
//   hashed per node: the interpolation is linear in the random values, so each node's value is
//   one weighted sum of them, its weights shared by the three axes and the hashes done in the
//   same vector loop over a block of nodes.
// - Nodes that form an axis-aligned tensor grid (an undistorted grid, a heightfield) are
//   interpolated one dimension at a time over the whole grid.
// - The tensor passes and the per-node sums run in single precision, sixteen lanes per AVX-512
//   instruction: a level's values carry a relative rounding error of about 1e-7 (the
//   point-by-point evaluation is in double), a displacement error far below a pixel.
// Each node's value depends only on its position, t and the field: not on the thread count, and
// not on the processor (the same operations in the same order in every build of the kernels).
//
// Thread-safety: reads the field; writes only `nodes`.
#include <vector>

#include "base/types.h"

namespace gridifs {

class FractalField;

/// nodes[n] += field.displacement(nodes[n], t) for every n with mask[n] set, up to single-precision
/// rounding.
/// Uses up to `threads` workers (≤ 0: all).
void fieldStepDisplace(const FractalField& field, std::vector<Vec3>& nodes, const std::vector<unsigned char>& mask,
                       double t, int threads);

}  // namespace gridifs
