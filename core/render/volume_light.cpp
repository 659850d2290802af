#include "render/volume_light.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "base/parallel.h"

namespace gridifs {
namespace {

/// Voxels that hold density or touch one that does (26-neighbourhood): a separable dilation.
std::vector<std::uint8_t> nearDensity(const std::vector<float>& density, int n) {
  const std::size_t count = density.size(), stride[3] = {1, std::size_t(n), std::size_t(n) * std::size_t(n)};
  std::vector<std::uint8_t> mask(count), next(count);
  for (std::size_t v = 0; v < count; ++v) mask[v] = density[v] > 0.0f;
  for (int axis = 0; axis < 3; ++axis) {
    for (std::size_t v = 0; v < count; ++v) {
      const int coordinate = int((v / stride[axis]) % std::size_t(n));
      std::uint8_t m = mask[v];
      if (coordinate > 0) m |= mask[v - stride[axis]];
      if (coordinate + 1 < n) m |= mask[v + stride[axis]];
      next[v] = m;
    }
    mask.swap(next);
  }
  return mask;
}

}  // namespace

std::vector<float> lightOpticalDepth(const std::vector<float>& density, int n, const Vec3& towardLight, int threads) {
  const std::size_t count = std::size_t(n) * std::size_t(n) * std::size_t(n);
  std::vector<float> depth(count, 0.0f);
  const double length =
      std::sqrt(towardLight.x * towardLight.x + towardLight.y * towardLight.y + towardLight.z * towardLight.z);
  if (n <= 0 || density.size() != count || !(length > 0.0)) return depth;
  // A sweep from the slice nearest the light, along the light's dominant axis a: the ray from a
  // voxel centre towards the light meets the next slice at a point whose depth and density are
  // interpolated bilinearly there, and the trapezoid rule adds the step between them (exact for
  // the piecewise-linear profiles of trilinear interpolation along an axis). Beyond the last
  // centre the field falls to 0 within one voxel. O(n³), where a march per voxel is O(n⁴).
  const Vec3 l = towardLight / length;
  int a = 0;
  for (int axis = 1; axis < 3; ++axis)
    if (std::abs(l[axis]) > std::abs(l[a])) a = axis;
  const int b = (a + 1) % 3, c = (a + 2) % 3;
  const int toward = l[a] > 0.0 ? 1 : -1;
  const double db = l[b] / std::abs(l[a]), dc = l[c] / std::abs(l[a]);  // voxels per slice step
  const float halfStep = float(0.5 * (2.0 / n) * std::sqrt(1.0 + db * db + dc * dc));
  const std::size_t stride[3] = {1, std::size_t(n), std::size_t(n) * std::size_t(n)};
  const float* d = density.data();
  for (int step = 0; step < n; ++step) {
    const int slice = toward > 0 ? n - 1 - step : step, previous = slice + toward;
    const bool first = previous < 0 || previous >= n;
    parallelFor(std::size_t(n), threads, 8, [&](std::size_t begin, std::size_t end) {
      for (std::size_t jc = begin; jc < end; ++jc)
        for (int jb = 0; jb < n; ++jb) {
          const std::size_t v = std::size_t(slice) * stride[a] + std::size_t(jb) * stride[b] + jc * stride[c];
          float dq = 0.0f, rq = 0.0f;
          if (!first) {
            // Bilinear in the previous slice, 0 outside the volume.
            const double qb = jb + db, qc = double(jc) + dc;
            const double fb = std::floor(qb), fc = std::floor(qc);
            const int ib = int(fb), ic = int(fc);
            const float wb = float(qb - fb), wc = float(qc - fc);
            for (int corner = 0; corner < 4; ++corner) {
              const int ub = ib + (corner & 1), uc = ic + (corner >> 1);
              if (ub < 0 || uc < 0 || ub >= n || uc >= n) continue;
              const float w = ((corner & 1) ? wb : 1.0f - wb) * ((corner >> 1) ? wc : 1.0f - wc);
              const std::size_t q =
                  std::size_t(previous) * stride[a] + std::size_t(ub) * stride[b] + std::size_t(uc) * stride[c];
              dq += w * depth[q];
              rq += w * d[q];
            }
          }
          depth[v] = dq + halfStep * (d[v] + rq);
        }
    });
  }
  // Voxels far from any density (more than one voxel) are never weighed by a ray march: 0.
  const std::vector<std::uint8_t> near = nearDensity(density, n);
  for (std::size_t v = 0; v < count; ++v)
    if (!near[v]) depth[v] = 0.0f;
  return depth;
}

}  // namespace gridifs
