#pragma once
// Adding and removing control points of a free-form IFS (Thollot, Zair, Tosan & Vandorpe 1997,
// §3.1), every matrix resized with them so that rows still sum to 1.
//  - A Bézier curve (two functions that are the de Casteljau halves of one degree at one r)
//    stays one: adding a point elevates the degree (the m + 1 new points trace the same curve,
//    the new one placed by the elevation, not by the caller), removing point j leaves the Bézier
//    curve of the other points, one degree lower, split at the same r.
//  - Any other project: an added point gets a zero column in every matrix (no coordinate moves
//    towards it, so the attractor is unchanged until that column is edited) and, as its row, the
//    mean of the other rows (where it goes is where the average coordinate goes, which keeps the
//    matrix a contraction when it was one). Removing point j deletes its row and column and
//    shares what went to j among the row's other entries in proportion (a row that went to j
//    alone stays where it is).
//
// Thread-safety: pure functions of their arguments. Throw ModelError ("space.control_points")
// for a project without control points, or one that would leave 2..64 points.
#include <optional>

#include "model/project.h"

namespace gridifs {

/// Whether the project is a Bézier curve (see above); `r` receives its split.
bool isBezierCurve(const Project& project, double* r = nullptr);

/// Adds a control point at `point` (default: the centroid of the others) as described above.
void addControlPoint(Project& project, std::optional<Vec3> point = std::nullopt);

/// Removes control point `index` as described above.
void removeControlPoint(Project& project, std::size_t index);

}  // namespace gridifs
