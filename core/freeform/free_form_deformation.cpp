#include "freeform/free_form_deformation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <sstream>

#include "freeform/free_form.h"
#include "freeform/free_form_basis.h"
#include "model/stack_evaluator.h"

namespace gridifs {
namespace {

/// x ↦ A·x + b, rows of [A | b].
using Affine = std::array<std::array<double, 4>, 3>;

Vec3 applyAffine(const Affine& t, const Vec3& p) {
  Vec3 out;
  for (int r = 0; r < 3; ++r) out[r] = t[r][0] * p.x + t[r][1] * p.y + t[r][2] * p.z + t[r][3];
  return out;
}

/// The least-squares affine map through a grid's nodes (the images of the regular lattice over
/// X = [-1, 1]³); `maxError` receives the largest distance between a node and the fit.
Affine fitAffine3(const Grid& g, double& maxError) {
  const Index3 n = g.resolution();
  BarycentricMatrix normal(4, std::vector<double>(4, 0.0)), rhs(4, std::vector<double>(3, 0.0));
  auto lattice = [&](int i, int j, int k) {
    return std::array<double, 4>{-1.0 + 2.0 * i / (n[0] - 1), -1.0 + 2.0 * j / (n[1] - 1), -1.0 + 2.0 * k / (n[2] - 1),
                                 1.0};
  };
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const auto u = lattice(i, j, k);
        const Vec3 q = g.node(i, j, k);
        for (int a = 0; a < 4; ++a) {
          for (int b = 0; b < 4; ++b) normal[a][b] += u[a] * u[b];
          for (int c = 0; c < 3; ++c) rhs[a][c] += u[a] * q[c];
        }
      }
  const BarycentricMatrix s = solveLinear(normal, rhs);  // s[a][c]: coefficient of u_a in coordinate c
  Affine t{};
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 4; ++a) t[c][a] = s[a][c];
  maxError = 0.0;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const auto u = lattice(i, j, k);
        maxError = std::max(maxError, double(glm::length(applyAffine(t, Vec3{u[0], u[1], u[2]}) - g.node(i, j, k))));
      }
  return t;
}

struct Box {
  Vec3 lo{-1.0}, hi{1.0};
};

/// The box the attractor lies in: B ← box hull of ⋃ T_i(B) from X, until it settles. Throws when
/// it grows without bound (a map that does not contract).
Box attractorBox(const std::vector<Affine>& maps, bool planar) {
  Box box;
  if (planar) box.lo.z = box.hi.z = 0.0;
  for (int iteration = 0; iteration < 400; ++iteration) {
    Box next{Vec3{1e300}, Vec3{-1e300}};
    for (const Affine& t : maps)
      for (int c = 0; c < 8; ++c) {
        const Vec3 corner{c & 1 ? box.hi.x : box.lo.x, c & 2 ? box.hi.y : box.lo.y, c & 4 ? box.hi.z : box.lo.z};
        const Vec3 p = applyAffine(t, corner);
        next.lo = glm::min(next.lo, p);
        next.hi = glm::max(next.hi, p);
      }
    const double change = glm::length(next.lo - box.lo) + glm::length(next.hi - box.hi);
    box = next;
    if (!(glm::length(box.hi - box.lo) < 1e6))
      throw ModelError("functions", "the functions' affine maps do not contract: the attractor has no bounded box");
    if (change < 1e-12) break;
  }
  return box;
}

/// The simplex the net is built on: a triangle around the box in the plane z = 0 (its base
/// under the box, its apex above), or a corner tetrahedron around the box in space.
std::vector<Vec3> netSimplex(const Box& box, int dim) {
  const Vec3 c = 0.5 * (box.lo + box.hi);
  Vec3 h = 0.5 * (box.hi - box.lo);
  const double largest = std::max({h.x, h.y, dim == 3 ? h.z : 0.0, 1e-3});
  for (int a = 0; a < dim; ++a) h[a] = std::max(h[a], 0.05 * largest);
  if (dim == 2)
    return {Vec3{c.x - 2.0 * h.x, c.y - h.y, 0.0}, Vec3{c.x + 2.0 * h.x, c.y - h.y, 0.0},
            Vec3{c.x, c.y + 3.0 * h.y, 0.0}};
  const Vec3 o = c - h;
  return {o, o + Vec3{6.0 * h.x, 0, 0}, o + Vec3{0, 6.0 * h.y, 0}, o + Vec3{0, 0, 6.0 * h.z}};
}

