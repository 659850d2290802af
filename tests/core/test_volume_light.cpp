// The light's optical depth behind the volume preview's self-shadowing (Beer–Lambert
// transmittance exp(-σ · depth) along the ray towards the light), checked against integrals
// worked out by hand for fields whose trilinear interpolation is piecewise linear.
#include <gtest/gtest.h>

#include <cstddef>

#include "render/volume_light.h"

namespace gridifs {
namespace {

std::size_t at(int n, int i, int j, int k) {
  return std::size_t(i) + std::size_t(n) * (std::size_t(j) + std::size_t(n) * std::size_t(k));
}

TEST(VolumeLight, UniformDensityGivesThePathLengthToTheBoundary) {
  const int n = 16;
  const std::vector<float> density(std::size_t(n * n * n), 1.0f);
  const std::vector<float> depth = lightOpticalDepth(density, n, Vec3(1.0, 0.0, 0.0), 2);
  for (int i = 0; i < n; ++i) {
    // Density 1 up to the last voxel centre, then a linear fall to 0 over one voxel (half a voxel of mass).
    const double expected = (double(n - 1 - i) + 0.5) * 2.0 / n;
    EXPECT_NEAR(depth[at(n, i, 5, 7)], expected, 1e-4) << "voxel " << i;
  }
  // Towards -x the same from the other side; the light's length does not matter.
  const std::vector<float> back = lightOpticalDepth(density, n, Vec3(-3.0, 0.0, 0.0), 1);
  EXPECT_NEAR(back[at(n, 0, 5, 7)], 0.5 * 2.0 / n, 1e-4);
  EXPECT_NEAR(back[at(n, n - 1, 5, 7)], (double(n - 1) + 0.5) * 2.0 / n, 1e-4);
}

TEST(VolumeLight, ABlockerShadowsWhatLiesBehindIt) {
  const int n = 24;
  std::vector<float> density(std::size_t(n * n * n), 0.0f);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 14; i < 18; ++i) density[at(n, i, j, k)] = 1.0f;  // a slab across x
  density[at(n, 4, 12, 12)] = 0.5f;   // a speck behind the slab (the light comes from +x)
  density[at(n, 20, 12, 12)] = 0.5f;  // a speck in front of it
  const std::vector<float> depth = lightOpticalDepth(density, n, Vec3(1.0, 0.0, 0.0), 2);
  // Behind: the whole slab, 3 voxels between its outer centres plus half a voxel of ramp at each
  // face, the speck's own ramp towards its neighbour (a quarter voxel) and the speck in front of
  // the slab (a tent of height 0.5 and base 2: half a voxel).
  EXPECT_NEAR(depth[at(n, 4, 12, 12)], 4.75 * 2.0 / n, 1e-4);
  EXPECT_LT(depth[at(n, 20, 12, 12)], 0.5 * 2.0 / n);  // only its own half voxel
  // A light along +y misses the slab (it spans all y, but the speck lies beside it in x): lit.
  const std::vector<float> sideways = lightOpticalDepth(density, n, Vec3(0.0, 1.0, 0.0), 2);
  EXPECT_LT(sideways[at(n, 4, 12, 12)], 0.5 * 2.0 / n);
  // Far from any density nothing is computed (the ray march never weighs it).
  EXPECT_EQ(depth[at(n, 2, 2, 2)], 0.0f);
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
