// The chaos game's loop for IFSs of bounded grid maps (render/chaos_kernel.h, runBoundedRounds)
// drops the per-sample checks that cannot fire there (escape, restart, skip, final function) and
// interleaves the z-buffer's writes with the next chunk's steps. Both must leave exactly the
// buffers, counters and chain state of the general loop (Gröller & Wegenkittl 1994, §3.1: the
// chaos game and its z-buffer; Draves & Reckase 2003, §5: colour sums in sample order).
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <vector>

#include "render/barycentric_kernel.h"
#include "render/camera.h"
#include "render/chaos_kernel.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "tests/core/renderer_scenes.h"
#include "tone/palette.h"

namespace gridifs {
namespace {

constexpr int kWidth = 160, kHeight = 120;

// Both of the camera's plotters take whole rounds, so the loop under test is the one they get.
static_assert(kernel::TakesWholeRounds<kernel::ZBufferPlot<false>>);
static_assert(kernel::TakesWholeRounds<kernel::ZBufferPlot<true>>);

struct Rendered {
  std::vector<kernel::PixelCell> cells = std::vector<kernel::PixelCell>(kWidth * kHeight);
  std::vector<std::uint64_t> sums = std::vector<std::uint64_t>(kWidth * kHeight * 4);
  kernel::ChainCounters counters;
  kernel::ChainState chain;
};

/// `batches` runs of runChain over one chain state, as a render thread's chunks call it.
template <bool kColor>
Rendered render(const kernel::HotIfs& ifs, const std::vector<std::int64_t>& batches, bool keys,
                const kernel::v4f* palette) {
  Camera c;
  c.yaw = 30.0;
  c.pitch = 20.0;
  c.distance = 3.0;
  const kernel::HotCamera cam = kernel::makeHotCamera(OrbitCamera(c, kWidth, kHeight));
  Rendered run;
  run.chain = kernel::ChainState::start(7, 1, ifs.skip);
  for (const std::int64_t count : batches) {
    auto plot = std::make_unique<kernel::ZBufferPlot<kColor>>(cam, run.cells.data(), run.sums.data(), palette);
    plot->keys = keys;
    kernel::runChain(run.chain, ifs, count, *plot, run.counters);
  }
  return run;
}

void expectSameRun(const Rendered& expected, const Rendered& actual) {
  EXPECT_EQ(expected.counters.samples, actual.counters.samples);
  EXPECT_EQ(expected.counters.plotted, actual.counters.plotted);
  EXPECT_EQ(expected.counters.bad, actual.counters.bad);
  int differing = 0;
  for (std::size_t p = 0; p < expected.cells.size(); ++p)
    differing += expected.cells[p].key != actual.cells[p].key || expected.cells[p].density != actual.cells[p].density;
  EXPECT_EQ(differing, 0) << "pixels whose key or hit count differ";
  EXPECT_EQ(std::memcmp(expected.sums.data(), actual.sums.data(), expected.sums.size() * sizeof(std::uint64_t)), 0);
  EXPECT_EQ(expected.chain.rng.state, actual.chain.rng.state);
  for (int l = 0; l < kernel::kLanes; ++l) {
    EXPECT_EQ(std::memcmp(&expected.chain.p[l], &actual.chain.p[l], sizeof(kernel::v4f)), 0) << "lane " << l;
    EXPECT_EQ(std::memcmp(&expected.chain.color[l], &actual.chain.color[l], sizeof(kernel::v4f)), 0) << "lane " << l;
  }
}

TEST(BoundedRounds, AGridIfsIsBoundedAndItsLoopLeavesTheGeneralLoopsBuffers) {
  const Project project = test::sierpinskiTetrahedron();
  const auto compiled = compileIfs(project);
  std::vector<kernel::HotFunction> hot;
  const kernel::HotIfs bounded = kernel::makeHotIfs(*compiled, hot, 20, limits::kEscapeBound);
  ASSERT_TRUE(bounded.boundedMaps);
  kernel::HotIfs general = bounded;
  general.boundedMaps = false;
  std::vector<kernel::v4f> palette;
  for (const Rgb& c : builtinPalette("ember").colors) palette.push_back(kernel::v4f{c.r, c.g, c.b, 0.0f});
  palette.push_back(palette.back());
  // Whole chunks, partial rounds, a batch shorter than the skip, batches that end mid-chunk.
  const std::vector<std::int64_t> batches = {100003, 17, 4096, 65536, 3, 251};
  for (bool keys : {true, false}) {
    SCOPED_TRACE(keys ? "with keys" : "hit counts only");
    expectSameRun(render<false>(general, batches, keys, nullptr), render<false>(bounded, batches, keys, nullptr));
    expectSameRun(render<true>(general, batches, keys, palette.data()),
                  render<true>(bounded, batches, keys, palette.data()));
  }
  const Rendered run = render<false>(bounded, batches, true, nullptr);
  EXPECT_GT(run.counters.plotted, run.counters.samples / 2) << "the attractor is in view";
}

TEST(BoundedRounds, MapsThatCanReachTheEscapeBoundAreNotBounded) {
  Project project = test::sierpinskiTetrahedron();
  std::vector<kernel::HotFunction> hot;
  // Nodes a quarter of the bound away: the blends stay inside it, so the loop may skip the check.
  project.functions[0].placement.translate = Vec3{0.25 * limits::kEscapeBound, 0.0, 0.0};
  EXPECT_TRUE(kernel::makeHotIfs(*compileIfs(project), hot, 20, limits::kEscapeBound).boundedMaps);
  // Beyond half of it they are not proven to stay inside.
  project.functions[0].placement.translate = Vec3{0.75 * limits::kEscapeBound, 0.0, 0.0};
  EXPECT_FALSE(kernel::makeHotIfs(*compileIfs(project), hot, 20, limits::kEscapeBound).boundedMaps);
  project.functions[0].placement.translate = Vec3{0.0, 0.0, 0.0};
  project.functions[0].variations = {{"spherical", 1.0}};
  EXPECT_FALSE(kernel::makeHotIfs(*compileIfs(project), hot, 20, limits::kEscapeBound).boundedMaps);
}

}  // namespace
}  // namespace gridifs
