#include "model/grid_affine_fit.h"

#include <algorithm>
#include <cmath>

namespace gridifs {
namespace {

/// Solves the 3×3 normal equations M·s = r by Cramer's rule (M symmetric positive definite for
/// any grid with non-collinear nodes).
std::array<double, 3> solve3(const double m[3][3], const double r[3]) {
  auto det = [](const double a[3][3]) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const double d = det(m);
  std::array<double, 3> s{};
  for (int c = 0; c < 3; ++c) {
    double t[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) t[i][j] = j == c ? r[i] : m[i][j];
    s[std::size_t(c)] = det(t) / d;
  }
  return s;
}

}  // namespace

FlameAffine fitAffine(const Grid& g, double& maxError) {
  const Index3 n = g.resolution();
  const Index3 n3 = n;
  double m[3][3] = {}, rx[3] = {}, ry[3] = {};
  for (int k = 0; k < n3[2]; ++k)
    for (int j = 0; j < n3[1]; ++j)
      for (int i = 0; i < n3[0]; ++i) {
        const double u[3] = {-1.0 + 2.0 * i / (n[0] - 1), -1.0 + 2.0 * j / (n[1] - 1), 1.0};
        const Vec3 q = g.node(i, j, k);
        for (int a = 0; a < 3; ++a) {
          for (int b = 0; b < 3; ++b) m[a][b] += u[a] * u[b];
          rx[a] += u[a] * q.x;
          ry[a] += u[a] * q.y;
        }
      }
  const auto sx = solve3(m, rx), sy = solve3(m, ry);
  FlameAffine f{sx[0], sx[1], sx[2], sy[0], sy[1], sy[2]};
  maxError = 0.0;
  for (int k = 0; k < n3[2]; ++k)
    for (int j = 0; j < n3[1]; ++j)
      for (int i = 0; i < n3[0]; ++i) {
        const FlamePoint p = f.apply({-1.0 + 2.0 * i / (n[0] - 1), -1.0 + 2.0 * j / (n[1] - 1)});
        const Vec3 q = g.node(i, j, k);
        maxError = std::max(maxError, std::sqrt((q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y) + q.z * q.z));
      }
  return f;
}

}  // namespace gridifs
