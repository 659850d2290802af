#pragma once
// The joint conditions of fractal curves and patches (Thollot, Zair, Tosan & Vandorpe 1997,
// §5.3.2): the pieces of a curve are continuous only when the end of one piece is the start of
// the next, T'_0 c_1 = T'_1 c_0 for two pieces (c_k the fixed point of T'_k), generally
// c_last·T_i = c_first·T_{i+1} for consecutive pieces in function order (λ ← λ·T). A patch whose
// pieces are named qIK (piece I along s, K along t, a full grid of them, as the presets name
// them) must also agree along shared edges: the right edge of qIK (the patch's right edge mapped
// by it) equals the left edge of q(I+1)K, and the top edge of qIK the bottom edge of qI(K+1).
// An edge of the patch is the attractor of the pieces along it; it is compared at the points of
// every address of depth 3 and at its ends, in barycentric coordinates (the control points do
// not matter).
//
// Thread-safety: pure functions of their arguments; never throw.
#include <string>
#include <vector>

#include "model/project.h"

namespace gridifs {

/// How far apart (ℓ1, barycentric) the two sides of a joint may be and still meet.
inline constexpr double kJointTolerance = 1e-7;

struct FreeFormJoint {
  std::size_t first = 0, second = 0;  // function indices, in piece order
  bool edge = false;                  // false: a curve's end meets the next start; true: a patch edge
  double gap = 0.0;                   // the largest ℓ1 distance between the two sides
  bool operator==(const FreeFormJoint&) const = default;
};

/// Every joint condition of a free-form project's pieces with its gap: the shared edges when
/// the functions form a patch, else the curve joints of consecutive functions. Empty for a
/// grid project or one with fewer than two matrix functions of the space's size.
std::vector<FreeFormJoint> freeFormJoints(const Project& project);

/// The joints of freeFormJoints whose gap is above kJointTolerance.
std::vector<FreeFormJoint> failingJoints(const Project& project);

/// The joints that held in `before` and fail in `after` (the same joints, compared by pieces):
/// what an edit broke. A Sierpinski gasket, whose pieces never met end to start, has none.
std::vector<FreeFormJoint> brokenJoints(const Project& before, const Project& after);

/// One sentence naming the failing pair: "left → right: the end of left is not the start of
/// right (gap 0.012); a fractal curve needs them equal".
std::string describeJoint(const Project& project, const FreeFormJoint& joint);

}  // namespace gridifs
