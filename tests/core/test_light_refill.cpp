// Moving a shadowed light re-renders only what depends on it: the renderer keeps the camera's
// buffers and the other lights' buffers and replays the chaos game into the moved light's buffer
// alone, and the result is the render from scratch with the moved light, bit for bit.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "render/chaos_renderer.h"
#include "shading_scenes.h"

using namespace gridifs;
using namespace gridifs::test;

namespace {

/// A square floating above a larger one, lit by two shadowed lights.
Project twoLightScene(std::int64_t samples) {
  Project p = shadedBase(96, samples);
  addSquare(p, Vec3{0, 0, -0.5}, 1.0, 2, Vec3{0.9, 0.9, 0.9});
  addSquare(p, Vec3{0, 0, 0.5}, 0.4, 2, Vec3{0.9, 0.2, 0.2});
  separateSquares(p);
  p.render.shading.lights = {ShadingLight{Vec3{0, 0, 1}, Vec3{1.0}, 1.0, true},
                             ShadingLight{Vec3{-1, 0.2, 0.5}, Vec3{0.5, 0.6, 1.0}, 0.5, true}};
  return p;
}

RenderJob jobFor(const Project& p, const CompiledIfs& ifs) {
  return shadedRenderJob(RenderJob::fromProject(p, 2), p.render.shading, ifs);
}

void expectSameBuffers(const RenderImage& a, const RenderImage& b) {
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(a.rgba, b.rgba);
  EXPECT_EQ(a.density, b.density);
  ASSERT_EQ(a.lightDepth.size(), b.lightDepth.size());
  for (std::size_t l = 0; l < a.lightDepth.size(); ++l) EXPECT_EQ(a.lightDepth[l], b.lightDepth[l]) << "light " << l;
}

}  // namespace

TEST(LightRefill, MovingAShadowedLightKeepsTheCameraBuffersAndRefillsOnlyThatLight) {
  Project p = twoLightScene(400'000);
  const auto ifs = compileIfs(p);
  const DisplaySettings display = shadedDisplaySettings(p);
  ChaosRenderer renderer;
  renderer.restart(ifs, jobFor(p, *ifs));
  renderer.waitUntilDone();
  const RenderImage before = renderer.snapshot(display);
  EXPECT_FALSE(before.stats.keptCamera);

  p.render.shading.lights[0].direction = Vec3{0.6, 0, 1};
  const RenderJob moved = jobFor(p, *ifs);
  renderer.restart(ifs, moved);
  EXPECT_TRUE(renderer.stats().keptCamera);
  renderer.waitUntilDone();
  const RenderImage after = renderer.snapshot(display);
  EXPECT_TRUE(after.stats.done);
  EXPECT_EQ(after.stats.samples, 400'000) << "the camera's samples are counted once";

  // The camera's buffers are the same bytes, the other light's buffer too; the moved one changed.
  EXPECT_EQ(after.depth, before.depth);
  EXPECT_EQ(after.rgba, before.rgba);
  EXPECT_EQ(after.density, before.density);
  EXPECT_EQ(after.lightDepth[1], before.lightDepth[1]);
  EXPECT_NE(after.lightDepth[0], before.lightDepth[0]);
  EXPECT_FALSE(after.lightViews[0] == before.lightViews[0]);
  // And the whole is the render from scratch with the moved light.
  expectSameBuffers(after, renderToCompletion(ifs, moved, display));
}

TEST(LightRefill, ToggleShadowsAndMoveALightWhileTheRenderRuns) {
  Project p = twoLightScene(6'000'000);
  const auto ifs = compileIfs(p);
  const DisplaySettings display = shadedDisplaySettings(p);
  ChaosRenderer renderer;
  renderer.restart(ifs, jobFor(p, *ifs));
  // Change the lights part way through: the replay must bring each chain back to where it was and
  // go on from there exactly as an uninterrupted render would.
  auto waitFor = [&](std::int64_t samples) {
    while (renderer.stats().samples < samples && !renderer.stats().done)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
  };
  waitFor(300'000);
  p.render.shading.lights[1].shadows = false;  // one light buffer fewer: nothing to replay
  renderer.restart(ifs, jobFor(p, *ifs));
  EXPECT_TRUE(renderer.stats().keptCamera);
  waitFor(1'000'000);
  p.render.shading.lights[1].shadows = true;  // back: its buffer is filled again from the start
  p.render.shading.lights[0].direction = Vec3{-0.3, 0.4, 1};
  const RenderJob last = jobFor(p, *ifs);
  renderer.restart(ifs, last);
  EXPECT_TRUE(renderer.stats().keptCamera);
  renderer.waitUntilDone();
  expectSameBuffers(renderer.snapshot(display), renderToCompletion(ifs, last, display));
}

TEST(LightRefill, DepthOfFieldAndOtherRenderInputsStartOver) {
  Project p = twoLightScene(200'000);
  const auto ifs = compileIfs(p);
  ChaosRenderer renderer;
  renderer.restart(ifs, jobFor(p, *ifs));
  renderer.waitUntilDone();
  // Depth of field moves the camera's samples: the camera's buffers are rendered again.
  p.render.shading.dof = DepthOfFieldSettings{0.02, 4.0};
  renderer.restart(ifs, jobFor(p, *ifs));
  EXPECT_FALSE(renderer.stats().keptCamera);
  renderer.waitUntilDone();
  p.render.seed = 9;
  renderer.restart(ifs, jobFor(p, *ifs));
  EXPECT_FALSE(renderer.stats().keptCamera);
  renderer.waitUntilDone();
  // A new compilation of the same project is another IFS object: no assumption that it is equal.
  renderer.restart(compileIfs(p), jobFor(p, *ifs));
  EXPECT_FALSE(renderer.stats().keptCamera);
  renderer.waitUntilDone();
}
