#pragma once
// The modelling space of a free-form IFS: the attractor lives in the simplex of m barycentric
// coordinates and is plotted through m control points, P·λ = Σ_j λ_j p_j (Thollot, Zair, Tosan &
// Vandorpe 1997, §3.1, eq. 3.1–3.2).
#include <vector>

#include "base/types.h"

namespace gridifs {

namespace limits {
inline constexpr int kMinControlPoints = 2;
inline constexpr int kMaxControlPoints = 64;
}  // namespace limits

/// Nodes per axis of a final-function lattice interpolated as Bézier control points (the
/// Bernstein degree is nodes − 1; higher degrees gain little and cost nodes³ per point).
inline constexpr int kMaxBezierLatticeNodes = 8;

struct FreeFormSpace {
  std::vector<Vec3> control_points;  // "space.control_points": m points
  bool operator==(const FreeFormSpace&) const = default;
};

}  // namespace gridifs
