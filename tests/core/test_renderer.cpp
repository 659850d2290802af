// The stochastic renderer: attractor correctness, determinism, restarts, z-test.
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <set>
#include <thread>

#include "model/stack_evaluator.h"
#include "render/accumulation.h"
#include "render/camera.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "tests/core/renderer_scenes.h"

namespace gridifs {
namespace {

std::vector<Vec3> exportPoints(const Project& project, std::int64_t samples, int threads, std::uint64_t seed = 1) {
  RenderJob job = RenderJob::fromProject(project, threads);
  job.samples = samples;
  job.seed = seed;
  std::vector<Vec3> points;
  generatePoints(*compileIfs(project), job, [&](const PointBatch& batch, const RenderStats&) {
    for (std::size_t i = 0; i < batch.count; ++i)
      points.emplace_back(batch.xyz[3 * i], batch.xyz[3 * i + 1], batch.xyz[3 * i + 2]);
    return true;
  });
  return points;
}

void expectSierpinski(const std::vector<Vec3>& points) {
  ASSERT_GT(points.size(), 100'000u);
  std::set<int> addresses;
  std::size_t outside = 0;
  for (const Vec3& p : points) {
    if (!test::inSierpinski(p, 7, 1e-3)) ++outside;
    addresses.insert(test::sierpinskiAddress(p, 5, 1e-3));
  }
  EXPECT_EQ(outside, 0u) << "points off the level-7 Sierpinski tetrahedron";
  addresses.erase(-1);
  EXPECT_EQ(addresses.size(), 1024u) << "every level-5 sub-tetrahedron is hit";
}

using test::waitUntil;

TEST(CompiledIfs, MatchesGridEvaluation) {
  Project p = test::sierpinskiTetrahedron();
  p.functions[0].resolution = {5, 4, 3};
  TwistOp twist;
  twist.axis = Axis::Z;
  twist.k = 1.1;
  Operation op;
  op.params = twist;
  p.functions[0].ops.push_back(op);
  const auto ifs = compileIfs(p);
  const Grid grid = evaluateFunction(p.functions[0]);
  for (double x = -1.2; x <= 1.2; x += 0.173)
    for (double y = -1.1; y <= 1.1; y += 0.21)
      for (double z = -1.0; z <= 1.0; z += 0.33) {
        const Vec3 expected = grid.evaluate({x, y, z});
        const auto got = ifs->functions[0].evaluate({float(x), float(y), float(z)});
        for (int d = 0; d < 3; ++d) EXPECT_NEAR(got[d], expected[d], 1e-5);
      }
}

TEST(CompiledIfs, AliasTableFollowsWeights) {
  const std::vector<double> weights = {1, 3, 0, 4};
  const auto table = buildAliasTable(weights);
  CompiledIfs ifs;
  ifs.alias = table;
  std::vector<double> counts(4, 0.0);
  std::uint64_t x = 12345;
  const int n = 400'000;
  for (int i = 0; i < n; ++i) {
    x = x * 6364136223846793005ull + 1442695040888963407ull;
    counts[ifs.choose(x ^ (x >> 29))] += 1.0;
  }
  EXPECT_EQ(counts[2], 0.0);
  EXPECT_NEAR(counts[0] / n, 1.0 / 8, 0.01);
  EXPECT_NEAR(counts[1] / n, 3.0 / 8, 0.01);
  EXPECT_NEAR(counts[3] / n, 4.0 / 8, 0.01);
  EXPECT_THROW(buildAliasTable({0.0, 0.0}), ModelError);
}

TEST(CompiledIfs, MutedAndZeroWeightFunctionsAreLeftOut) {
  Project p = test::sierpinskiTetrahedron();
  p.functions[1].muted = true;
  p.functions[2].weight = 0.0;
  const auto ifs = compileIfs(p);
  ASSERT_EQ(ifs->functions.size(), 2u);
  EXPECT_EQ(ifs->functions[0].sourceIndex, 0u);
  EXPECT_EQ(ifs->functions[1].sourceIndex, 3u);
  for (auto& f : p.functions) f.muted = true;
  EXPECT_THROW(compileIfs(p), ModelError);
}

TEST(Camera, ProjectsTargetToCentreAndMatchesPixelRows) {
  Camera c;
  c.yaw = 40;
  c.pitch = 25;
  c.distance = 5;
  c.target = {0.1, -0.2, 0.3};
  for (bool ortho : {false, true}) {
    c.projection = ortho ? CameraProjection::Orthographic : CameraProjection::Perspective;
    const OrbitCamera cam(c, 200, 100);
    const ProjectedPoint centre = cam.project(c.target);
    EXPECT_NEAR(centre.x, 100.0, 1e-9);
    EXPECT_NEAR(centre.y, 50.0, 1e-9);
    EXPECT_NEAR(centre.depth, 5.0, 1e-9);
    // +z is up: a point above the target appears higher in the image (smaller y).
    EXPECT_LT(cam.project(c.target + Vec3{0, 0, 0.5}).y, 50.0);
    const auto rows = cam.pixelRows();
    const Vec3 q{0.3, 0.7, -0.4};
    const ProjectedPoint pp = cam.project(q);
    auto dot = [&](const float* r) { return r[0] * q.x + r[1] * q.y + r[2] * q.z + r[3]; };
    EXPECT_NEAR(dot(rows.rowX) / dot(rows.rowW), pp.x, 1e-3);
    EXPECT_NEAR(dot(rows.rowY) / dot(rows.rowW), pp.y, 1e-3);
    EXPECT_NEAR(dot(rows.rowD), pp.depth, 1e-5);
  }
  // yaw 0, pitch 0: the eye is on +x.
  Camera side;
  side.yaw = 0;
  side.pitch = 0;
  side.distance = 3;
  const glm::dvec3 eye = orbitEye(side);
  EXPECT_NEAR(eye.x, 3.0, 1e-12);
  EXPECT_NEAR(eye.y, 0.0, 1e-12);
  EXPECT_NEAR(eye.z, 0.0, 1e-12);
}

TEST(Renderer, SierpinskiPointsLieOnTheAttractorAndCoverIt) {
  expectSierpinski(exportPoints(test::sierpinskiTetrahedron(), 300'000, 1));
}

TEST(Renderer, EveryThreadCountProducesTheAttractor) {
  const Project p = test::sierpinskiTetrahedron();
  for (int threads = 1; threads <= 4; ++threads) {
    SCOPED_TRACE(threads);
    expectSierpinski(exportPoints(p, 300'000, threads));
    RenderJob job = RenderJob::fromProject(p, threads);
    const RenderImage image = renderToCompletion(compileIfs(p), job, DisplaySettings::fromProject(p));
    EXPECT_EQ(image.stats.samples, job.samples);
    EXPECT_EQ(image.stats.badSamples, 0);
    EXPECT_GT(image.hitPixels, 1000);
    // Every plotted pixel is the projection of some attractor point: check the depth range.
    EXPECT_GT(image.minDepth, 4.5 - std::sqrt(3.0) - 1e-3);
    EXPECT_LT(image.maxDepth, 4.5 + std::sqrt(3.0) + 1e-3);
  }
}

TEST(Renderer, SameSeedGivesIdenticalBytesOtherSeedDiffers) {
  const Project p = test::sierpinskiTetrahedron();
  const auto ifs = compileIfs(p);
  RenderJob job = RenderJob::fromProject(p, 2);
  job.accumulateColor = true;
  const DisplaySettings display = DisplaySettings::fromProject(p);
  const RenderImage a = renderToCompletion(ifs, job, display);
  const RenderImage b = renderToCompletion(ifs, job, display);
  EXPECT_EQ(a.rgba, b.rgba);
  EXPECT_EQ(a.density, b.density);
  EXPECT_EQ(a.colorSums, b.colorSums);
  EXPECT_TRUE(std::equal(a.depth.begin(), a.depth.end(), b.depth.begin(),
                         [](float x, float y) { return std::memcmp(&x, &y, 4) == 0; }));
  job.seed = 2;
  const RenderImage c = renderToCompletion(ifs, job, display);
  EXPECT_NE(a.density, c.density);
  EXPECT_EQ(exportPoints(p, 50'000, 2, 7), exportPoints(p, 50'000, 2, 7));
  EXPECT_NE(exportPoints(p, 50'000, 2, 7), exportPoints(p, 50'000, 2, 8));
}

TEST(Renderer, TakingTheAccumulationGivesTheSameSumsAndLeavesTheGiverOut) {
  const Project p = test::sierpinskiTetrahedron();
  const auto ifs = compileIfs(p);
  for (int threads : {1, 2, 3}) {
    SCOPED_TRACE(threads);
    RenderJob job = RenderJob::fromProject(p, threads);
    job.accumulateColor = true;
    job.samples = 400'000;
    ChaosRenderer renderer;
    renderer.restart(ifs, job);
    ASSERT_TRUE(renderer.waitUntilDone());
    Accumulation copied, taken;
    renderer.accumulation(copied);
    renderer.takeAccumulation(taken);
    EXPECT_EQ(taken.colorSums, copied.colorSums);
    EXPECT_EQ(taken.density, copied.density);
    EXPECT_EQ(taken.samples, copied.samples);
    EXPECT_EQ(taken.samples, job.samples);
    // The giver's sums left with `taken`: a later read leaves that worker out instead of reading
    // an empty buffer, so with one thread nothing is left.
    Accumulation after;
    renderer.accumulation(after);
    EXPECT_LT(after.samples, taken.samples);
    if (threads == 1) {
      EXPECT_EQ(after.samples, 0);
    }
    ASSERT_EQ(after.colorSums.size(), taken.colorSums.size());
    // And the renderer starts over as before.
    renderer.restart(ifs, job);
    ASSERT_TRUE(renderer.waitUntilDone());
    Accumulation again;
    renderer.takeAccumulation(again);
    EXPECT_EQ(again.colorSums, copied.colorSums);
  }
}

TEST(Renderer, ZTestKeepsTheNearestPoint) {
  const Project p = test::twoLayers();
  const RenderImage image =
      renderToCompletion(compileIfs(p), RenderJob::fromProject(p, 2), DisplaySettings::fromProject(p));
  const OrbitCamera cam(p.camera, image.width, image.height);
  int checkedFront = 0, checkedBack = 0;
  for (double y = -0.95; y <= 0.95; y += 0.05)
    for (double z = -0.95; z <= 0.95; z += 0.05) {
      const double m = std::max(std::abs(y), std::abs(z));
      const bool front = m<0.45, back = m> 0.55 && m < 0.95;
      if (!front && !back) continue;
      const ProjectedPoint q = cam.project({front ? 0.5 : -0.5, y, z});
      const std::size_t i = std::size_t(q.y) * image.width + std::size_t(q.x);
      const std::uint8_t* px = &image.rgba[i * 4];
      if (front) {
        EXPECT_EQ(px[0], 255);
        EXPECT_EQ(px[2], 0);
        EXPECT_NEAR(image.depth[i], 3.5, 1e-4);
        ++checkedFront;
      } else {
        EXPECT_EQ(px[0], 0);
        EXPECT_EQ(px[2], 255);
        EXPECT_NEAR(image.depth[i], 4.5, 1e-4);
        ++checkedBack;
      }
      EXPECT_EQ(px[3], 255);
    }
  EXPECT_GT(checkedFront, 200);
  EXPECT_GT(checkedBack, 200);
  // Depth cueing darkens the far layer only.
  Project cued = p;
  cued.render.depth_cue = 0.5;
  const RenderImage dim =
      renderToCompletion(compileIfs(cued), RenderJob::fromProject(cued, 1), DisplaySettings::fromProject(cued));
  const ProjectedPoint far = cam.project({-0.5, 0.8, 0.8}), nearPt = cam.project({0.5, 0.0, 0.0});
  EXPECT_EQ(dim.rgba[(std::size_t(nearPt.y) * dim.width + std::size_t(nearPt.x)) * 4 + 0], 255);
  EXPECT_NEAR(dim.rgba[(std::size_t(far.y) * dim.width + std::size_t(far.x)) * 4 + 2], 128, 1);
}

TEST(Renderer, RestartNeverShowsOldGenerationPoints) {
  // Scene A sits left of the frame centre, scene B right of it; no image of B may contain a
  // pixel left of the centre.
  Project a = test::sierpinskiTetrahedron();
  a.camera.yaw = 0;
  a.camera.pitch = 0;
  a.camera.distance = 6;
  a.camera.projection = CameraProjection::Orthographic;
  Project b = a;
  for (auto& f : a.functions) {
    f.placement.scale *= 0.5;
    f.placement.translate = 0.5 * f.placement.translate + Vec3{0, -0.6, 0};  // screen x = world y
  }
  for (auto& f : b.functions) {
    f.placement.scale *= 0.5;
    f.placement.translate = 0.5 * f.placement.translate + Vec3{0, 0.6, 0};
  }
  RenderJob job = RenderJob::fromProject(a, 2);
  job.samples = 0;  // unlimited
  ChaosRenderer renderer;
  const auto ifsA = compileIfs(a), ifsB = compileIfs(b);
  RenderImage image;
  for (int round = 0; round < 20; ++round) {
    renderer.restart(ifsA, job);
    // Generation A has plotted points before B replaces it, so a leak would show.
    ASSERT_TRUE(waitUntil([&] { return renderer.stats().samples > 0; })) << "round " << round;
    const std::uint64_t generation = renderer.restart(ifsB, job);
    for (int s = 0; s < 5; ++s) {
      renderer.snapshot(image, DisplaySettings{});
      ASSERT_EQ(image.generation, generation);
      for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width / 2; ++x)
          ASSERT_EQ(image.density[std::size_t(y) * image.width + x], 0u) << "round " << round << " snapshot " << s;
    }
  }
  EXPECT_TRUE(waitUntil([&] {
    renderer.snapshot(image, DisplaySettings{});
    return image.hitPixels > 20;
  }));
  EXPECT_FALSE(image.stats.done);
  renderer.stop();
}

TEST(Renderer, PauseResumeAndBudget) {
  const Project p = test::sierpinskiTetrahedron();
  ChaosRenderer renderer;
  RenderJob job = RenderJob::fromProject(p, 2);
  job.samples = 3'000'001;
  renderer.restart(compileIfs(p), job);
  renderer.pause();
  const std::int64_t atPause = renderer.stats().samples;
  // Asserting that nothing happens needs time to pass: a fixed pause, not a wait on a condition.
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const std::int64_t later = renderer.stats().samples;
  EXPECT_LE(later - atPause, 2 * 8192) << "at most one batch per worker after pause()";
  EXPECT_TRUE(renderer.stats().paused);
  renderer.resume();
  EXPECT_TRUE(renderer.waitUntilDone());
  const RenderStats s = renderer.stats();
  EXPECT_TRUE(s.done);
  EXPECT_EQ(s.samples, 3'000'001);
  EXPECT_GT(s.pointsPerSecond, 0.0);
}

TEST(Renderer, RejectsUnusableJobs) {
  const Project p = test::sierpinskiTetrahedron();
  RenderJob job = RenderJob::fromProject(p, 1);
  job.width = 0;
  EXPECT_THROW(validateRenderJob(job), ModelError);
  job.width = job.height = 16384;
  EXPECT_THROW(validateRenderJob(job), ModelError);
  job.width = job.height = 100;
  job.samples = 1'000'000'000'000;
  EXPECT_THROW(validateRenderJob(job), ModelError);
  job.samples = 0;
  EXPECT_THROW(renderToCompletion(compileIfs(p), job, {}), ModelError);
  ChaosRenderer renderer;
  EXPECT_THROW(renderer.restart(nullptr, RenderJob::fromProject(p, 1)), ModelError);
}

TEST(Renderer, FinalFunctionAppliesOutsideTheLoop) {
  // Final function: shift by +0.25 in x (placement). The loop itself stays the tetrahedron.
  Project p = test::sierpinskiTetrahedron();
  Function final;
  final.resolution = {2, 2, 2};
  final.placement.translate = {0.25, 0, 0};
  p.final_function = final;
  const auto points = exportPoints(p, 100'000, 1);
  for (std::size_t i = 0; i < points.size(); i += 97)
    ASSERT_TRUE(test::inSierpinski(points[i] - Vec3{0.25, 0, 0}, 6, 1e-3)) << i;
}

TEST(Renderer, NonContractiveAndSingleFunctionIfsGiveFiniteImages) {
  Project p = test::sierpinskiTetrahedron();
  p.functions.resize(1);
  p.functions[0].placement.scale = Vec3{3.0};  // expands; clamping keeps the chain bounded
  const RenderImage image =
      renderToCompletion(compileIfs(p), RenderJob::fromProject(p, 2), DisplaySettings::fromProject(p));
  EXPECT_EQ(image.stats.samples, p.render.samples);
  // Sixty-four functions.
  Project many = test::sierpinskiTetrahedron();
  while (many.functions.size() < 64) many.functions.push_back(many.functions[many.functions.size() % 4]);
  expectSierpinski(exportPoints(many, 300'000, 2));
}

}  // namespace
}  // namespace gridifs
