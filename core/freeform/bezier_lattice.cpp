#include "freeform/bezier_lattice.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "model/free_form_space.h"

namespace gridifs {
namespace {

using Basis = std::array<double, kMaxBezierLatticeNodes>;

/// B_i^{n−1}(t) for i < n, by de Casteljau's recurrence (stable for t in [0, 1]).
Basis bernsteinBasis(int n, double t) {
  Basis b{};
  b[0] = 1.0;
  for (int degree = 1; degree < n; ++degree) {
    for (int i = degree; i > 0; --i) b[std::size_t(i)] = (1.0 - t) * b[std::size_t(i)] + t * b[std::size_t(i - 1)];
    b[0] *= 1.0 - t;
  }
  return b;
}

double toUnit(double x) {
  x = x > -1.0 ? x : -1.0;  // NaN → -1
  x = x < 1.0 ? x : 1.0;
  return 0.5 * (x + 1.0);
}

}  // namespace

Vec3 evaluateBezierLattice(const Grid& lattice, Vec3 p) {
  const Index3 n = lattice.resolution();
  for (int d = 0; d < 3; ++d)
    if (n[d] > kMaxBezierLatticeNodes)
      throw ModelError("resolution", "a \"bezier\" lattice has at most " + std::to_string(kMaxBezierLatticeNodes) +
                                         " nodes per axis");
  const Basis bu = bernsteinBasis(n[0], toUnit(p.x)), bv = bernsteinBasis(n[1], toUnit(p.y)),
              bw = bernsteinBasis(n[2], toUnit(p.z));
  Vec3 out{0.0};
  for (int k = 0; k < n[2]; ++k) {
    Vec3 plane{0.0};
    for (int j = 0; j < n[1]; ++j) {
      Vec3 row{0.0};
      for (int i = 0; i < n[0]; ++i) row += bu[std::size_t(i)] * lattice.node(i, j, k);
      plane += bv[std::size_t(j)] * row;
    }
    out += bw[std::size_t(k)] * plane;
  }
  return out;
}

std::shared_ptr<const Grid> sampleBezierLattice(const Grid& lattice, int nodes) {
  auto grid = std::make_shared<Grid>(Index3{nodes, nodes, nodes});
  for (int k = 0; k < nodes; ++k)
    for (int j = 0; j < nodes; ++j)
      for (int i = 0; i < nodes; ++i) grid->node(i, j, k) = evaluateBezierLattice(lattice, grid->undistorted(i, j, k));
  return grid;
}

}  // namespace gridifs
