// The flame display over the chaos game: per-sample palette colors in the renderer's
// sums, exposure from the camera, developing a snapshot (written to files: files/).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "render/compiled_ifs.h"
#include "render/flame_render.h"
#include "tests/core/flame_scenes.h"

using namespace gridifs;

using test_support::sierpinskiFlame;

TEST(FlameRender, PixelsPerUnitFollowTheOrbitCamera) {
  Camera c;
  c.distance = 4.0;
  c.fov = 35.0;
  EXPECT_NEAR(flamePixelsPerUnit(c, 768), 768.0 / (2.0 * 4.0 * std::tan(17.5 * M_PI / 180.0)), 1e-9);
}

TEST(FlameRender, RendererSumsThePaletteColorOfEverySample) {
  const Project p = sierpinskiFlame(64);
  auto palette = std::make_shared<Palette>();
  for (int i = 0; i < 256; ++i) palette->colors[i] = {0.2f, 0.4f, i < 128 ? 0.6f : 1.0f};
  const RenderJob job = flameRenderJob(p, palette, 2);
  EXPECT_TRUE(job.accumulateColor);
  const int g = flameGutter(p.render.flame), side = 64 + 2 * g;  // the job covers a gutter too
  ASSERT_EQ(job.width, side);
  const RenderImage snap = renderToCompletion(compileIfs(p), job, DisplaySettings::fromProject(p));
  ASSERT_EQ(snap.colorSums.size(), std::size_t(side * side * 4));
  std::int64_t hits = 0;
  for (std::size_t i = 0; i < std::size_t(side * side); ++i) {
    const double n = snap.density[i];
    hits += snap.density[i];
    EXPECT_NEAR(snap.colorSums[i * 4 + 0], 0.2 * n, 1e-3 * n + 1e-4);
    EXPECT_NEAR(snap.colorSums[i * 4 + 1], 0.4 * n, 1e-3 * n + 1e-4);
    EXPECT_GE(snap.colorSums[i * 4 + 2], 0.6 * n - 1e-3 * n - 1e-4);
    EXPECT_LE(snap.colorSums[i * 4 + 2], 1.0 * n + 1e-3 * n + 1e-4);
  }
  EXPECT_GT(hits, 100000);
  // Structural coloring: the bottom-left corner (function 0, c → 0) takes the palette's first
  // half, the top corner (function 2, c → 1) its second half.
  auto meanBlue = [&](int x, int y) {
    double b = 0, n = 0;
    for (int j = y - 2 + g; j <= y + 2 + g; ++j)
      for (int i = x - 2 + g; i <= x + 2 + g; ++i) {
        b += snap.colorSums[(std::size_t(j) * side + i) * 4 + 2];
        n += snap.density[std::size_t(j) * side + i];
      }
    return n > 0 ? b / n : -1.0;
  };
  EXPECT_NEAR(meanBlue(20, 44), 0.6, 0.1);  // y down: bottom-left
  EXPECT_NEAR(meanBlue(32, 20), 1.0, 0.1);  // top
}
