#include "model/grid.h"

#include <algorithm>
#include <cmath>

namespace gridifs {

Grid::Grid(const Index3& resolution) : resolution_(resolution) {
  for (int d = 0; d < 3; ++d)
    if (resolution[d] < limits::kMinResolution || resolution[d] > limits::kMaxResolution)
      throw ModelError("", "grid resolution must be between 2 and 128 nodes per axis");
  nodes_.resize(std::size_t(resolution[0]) * resolution[1] * resolution[2]);
  for (int k = 0; k < resolution[2]; ++k)
    for (int j = 0; j < resolution[1]; ++j)
      for (int i = 0; i < resolution[0]; ++i) nodes_[index(i, j, k)] = undistorted(i, j, k);
}

Vec3 Grid::undistorted(int i, int j, int k) const {
  return {-1.0 + 2.0 * i / (resolution_[0] - 1), -1.0 + 2.0 * j / (resolution_[1] - 1),
          -1.0 + 2.0 * k / (resolution_[2] - 1)};
}

Vec3 Grid::evaluate(Vec3 p) const {
  int cell[3];
  double frac[3];
  for (int d = 0; d < 3; ++d) {
    // Points outside X are clamped to X first; NaN maps to -1.
    const double c = std::clamp(std::isnan(p[d]) ? -1.0 : p[d], -1.0, 1.0);
    const double s = (c + 1.0) * 0.5 * (resolution_[d] - 1);
    const int cd = std::min(static_cast<int>(s), resolution_[d] - 2);
    cell[d] = cd;
    frac[d] = s - cd;
  }
  const Vec3* base = &nodes_[index(cell[0], cell[1], cell[2])];
  const std::size_t sj = resolution_[0], sk = std::size_t(resolution_[0]) * resolution_[1];
  const double fx = frac[0], fy = frac[1], fz = frac[2];
  auto lerp = [](const Vec3& a, const Vec3& b, double t) { return a + (b - a) * t; };
  const Vec3 c00 = lerp(base[0], base[1], fx);
  const Vec3 c10 = lerp(base[sj], base[sj + 1], fx);
  const Vec3 c01 = lerp(base[sk], base[sk + 1], fx);
  const Vec3 c11 = lerp(base[sk + sj], base[sk + sj + 1], fx);
  return lerp(lerp(c00, c10, fy), lerp(c01, c11, fy), fz);
}

bool allFinite(const Grid& grid) {
  for (const Vec3& n : grid.nodes())
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) return false;
  return true;
}

}  // namespace gridifs
