#pragma once
// Evaluates a function's op stack: distorted nodes = placement(stack(undistorted)).
#include <memory>

#include "model/function.h"
#include "model/grid.h"

namespace gridifs {

/// The rotation of Euler angles in degrees, R = Rz·Ry·Rx (x first), as a matrix.
struct EulerRotation {
  explicit EulerRotation(const Vec3& anglesDegrees);
  Vec3 apply(const Vec3& q) const {
    return {m[0].x * q.x + m[0].y * q.y + m[0].z * q.z, m[1].x * q.x + m[1].y * q.y + m[1].z * q.z,
            m[2].x * q.x + m[2].y * q.y + m[2].z * q.z};
  }
  Vec3 m[3];  // rows
};

/// R·q for Euler angles in degrees (see EulerRotation).
Vec3 rotateEuler(const Vec3& q, const Vec3& anglesDegrees);

/// Triangle wave in [-1, 1] with the period and phase of sin: tri(0) = 0, tri(π/2) = 1
/// (the 'ping-pong' profile of Gröller & Wegenkittl 1994, §4.3, figure 13).
double triangleWave(double x);

/// The centroid used as center of transformation for `op` on the current nodes.
Vec3 operationCenter(const Operation& op, const std::vector<Vec3>& nodes, const std::vector<unsigned char>& mask);

/// Applies one operation in place to `nodes` (a grid of `resolution`) at project time `time`.
/// Throws ModelError (path relative to the op, e.g. "pairs" or "x") on a singular
/// morph, a calculator error or a non-finite result.
void applyOperation(const Operation& op, std::vector<Vec3>& nodes, const Index3& resolution, double time = 0.0);

/// Solves the morph's RBF system (Gröller & Wegenkittl 1994, §2.6) and returns α (one Vec3 per pair) and r_i.
/// Throws ModelError("pairs", ...) for coincident or (numerically) singular start points.
void solveMorph(const MorphOp& morph, std::vector<Vec3>& alpha, std::vector<double>& radius);

/// placement(q) = T + R·(S·q).
Vec3 applyPlacement(const Placement& placement, const Vec3& q);

/// Evaluates the whole stack (muted ops skipped) and the placement at project time `time`.
/// `upToOp` < ops.size() stops before that op (the UI shows intermediate stages).
/// Throws ModelError with a path relative to the function ("ops[3].k: ...").
Grid evaluateFunction(const Function& function, std::size_t upToOp = std::size_t(-1), bool applyPlacementToo = true,
                      double time = 0.0);

/// evaluateFunction with errors located under `path` ("functions[2]", "final"), the form
/// every caller outside the stack reports (Document cache, compiled snapshots, mesh export).
std::shared_ptr<const Grid> evaluateFunctionAt(const Function& function, const std::string& path, double time = 0.0);

/// Whether the function's grid changes with the project time: an unmuted field op, or a
/// calculator whose expressions read t. Caches of evaluated grids key on the time only then.
bool dependsOnTime(const Function& function);

}  // namespace gridifs
