// The shadow maps' plotter (Williams 1978: depth maps filled by the chaos game's own samples)
// projects a chunk of samples into every shadowed light at once, eight samples at a time. Its maps
// must be exactly those of plotting one sample at a time into one light at a time: the nearest
// depth step per texel, whatever the light count, the chunk boundaries or the sample order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "render/light_view.h"
#include "render/shaded_plot.h"

namespace gridifs {
namespace {

using Map = std::vector<std::uint16_t>;

constexpr int kSize = 64;

std::vector<LightView> views() {
  const BoundingSphere bounds{glm::dvec3(0.1, -0.2, 0.05), 1.3};
  return {LightView(Vec3{0.3, -0.5, 1.0}, bounds, kSize), LightView(Vec3{-0.8, 0.4, 0.5}, bounds, kSize),
          LightView(Vec3{0.2, 0.9, -0.3}, bounds, kSize)};
}

/// Points mostly inside the bounding sphere, some beyond it (outside the map, or past its depth
/// range), and a few that are not numbers, as a diverging chain can produce.
std::vector<kernel::v4f> lightSamplePoints(int count) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> coordinate(-1.2f, 1.2f), far(-4.0f, 4.0f);
  std::vector<kernel::v4f> points;
  for (int i = 0; i < count; ++i) {
    if (i % 97 == 13) {
      points.push_back(kernel::v4f{NAN, 0.0f, 0.0f, 0.0f});
    } else if (i % 11 == 5) {
      points.push_back(kernel::v4f{far(rng), far(rng), far(rng), 0.0f});
    } else {
      const float x = coordinate(rng), y = coordinate(rng), z = coordinate(rng);
      points.push_back(kernel::v4f{x, y, z, 0.5f});
    }
  }
  return points;
}

/// One sample into one light, scalar: the light rows' float operations in the same order, the
/// texel of the truncated (u, v) when both lie in [0, size), the depth step truncated after
/// clamping to [0, kLightSteps], kept where it is nearer than the texel's.
void plotOne(const kernel::HotLight& light, kernel::v4f q, Map& map) {
  float r[3];
  for (int row = 0; row < 3; ++row)
    r[row] = light.cx[row] * q[0] + light.cy[row] * q[1] + light.cz[row] * q[2] + light.c1[row];
  if (!(r[0] >= 0.0f && r[0] < float(kSize) && r[1] >= 0.0f && r[1] < float(kSize))) return;
  const std::size_t texel = std::size_t(r[1]) * kSize + std::size_t(r[0]);
  const auto key = std::uint16_t(std::min(std::max(r[2], 0.0f), kernel::kLightSteps));
  map[texel] = std::min(map[texel], key);
}

/// The maps of `lights` (indices into views()) after plotting `points` through LightPlot.
std::vector<Map> plotChunked(const std::vector<int>& lights, const std::vector<kernel::v4f>& points) {
  const std::vector<LightView> all = views();
  std::vector<Map> maps(lights.size(), Map(std::size_t(kSize) * kSize, kernel::kLightEmpty));
  kernel::LightPlot plot;
  for (std::size_t l = 0; l < lights.size(); ++l)
    plot.lights[plot.lightCount++] = kernel::makeHotLight(all[std::size_t(lights[l])], maps[l].data());
  plot.lightSize = float(kSize);
  plot.lightStride = kSize;
  for (const kernel::v4f& q : points) EXPECT_EQ(plot(q, q), 1);
  plot.flush();
  return maps;
}

Map plotOneByOne(int light, const std::vector<kernel::v4f>& points) {
  Map map(std::size_t(kSize) * kSize, kernel::kLightEmpty);
  Map unused;
  const kernel::HotLight hot = kernel::makeHotLight(views()[std::size_t(light)], unused.data());
  for (const kernel::v4f& q : points) plotOne(hot, q, map);
  return map;
}

int filled(const Map& map) {
  return int(std::count_if(map.begin(), map.end(), [](std::uint16_t k) { return k != kernel::kLightEmpty; }));
}

TEST(LightPlot, EveryLightCountGivesTheMapsOfPlottingSampleBySample) {
  // Not a multiple of the chunk or of the eight samples projected at once: the last chunk is partial.
  const std::vector<kernel::v4f> points = lightSamplePoints(3 * kernel::LightPlot::kChunk + 37);
  const Map reference[3] = {plotOneByOne(0, points), plotOneByOne(1, points), plotOneByOne(2, points)};
  for (const Map& map : reference) {
    ASSERT_GT(filled(map), 200) << "the samples should cover a good part of every map";
    ASSERT_LT(filled(map), kSize * kSize) << "the sphere's disc leaves the map's corners empty";
  }
  for (const std::vector<int>& lights : std::vector<std::vector<int>>{{0}, {1}, {2}, {0, 1}, {2, 0}, {0, 1, 2}}) {
    const std::vector<Map> maps = plotChunked(lights, points);
    for (std::size_t l = 0; l < lights.size(); ++l)
      EXPECT_TRUE(maps[l] == reference[lights[l]]) << "light " << lights[l] << " of " << lights.size();
  }
}

TEST(LightPlot, TheMapsDoNotDependOnTheSampleOrderOrTheChunkBoundaries) {
  std::vector<kernel::v4f> points = lightSamplePoints(2000);
  const std::vector<Map> forward = plotChunked({0, 1, 2}, points);
  std::reverse(points.begin(), points.end());
  EXPECT_TRUE(plotChunked({0, 1, 2}, points) == forward);
  // Shifted by a few samples, every chunk holds other samples.
  std::rotate(points.begin(), points.begin() + 5, points.end());
  EXPECT_TRUE(plotChunked({0, 1, 2}, points) == forward);
}

TEST(LightPlot, EachSampleLandsOnItsLightViewTexelAndDepthStep) {
  // One sample at the centre of each of some texels, at a random depth, placed through the
  // inverse of LightView::project: the map must hold that depth's step at that texel.
  const std::vector<LightView> all = views();
  for (int l = 0; l < 3; ++l) {
    const LightView& view = all[std::size_t(l)];
    const double scale = 0.5 * kSize / view.bounds().radius, step = kernel::lightDepthStep(view);
    std::mt19937 rng(11 + l);
    std::uniform_int_distribution<int> texelOf(0, kSize * kSize - 1);
    std::uniform_real_distribution<double> depthOf(0.0, 2.0 * view.bounds().radius);
    std::vector<int> texels;
    std::vector<double> depths;
    std::vector<kernel::v4f> points;
    for (int i = 0; i < 300; ++i) {
      const int texel = texelOf(rng);
      if (std::find(texels.begin(), texels.end(), texel) != texels.end()) continue;
      const double u = texel % kSize + 0.5, v = texel / kSize + 0.5, depth = depthOf(rng);
      const glm::dvec3 p = view.bounds().center + view.right() * ((u - 0.5 * kSize) / scale) -
                           view.up() * ((v - 0.5 * kSize) / scale) + view.direction() * (view.bounds().radius - depth);
      texels.push_back(texel);
      depths.push_back(depth);
      points.push_back(kernel::v4f{float(p.x), float(p.y), float(p.z), 0.0f});
    }
    const Map map = plotChunked({l}, points)[0];
    EXPECT_EQ(filled(map), int(texels.size())) << "light " << l;
    for (std::size_t i = 0; i < texels.size(); ++i)
      EXPECT_NEAR(double(map[std::size_t(texels[i])]), std::floor(depths[i] / step), 1.0)
          << "light " << l << ", texel " << texels[i];
  }
}

}  // namespace
}  // namespace gridifs
