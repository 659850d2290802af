#include "render/volume_light.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "base/parallel.h"

namespace gridifs {
namespace {

/// Trilinear density at a point in voxel coordinates (voxel centres at integers), 0 outside.
float sampleTrilinear(const float* density, int n, double x, double y, double z) {
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const int x0 = int(fx), y0 = int(fy), z0 = int(fz);
  const float tx = float(x - fx), ty = float(y - fy), tz = float(z - fz);
  auto at = [&](int i, int j, int k) -> float {
    if (i < 0 || j < 0 || k < 0 || i >= n || j >= n || k >= n) return 0.0f;
    return density[std::size_t(i) + std::size_t(n) * (std::size_t(j) + std::size_t(n) * std::size_t(k))];
  };
  const float c00 = at(x0, y0, z0) + (at(x0 + 1, y0, z0) - at(x0, y0, z0)) * tx;
  const float c10 = at(x0, y0 + 1, z0) + (at(x0 + 1, y0 + 1, z0) - at(x0, y0 + 1, z0)) * tx;
  const float c01 = at(x0, y0, z0 + 1) + (at(x0 + 1, y0, z0 + 1) - at(x0, y0, z0 + 1)) * tx;
  const float c11 = at(x0, y0 + 1, z0 + 1) + (at(x0 + 1, y0 + 1, z0 + 1) - at(x0, y0 + 1, z0 + 1)) * tx;
  const float c0 = c00 + (c10 - c00) * ty, c1 = c01 + (c11 - c01) * ty;
  return c0 + (c1 - c0) * tz;
}

/// Whether voxel (i, j, k) or one of its 26 neighbours holds density.
bool nearDensity(const float* density, int n, int i, int j, int k) {
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int a = i + di, b = j + dj, c = k + dk;
        if (a < 0 || b < 0 || c < 0 || a >= n || b >= n || c >= n) continue;
        if (density[std::size_t(a) + std::size_t(n) * (std::size_t(b) + std::size_t(n) * std::size_t(c))] > 0.0f)
          return true;
      }
  return false;
}

}  // namespace

std::vector<float> lightOpticalDepth(const std::vector<float>& density, int n, const Vec3& towardLight, int threads) {
  const std::size_t count = std::size_t(n) * std::size_t(n) * std::size_t(n);
  std::vector<float> depth(count, 0.0f);
  const double length =
      std::sqrt(towardLight.x * towardLight.x + towardLight.y * towardLight.y + towardLight.z * towardLight.z);
  if (n <= 0 || density.size() != count || !(length > 0.0)) return depth;
  // Half a voxel per step along the light, midpoint rule: with trilinear interpolation this
  // is close to the exact integral of the interpolated field (the shadow has no stair steps).
  const Vec3 step = towardLight / length * 0.5;  // in voxel units
  const double worldStep = 0.5 * 2.0 / double(n);
  const float* d = density.data();
  const double high = double(n) - 0.5;  // beyond the last centre the field falls to 0 within one voxel
  parallelFor(count, threads, 4096, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
      const int i = int(v % std::size_t(n)), j = int((v / std::size_t(n)) % std::size_t(n)),
                k = int(v / (std::size_t(n) * std::size_t(n)));
      if (!nearDensity(d, n, i, j, k)) continue;
      double x = i + 0.5 * step.x, y = j + 0.5 * step.y, z = k + 0.5 * step.z;
      double sum = 0.0;
      while (x > -1.0 && y > -1.0 && z > -1.0 && x < high + 0.5 && y < high + 0.5 && z < high + 0.5) {
        sum += sampleTrilinear(d, n, x, y, z);
        x += step.x;
        y += step.y;
        z += step.z;
      }
      depth[v] = float(sum * worldStep);
    }
  });
  return depth;
}

}  // namespace gridifs
