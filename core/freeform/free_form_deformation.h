#pragma once
// F̂ for any IFS (Thollot, Zair, Tosan & Vandorpe 1997, §5.2 and §5.5): a grid project's
// functions, fitted by affine maps T_i, become matrices of barycentric coordinates on a control
// net, so that the free-form attractor is F(A), the image of the grid attractor A under the
// control-point map F. The basis is the Bernstein basis of total degree n on a triangle (an
// attractor in the plane z = 0) or a tetrahedron around the attractor: polynomials of total
// degree ≤ n stay polynomials of total degree ≤ n under every affine map, so B(T x) = B(x)·M_T
// holds exactly for one matrix M_T = F̂(T) (found by collocation at the domain points) and, by
// eq. 5.1, F(A) is the attractor of {F̂(T_i)}. The net starts as F = the identity lifted to degree
// n (moving its points deforms the attractor smoothly), or as one of the paper's quadratic
// deformations (figure 5.5): z + h·(u² + v²), the elliptic paraboloid, or z + h·(u² − v²), the
// hyperbolic one, u and v the attractor's x and y measured from its centre in half-widths.
//
// Thread-safety: pure functions of their arguments. Throws ModelError with a JSON path.
#include <string>
#include <vector>

#include "model/project.h"

namespace gridifs {

enum class ControlNetShape { Flat, EllipticParaboloid, HyperbolicParaboloid };

/// "flat", "elliptic-paraboloid", "hyperbolic-paraboloid".
const char* controlNetShapeName(ControlNetShape shape);
bool parseControlNetShape(const std::string& name, ControlNetShape& out);

/// The largest degrees: C(n + 2, 2) and C(n + 3, 3) control points stay within the limit of 64.
inline constexpr int kMaxPlanarNetDegree = 7, kMaxSpatialNetDegree = 5;

struct ControlNetOptions {
  int degree = 2;  // total degree n of the net, 1..7 (plane) or 1..5 (space)
  ControlNetShape shape = ControlNetShape::Flat;
  double height = 0.5;  // h of the paraboloids, in half-widths of the attractor
};

struct ControlNetResult {
  Project project;                 // the free-form project: same names, weights, colours, transitions
  std::vector<std::string> notes;  // functions that are only nearly affine, dropped keyframe tracks
  int dimension = 2;               // 2: a triangular net (planar attractor), 3: a tetrahedral one
};

/// F̂ of every function of the grid project `grid`. Throws ModelError for a project that already
/// has control points ("space"), condensation or median functions, flame variations or a post
/// transform ("functions[i].variations"), a degree out of range ("degree"), a paraboloid of
/// degree 1, maps that do not contract (no bounded attractor), or grids that fail to evaluate.
ControlNetResult mapOntoControlNet(const Project& grid, const ControlNetOptions& options = {});

}  // namespace gridifs