/// Barycentric coordinates of p on the simplex `v` (dim + 1 vertices).
std::vector<double> barycentric(const std::vector<Vec3>& v, const Vec3& p, int dim) {
  const std::size_t d = static_cast<std::size_t>(dim);
  BarycentricMatrix a(d, std::vector<double>(d)), b(d, std::vector<double>{0.0});
  for (int r = 0; r < dim; ++r) {
    for (int k = 0; k < dim; ++k) a[r][k] = v[std::size_t(k) + 1][r] - v[0][r];
    b[r][0] = p[r] - v[0][r];
  }
  const BarycentricMatrix s = solveLinear(a, b);
  std::vector<double> beta(std::size_t(dim) + 1);
  beta[0] = 1.0;
  for (int k = 0; k < dim; ++k) beta[0] -= beta[std::size_t(k) + 1] = s[k][0];
  return beta;
}

/// Rows summing to 1 exactly enough for checkFreeForm; entries below rounding set to 0.
void tidyRows(BarycentricMatrix& m) {
  for (auto& row : m) {
    double sum = 0.0;
    std::size_t largest = 0;
    for (std::size_t j = 0; j < row.size(); ++j) {
      if (std::abs(row[j]) < 1e-13) row[j] = 0.0;
      sum += row[j];
      if (std::abs(row[j]) > std::abs(row[largest])) largest = j;
    }
    row[largest] += 1.0 - sum;
  }
}

std::string functionPath(std::size_t i) { return "functions[" + std::to_string(i) + "]"; }

std::vector<Affine> fitFunctions(const Project& grid, std::vector<std::string>& notes) {
  std::vector<Affine> maps;
  for (std::size_t i = 0; i < grid.functions.size(); ++i) {
    const Function& f = grid.functions[i];
    if (f.kind != FunctionKind::Grid)
      throw ModelError(functionPath(i) + ".kind", "only grid functions have an affine map to put on a control net");
    if (f.hasVariationStage())
      throw ModelError(functionPath(i) + (f.variations.empty() ? ".post" : ".variations"),
                       "flame variations and post transforms are not affine: mute or remove them first");
    double error = 0.0;
    maps.push_back(fitAffine3(evaluateFunction(f, std::size_t(-1), true, grid.time), error));
    if (error > 1e-6) {
      std::ostringstream s;
      s.precision(3);
      s << functionPath(i) << " (" << f.name << ") is not affine: its nearest affine map is off by up to " << error
        << " at a node, and the control net carries that map";
      notes.push_back(s.str());
    }
  }
  return maps;
}

Vec3 deform(const ControlNetOptions& options, const Box& box, const Vec3& p) {
  if (options.shape == ControlNetShape::Flat) return p;
  const Vec3 c = 0.5 * (box.lo + box.hi);
  const double half = std::max({0.5 * (box.hi.x - box.lo.x), 0.5 * (box.hi.y - box.lo.y), 1e-3});
  const double u = (p.x - c.x) / half, v = (p.y - c.y) / half;
  const double sign = options.shape == ControlNetShape::EllipticParaboloid ? 1.0 : -1.0;
  return p + Vec3{0.0, 0.0, options.height * half * (u * u + sign * v * v)};
}

}  // namespace

const char* controlNetShapeName(ControlNetShape shape) {
  switch (shape) {
    case ControlNetShape::EllipticParaboloid:
      return "elliptic-paraboloid";
    case ControlNetShape::HyperbolicParaboloid:
      return "hyperbolic-paraboloid";
    case ControlNetShape::Flat:
      break;
  }
  return "flat";
}

