#pragma once
// Where a grid (or a condensation set's mesh) sits in the common initial grid.
#include "base/types.h"

namespace gridifs {

/// How the function's grid sits in the common initial grid (Gröller & Wegenkittl 1994, §4.5):
/// placement(q) = T + R·(S·q), R with the rotate op's Euler convention.
struct Placement {
  Vec3 translate{0.0}, rotate{0.0}, scale{1.0};
  bool operator==(const Placement&) const = default;
};

}  // namespace gridifs
