// The light's optical depth behind the volume preview's self-shadowing (Beer–Lambert
// transmittance exp(-σ · depth) along the ray towards the light), checked against integrals
// worked out by hand for fields whose trilinear interpolation is piecewise linear.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>

#include "render/volume_light.h"

namespace gridifs {
namespace {

std::size_t voxelIndex(int n, int i, int j, int k) {
  return std::size_t(i) + std::size_t(n) * (std::size_t(j) + std::size_t(n) * std::size_t(k));
}

TEST(VolumeLight, UniformDensityGivesThePathLengthToTheBoundary) {
  const int n = 16;
  const std::vector<float> density(std::size_t(n * n * n), 1.0f);
  const std::vector<float> depth = lightOpticalDepth(density, n, Vec3(1.0, 0.0, 0.0), 2);
  for (int i = 0; i < n; ++i) {
    // Density 1 up to the last voxel centre, then a linear fall to 0 over one voxel (half a voxel of mass).
    const double expected = (double(n - 1 - i) + 0.5) * 2.0 / n;
    EXPECT_NEAR(depth[voxelIndex(n, i, 5, 7)], expected, 1e-4) << "voxel " << i;
  }
  // Towards -x the same from the other side; the light's length does not matter.
  const std::vector<float> back = lightOpticalDepth(density, n, Vec3(-3.0, 0.0, 0.0), 1);
  EXPECT_NEAR(back[voxelIndex(n, 0, 5, 7)], 0.5 * 2.0 / n, 1e-4);
  EXPECT_NEAR(back[voxelIndex(n, n - 1, 5, 7)], (double(n - 1) + 0.5) * 2.0 / n, 1e-4);
}

TEST(VolumeLight, ABlockerShadowsWhatLiesBehindIt) {
  const int n = 24;
  std::vector<float> density(std::size_t(n * n * n), 0.0f);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 14; i < 18; ++i) density[voxelIndex(n, i, j, k)] = 1.0f;  // a slab across x
  density[voxelIndex(n, 4, 12, 12)] = 0.5f;   // a speck behind the slab (the light comes from +x)
  density[voxelIndex(n, 20, 12, 12)] = 0.5f;  // a speck in front of it
  const std::vector<float> depth = lightOpticalDepth(density, n, Vec3(1.0, 0.0, 0.0), 2);
  // Behind: the whole slab, 3 voxels between its outer centres plus half a voxel of ramp at each
  // face, the speck's own ramp towards its neighbour (a quarter voxel) and the speck in front of
  // the slab (a tent of height 0.5 and base 2: half a voxel).
  EXPECT_NEAR(depth[voxelIndex(n, 4, 12, 12)], 4.75 * 2.0 / n, 1e-4);
  EXPECT_LT(depth[voxelIndex(n, 20, 12, 12)], 0.5 * 2.0 / n);  // only its own half voxel
  // A light along +y misses the slab (it spans all y, but the speck lies beside it in x): lit.
  const std::vector<float> sideways = lightOpticalDepth(density, n, Vec3(0.0, 1.0, 0.0), 2);
  EXPECT_LT(sideways[voxelIndex(n, 4, 12, 12)], 0.5 * 2.0 / n);
  // Far from any density nothing is computed (the ray march never weighs it).
  EXPECT_EQ(depth[voxelIndex(n, 2, 2, 2)], 0.0f);
}

/// The optical depth by brute force: a fine midpoint march of the trilinear field towards the light.
double marchedDepth(const std::vector<float>& d, int n, int i, int j, int k, Vec3 l) {
  l /= std::sqrt(l.x * l.x + l.y * l.y + l.z * l.z);
  auto at3 = [&](int a, int b, int c) -> double {
    if (a < 0 || b < 0 || c < 0 || a >= n || b >= n || c >= n) return 0.0;
    return d[voxelIndex(n, a, b, c)];
  };
  const double h = 0.02;
  double sum = 0.0;
  for (double t = 0.5 * h; t < 2.0 * n; t += h) {
    const double x = i + l.x * t, y = j + l.y * t, z = k + l.z * t;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y)), z0 = int(std::floor(z));
    const double fx = x - x0, fy = y - y0, fz = z - z0;
    double v = 0.0;
    for (int c = 0; c < 8; ++c)
      v += ((c & 1) ? fx : 1 - fx) * ((c & 2) ? fy : 1 - fy) * ((c & 4) ? fz : 1 - fz) *
           at3(x0 + (c & 1), y0 + ((c >> 1) & 1), z0 + ((c >> 2) & 1));
    sum += v * h;
  }
  return sum * 2.0 / n;
}

TEST(VolumeLight, AnObliqueLightMatchesAMarchOfTheInterpolatedField) {
  // A smooth blob: the sweep's interpolation between slices stays within a few percent of the
  // exact integral of the trilinear field (bilinear interpolation of the depth slice by slice
  // smooths its peak a little: about 4% low at the blob's centre here).
  const int n = 32;
  std::vector<float> density(std::size_t(n * n * n));
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = (i - 15.5) / 8.0, y = (j - 15.5) / 8.0, z = (k - 15.5) / 8.0;
        density[voxelIndex(n, i, j, k)] = float(std::exp(-(x * x + y * y + z * z)));
      }
  const Vec3 light(0.8, -0.5, 0.35);
  const std::vector<float> depth = lightOpticalDepth(density, n, light, 2);
  for (const auto& v : {std::array<int, 3>{16, 16, 16}, {8, 20, 12}, {20, 10, 22}, {4, 28, 6}}) {
    const double expected = marchedDepth(density, n, v[0], v[1], v[2], light);
    EXPECT_NEAR(depth[voxelIndex(n, v[0], v[1], v[2])], expected, 0.07 * expected + 1e-3)
        << v[0] << " " << v[1] << " " << v[2];
  }
}

TEST(VolumeLight, NoLightOrAMismatchedVolumeLeavesEverythingLit) {
  const int n = 8;
  const std::vector<float> density(std::size_t(n * n * n), 1.0f);
  for (float d : lightOpticalDepth(density, n, Vec3(0.0), 1)) EXPECT_EQ(d, 0.0f);
  const std::vector<float> wrong = lightOpticalDepth(std::vector<float>(10, 1.0f), n, Vec3(1.0, 0.0, 0.0), 1);
  EXPECT_EQ(wrong.size(), std::size_t(n * n * n));
  for (float d : wrong) EXPECT_EQ(d, 0.0f);
}

}  // namespace
}  // namespace gridifs