bool parseControlNetShape(const std::string& name, ControlNetShape& out) {
  for (ControlNetShape s :
       {ControlNetShape::Flat, ControlNetShape::EllipticParaboloid, ControlNetShape::HyperbolicParaboloid})
    if (name == controlNetShapeName(s)) {
      out = s;
      return true;
    }
  return false;
}

ControlNetResult mapOntoControlNet(const Project& grid, const ControlNetOptions& options) {
  if (grid.space) throw ModelError("space", "the project already has control points");
  if (grid.functions.empty()) throw ModelError("functions", "the project has no functions to map");
  if (!std::isfinite(options.height) || std::abs(options.height) > 100.0)
    throw ModelError("height", "expected a height between -100 and 100");
  ControlNetResult result;
  const std::vector<Affine> maps = fitFunctions(grid, result.notes);
  // The plane z = 0 holds the attractor when every map keeps it (then so does the unique attractor).
  bool planar = true;
  for (const Affine& t : maps) planar &= std::abs(t[2][0]) + std::abs(t[2][1]) + std::abs(t[2][3]) < 1e-9;
  const int dim = planar ? 2 : 3, maxDegree = planar ? kMaxPlanarNetDegree : kMaxSpatialNetDegree;
  const int n = options.degree;
  if (n < 1 || n > maxDegree)
    throw ModelError("degree", "expected a degree between 1 and " + std::to_string(maxDegree) + " for a " +
                                   (planar ? "planar" : "spatial") + " attractor, found " + std::to_string(n));
  if (n < 2 && options.shape != ControlNetShape::Flat)
    throw ModelError("degree", "a paraboloid is quadratic: the net needs degree 2 or more");
  std::vector<Affine> unmuted;
  for (std::size_t i = 0; i < maps.size(); ++i)
    if (!grid.functions[i].muted) unmuted.push_back(maps[i]);
  const Box box = attractorBox(unmuted.empty() ? maps : unmuted, planar);
  const std::vector<Vec3> simplex = netSimplex(box, dim);
  const auto indices = simplexIndices(dim, n);
  // Collocation at the domain points x_α = Σ α_i v_i / n: C = B(x_α) (the same for every simplex).
  BarycentricMatrix collocation, images;
  std::vector<Vec3> domain;
  for (const auto& alpha : indices) {
    std::vector<double> beta(alpha.begin(), alpha.end());
    Vec3 x{0.0};
    for (std::size_t k = 0; k < beta.size(); ++k) x += (beta[k] /= n) * simplex[k];
    domain.push_back(x);
    collocation.push_back(simplexBernstein(n, indices, beta));
    const Vec3 f = deform(options, box, x);
    images.push_back({f.x, f.y, f.z});
  }
  const BarycentricMatrix points = solveLinear(collocation, images);
  result.dimension = dim;
  Project& out = result.project;
  out = grid;
  out.space = FreeFormSpace{};
  for (const auto& p : points) out.space->control_points.push_back(Vec3{p[0], p[1], p[2]});
  out.functions.clear();
  for (std::size_t i = 0; i < grid.functions.size(); ++i) {
    BarycentricMatrix moved;
    for (const Vec3& x : domain)
      moved.push_back(simplexBernstein(n, indices, barycentric(simplex, applyAffine(maps[i], x), dim)));
    const Function& g = grid.functions[i];
    Function f;
    f.kind = FunctionKind::Matrix;
    f.name = g.name;
    f.weight = g.weight;
    f.color = g.color;
    f.palette_index = g.palette_index;
    f.color_speed = g.color_speed;
    f.muted = g.muted;
    f.matrix = solveLinear(collocation, moved);  // B(T x) = B(x)·M at every domain point
    tidyRows(f.matrix);
    out.functions.push_back(std::move(f));
  }
  if (!out.tracks.empty()) {
    result.notes.push_back("the keyframe tracks animated grid operations and were dropped");
    out.tracks.clear();
  }
  checkFreeForm(out);
  return result;
}

}  // namespace gridifs
