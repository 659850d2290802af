#pragma once
// Combining two projects into one (Thollot, Zair, Tosan & Vandorpe 1997, §4: operations on IFS
// matrices). Both inputs must pass validateProject; the result does too.
//
//  union    both function lists, the transition matrix block diagonal (a chain stays in the
//           project it started in): the attractor is the union of the two attractors (§4.2,
//           block matrix). Grid projects, or free-form ones (the spaces' control points are
//           concatenated; a matrix maps the other project's coordinates to its own centroid,
//           which a chain never needs after its first step).
//  concat   as union, and a function of A may also be followed by one of B: the chaos game then
//           applies B's maps to A's points (the paper's concatenation, an empty block replaced by
//           the identity). Grid projects only. The graph is not strongly connected (`info`
//           says so): the chaos game restarts its chains regularly (CompiledIfs::restartInterval)
//           and the deterministic algorithm builds every allowed word.
//  product  free-form projects: the tensor (Kronecker) products T_a ⊗ T_b of every pair, on the
//           m_A·m_B control points p_i + q_k: the attractor is the sum A + B of the two
//           (§5.4; two Bézier curves give a translational patch). Transitions multiply.
//  shuffle  free-form projects: T_a ⊗ I and I ⊗ T_b (the tensor sum, the shuffle of the two
//           languages, §4.2) on the same space: the same sum A + B, reached by interleaving
//           the two IFSs instead of stepping both at once.
//
//
// With states (freeform/state_expansion.h), and for the operations below, the result is the IFS
// matrix the paper's operation gives (freeform/ifs_matrix_ops.h) on the two projects' matrices
// (ifsMatrixOf: a project without states is one state, or one state per function with transitions):
//  union        (with states) the block matrix: the union of the two attractors.
//  concat       (with states, or free-form projects with the same control points) as above, A's
//               chains continue into B's maps: the words L_B·L_A (B's maps outermost), the block
//               matrix with the identity from B's final states to A's initial ones, H̃_B ◇ H̃_A.
//               Grid projects without states keep the concat above, which is the same attractor.
//  product      grid projects: the tensor product H̃ ⊗ H̃′, entries H̃_ij ∪ H̃′_kl (§4.1).
//  shuffle      grid projects: the tensor sum (§4.2); free-form projects with states: the tensor sum
//               with the functions lifted to the product space as above.
//  intersection, matrix-union  entrywise on matrices with the same states; functions of the two
//               projects with the same name are the same function (A's is kept).
//  composition  (H̃H̃′)_ij = ⋃_k H̃_ik H̃′_kj, stored through intermediate states.
// A result without attractor (an empty intersection, no path from Q_I to Q_F) is refused.
// Free-form projects need the same control points for every operation but union, product and
// shuffle.
//
// Weights are normalised per project so that each contributes in proportion to its own weights
// (union/concat/shuffle: each project's total becomes 1; product: w_a·w_b). Camera and render
// settings come from A. The final functions must be equal (or both absent).
//
// Thread-safety: pure functions of their arguments.
#include <string>

#include "model/project.h"

namespace gridifs {

/// "union", "concat", "product", "shuffle", "intersection", "composition", "matrix-union".
const char* combineOpName(CombineOp op);
bool parseCombineOp(const std::string& name, CombineOp& out);

/// The combination of `a` and `b`. Throws ModelError (empty path) with one sentence when the
/// two cannot be combined that way (kinds, sizes over the limits, different final functions).
Project combineProjects(const Project& a, const Project& b, CombineOp op);

}  // namespace gridifs
