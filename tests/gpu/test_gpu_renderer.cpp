// The GPU compute renderer against the CPU renderer (label `gpu`). CI machines have no GPU: these
// run on Mesa's llvmpipe through EGL surfaceless, so they need libegl-mesa0 and fail without it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/renderer_scenes.h"
#include "gpu/correlation.h"
#include "gpu/gpu_chaos_renderer.h"
#include "gpu/render_device.h"
#include "gpu_test_support.h"
#include "io/project_io.h"
#include "render/compiled_ifs.h"

namespace gridifs {
namespace {

using gpu::GpuChaosRenderer;

RenderImage renderGpu(GpuChaosRenderer& gpu, std::shared_ptr<const CompiledIfs> ifs, const RenderJob& job,
                      const DisplaySettings& display) {
  gpu.restart(std::move(ifs), job);
  EXPECT_TRUE(gpu.waitUntilDone());
  RenderImage image;
  gpu.snapshot(image, display);
  return image;
}

using test::correlation;

TEST(GpuRenderer, OpensAHeadlessContextWithCompute) {
  GpuChaosRenderer gpu;
  EXPECT_FALSE(gpu.info().renderer.empty());
  EXPECT_GE(gpu.info().maxStorageBlockBytes, 1 << 24);
  EXPECT_NE(std::string(gpu.deviceName()).find("gpu"), std::string::npos);
}

/// The GPU's image of `file` against the CPU's at 128 px wide from 2·10^6 samples: the same share
/// of plotted points, density and coverage correlated over blocks, the same hit pixels within 3 %.
/// `sparse`: a picture whose coverage is speckle at this budget, so coverage need only correlate
/// as well as the CPU's with another seed does (less 0.01), not 0.99.
/// Free-form IFSs run on the CPU only: the GPU renderer must say so instead of drawing something else.
void expectGpuMatchesCpu(GpuChaosRenderer& gpu, const std::filesystem::path& file, bool sparse = false) {
  SCOPED_TRACE(file.filename().string());
  const Project project = loadProject(file);
  if (project.space) {
    EXPECT_THROW(
        renderGpu(gpu, compileIfs(project), RenderJob::fromProject(project, 1), DisplaySettings::fromProject(project)),
        gpu::GpuUnavailable);
    return;
  }
  RenderJob job = RenderJob::fromProject(project, 2);
  job.width = 128;
  job.height = std::max(1, int(128.0 * project.render.height / project.render.width));
  job.samples = 2'000'000;
  const auto ifs = compileIfs(project);
  const DisplaySettings display = DisplaySettings::fromProject(project);
  const RenderImage cpu = renderToCompletion(ifs, job, display);
  const RenderImage g = renderGpu(gpu, ifs, job, display);
  EXPECT_EQ(g.stats.samples, job.samples);
  EXPECT_TRUE(g.stats.done);
  EXPECT_NEAR(double(g.stats.plotted) / double(job.samples), double(cpu.stats.plotted) / double(job.samples), 0.02);
  const double density = correlation(test::blockDensity(cpu), test::blockDensity(g));
  const double alpha = correlation(test::blockAlpha(cpu), test::blockAlpha(g));
  EXPECT_GE(density, 0.99);
  double alphaFloor = 0.99;
  if (sparse) {
    RenderJob other = job;
    other.seed += 1;
    const double cpuAlpha =
        correlation(test::blockAlpha(cpu), test::blockAlpha(renderToCompletion(ifs, other, display)));
    alphaFloor = std::min(alphaFloor, cpuAlpha - 0.01);
  }
  EXPECT_GE(alpha, alphaFloor);
  // In the XML report (--gtest_output=xml): the figures behind docs/RENDERER.md.
  ::testing::Test::RecordProperty(file.stem().string() + ".density_correlation", std::to_string(density));
  ::testing::Test::RecordProperty(file.stem().string() + ".alpha_correlation", std::to_string(alpha));
  EXPECT_NEAR(double(g.hitPixels), double(cpu.hitPixels), 0.03 * double(cpu.hitPixels) + 8);
}

std::vector<std::filesystem::path> projectsIn(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(folder))
    if (e.path().extension() == ".gridifs") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Every example, transition matrices included (the shader walks the same transition rows).
TEST(GpuRenderer, EveryExampleMatchesTheCpuImage) {
  const auto files = projectsIn(GRIDIFS_ASSETS);
  ASSERT_FALSE(files.empty());
  GpuChaosRenderer gpu;
  for (const auto& file : files) expectGpuMatchesCpu(gpu, file);
}

// IFS matrices with states (Thollot et al. §3): hidden, peek and skip-phase steps and restarts
// on the GPU as on the CPU, for the state examples and the results of every matrix operation.
TEST(GpuRenderer, StateMatrixExamplesMatchTheCpuImage) {
  const auto files = projectsIn(std::filesystem::path(GRIDIFS_ASSETS) / "matrices");
  ASSERT_GE(files.size(), 5u);
  GpuChaosRenderer gpu;
  for (const auto& file : files) {
    if (!loadProject(file).states) continue;
    expectGpuMatchesCpu(gpu, file, true);  // Cantor dusts: speckle at 2·10^6 samples
  }
}

TEST(GpuRenderer, SameSeedSameBytesOtherSeedOtherImage) {
  const Project p = loadProject(std::filesystem::path(GRIDIFS_ASSETS) / "twisted_functions.gridifs");
  RenderJob job = RenderJob::fromProject(p, 1);
  job.width = 96;
  job.height = 72;
  job.samples = 1'000'000;
  job.accumulateColor = true;
  const auto ifs = compileIfs(p);
  GpuChaosRenderer gpu;
  // Different slice lengths on the second run: the image must not depend on how work was sliced.
  GpuChaosRenderer::Options other;
  other.sliceSeconds = 0.0005;
  GpuChaosRenderer gpu2(other);
  const RenderImage a = renderGpu(gpu, ifs, job, DisplaySettings{});
  const RenderImage b = renderGpu(gpu2, ifs, job, DisplaySettings{});
  EXPECT_EQ(a.rgba, b.rgba);
  EXPECT_EQ(a.density, b.density);
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(a.colorSums, b.colorSums);
  job.seed += 1;
  const RenderImage c = renderGpu(gpu, ifs, job, DisplaySettings{});
  EXPECT_NE(a.density, c.density);
}

TEST(GpuRenderer, ZBufferKeepsTheNearestLayer) {
  const Project p = test::twoLayers();
  GpuChaosRenderer gpu;
  const RenderImage image =
      renderGpu(gpu, compileIfs(p), RenderJob::fromProject(p, 1), DisplaySettings::fromProject(p));
  const OrbitCamera cam(p.camera, image.width, image.height);
  int front = 0, back = 0;
  for (double y = -0.95; y <= 0.95; y += 0.05)
    for (double z = -0.95; z <= 0.95; z += 0.05) {
      const double m = std::max(std::abs(y), std::abs(z));
      const bool isFront = m<0.45, isBack = m> 0.55 && m < 0.95;
      if (!isFront && !isBack) continue;
      const ProjectedPoint q = cam.project({isFront ? 0.5 : -0.5, y, z});
      const std::size_t i = std::size_t(q.y) * image.width + std::size_t(q.x);
      const std::uint8_t* px = &image.rgba[i * 4];
      EXPECT_EQ(px[0], isFront ? 255 : 0);
      EXPECT_EQ(px[2], isFront ? 0 : 255);
      // 32-bit keys quantise depth to 1/65534 of the scene's depth range (here 1).
      EXPECT_NEAR(image.depth[i], isFront ? 3.5 : 4.5, gpu.exactDepth() ? 1e-4 : 1e-4 + 1.0 / 65534);
      EXPECT_EQ(px[3], 255);
      ++(isFront ? front : back);
    }
  EXPECT_GT(front, 50);
  EXPECT_GT(back, 50);
  EXPECT_EQ(gpu.exactDepth(), gpu.info().atomic64);
}

TEST(GpuRenderer, FlameColourSumsMatchTheCpu) {
  const Project p = loadProject(std::filesystem::path(GRIDIFS_ASSETS) / "sierpinski_tetrahedron.gridifs");
  RenderJob job = RenderJob::fromProject(p, 2);
  job.width = 96;
  job.height = 96;
  job.samples = 1'000'000;
  job.accumulateColor = true;
  job.palette = std::make_shared<const Palette>(resolvePalette("spectrum", GRIDIFS_ASSETS));
  const auto ifs = compileIfs(p);
  const RenderImage cpu = renderToCompletion(ifs, job, DisplaySettings{});
  GpuChaosRenderer gpu;
  const RenderImage g = renderGpu(gpu, ifs, job, DisplaySettings{});
  ASSERT_EQ(g.colorSums.size(), cpu.colorSums.size());
  double hitsCpu = 0, hitsGpu = 0;
  for (std::size_t i = 0; i < cpu.density.size(); ++i) hitsCpu += cpu.density[i], hitsGpu += g.density[i];
  for (int k = 0; k < 4; ++k) {
    double sc = 0, sg = 0;
    for (std::size_t i = 0; i < cpu.density.size(); ++i) sc += cpu.colorSums[i * 4 + k], sg += g.colorSums[i * 4 + k];
    SCOPED_TRACE(k);
    EXPECT_NEAR(sg / hitsGpu, sc / hitsCpu, 0.01);  // mean palette colour and mean c per hit
  }
}

TEST(GpuRenderer, RefusesAnImageLargerThanItsStorageBuffers) {
  GpuChaosRenderer gpu;
  const Project p = test::twoLayers();
  RenderJob job = RenderJob::fromProject(p, 1);
  job.width = job.height = 8192;
  job.accumulateColor = true;  // 32 bytes a pixel of colour sums: 2 GB
  if (gpu.info().maxStorageBlockBytes >= std::int64_t(8192) * 8192 * 32)
    GTEST_SKIP() << "this GPU's storage buffers hold a 2 GB image";
  try {
    gpu.restart(compileIfs(p), job);
    FAIL() << "expected GpuUnavailable";
  } catch (const gpu::GpuUnavailable& e) {
    EXPECT_NE(std::string(e.what()).find("8192×8192"), std::string::npos) << e.what();
  }
  // Auto falls back to the CPU renderer for the same job.
  gpu::RendererChoice choice;
  choice.renderer = std::make_unique<GpuChaosRenderer>();
  choice.gpu = true;
  job.width = job.height = 4096;
  job.samples = 1000;
  if (gpu.info().maxStorageBlockBytes >= std::int64_t(4096) * 4096 * 32) GTEST_SKIP();
  gpu::restartOrFallBack(choice, gpu::RenderDevice::Auto, compileIfs(p), job);
  EXPECT_FALSE(choice.gpu);
  EXPECT_FALSE(choice.fallbackReason.empty());
  EXPECT_TRUE(choice.renderer->waitUntilDone());
}

TEST(GpuRenderer, ExportPointsWalkIsDeterministicAndInsideTheAttractorBox) {
  const Project p = test::twoLayers();
  RenderJob job = RenderJob::fromProject(p, 1);
  job.samples = 200'000;
  const auto ifs = compileIfs(p);
  auto collect = [&] {
    std::vector<float> all;
    const RenderStats s = gpu::generatePointsGpu(*ifs, job, [&](const PointBatch& b, const RenderStats&) {
      all.insert(all.end(), b.xyz, b.xyz + 3 * b.count);
      return true;
    });
    EXPECT_EQ(s.samples, job.samples);
    EXPECT_EQ(std::int64_t(all.size() / 3), s.plotted);
    return all;
  };
  const std::vector<float> a = collect(), b = collect();
  EXPECT_EQ(a, b);
  ASSERT_GT(a.size(), 3u * 150'000);
  for (std::size_t i = 0; i < a.size(); i += 3) ASSERT_NEAR(std::abs(a[i]), 0.5f, 1e-5f);
}

}  // namespace
}  // namespace gridifs
