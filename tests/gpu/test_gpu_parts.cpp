// Render parts on the GPU (label `gpu`): part K of N plays its share of the whole job's chains,
// each seeded and budgeted as in the whole render, so the N parts' accumulations sum to the whole
// render's bit for bit — with the 32-bit keys (llvmpipe, or forced) as with 64-bit ones — and
// `render --part` + `merge` write the bytes `render` writes. Like the other GPU tests these run on
// Mesa's llvmpipe through EGL where there is no GPU, and fail without a context.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/run_command.h"
#include "gpu/chaos_compute.h"
#include "gpu/gpu_chaos_renderer.h"
#include "gpu/render_device.h"
#include "io/project_io.h"
#include "io/render_part_file.h"
#include "render/accumulation.h"
#include "render/compiled_ifs.h"
#include "tone/palette.h"

namespace gridifs {
namespace {

using gpu::GpuChaosRenderer;
namespace fs = std::filesystem;

Accumulation accumulate(GpuChaosRenderer& gpu, std::shared_ptr<const CompiledIfs> ifs, const RenderJob& job) {
  gpu.restart(std::move(ifs), job);
  EXPECT_TRUE(gpu.waitUntilDone());
  Accumulation acc;
  gpu.accumulation(acc);
  return acc;
}

void expectSameAccumulation(const Accumulation& a, const Accumulation& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.keys, b.keys);
  EXPECT_EQ(a.keys32, b.keys32);
  EXPECT_EQ(a.depthMin, b.depthMin);
  EXPECT_EQ(a.depthScale, b.depthScale);
  EXPECT_EQ(a.density, b.density);
  EXPECT_EQ(a.colorSums, b.colorSums);
  EXPECT_EQ(a.samples, b.samples);
  EXPECT_EQ(a.badSamples, b.badSamples);
  EXPECT_EQ(a.plotted, b.plotted);
}

/// A job with depth to quantise (two functions that twist the box) and, in flame mode, palette
/// colour sums.
RenderJob testJob(const Project& p, bool flame) {
  RenderJob job = RenderJob::fromProject(p, 1);
  job.width = 96;
  job.height = 72;
  job.samples = 600'000;  // 384 chains at skip 20: parts of 192, 128 and 76/77 chains
  job.accumulateColor = flame;
  if (flame) job.palette = std::make_shared<const Palette>(resolvePalette("spectrum", GRIDIFS_ASSETS));
  return job;
}

void checkPartsSumToTheWhole(GpuChaosRenderer& gpu, bool flame) {
  const Project p = loadProject(fs::path(GRIDIFS_ASSETS) / "twisted_functions.gridifs");
  const auto ifs = compileIfs(p);
  const RenderJob job = testJob(p, flame);
  ASSERT_EQ(gpu::chainCount(job, false), 384u);
  const Accumulation whole = accumulate(gpu, ifs, job);
  ASSERT_EQ(whole.samples, job.samples);
  ASSERT_GT(whole.plotted, job.samples / 2);
  if (!gpu.exactDepth()) {
    ASSERT_FALSE(whole.keys32.empty());
    ASSERT_GT(whole.depthScale, 0.0f);
  }
  EXPECT_EQ(whole.colorSums.empty(), !flame);
  for (const std::int64_t n : {1, 2, 3, 5}) {
    SCOPED_TRACE("N = " + std::to_string(n));
    Accumulation sum;
    for (std::int64_t k = 0; k < n; ++k) {
      RenderJob part = job;
      part.part = RenderPart{k, n};
      const Accumulation a = accumulate(gpu, ifs, part);
      // The 32-bit keys' depth step depends on the IFS and the camera only: every part's keys
      // mean the same depths.
      EXPECT_EQ(a.depthMin, whole.depthMin);
      EXPECT_EQ(a.depthScale, whole.depthScale);
      EXPECT_EQ(gpu.stats().budget, a.samples);
      if (n > 1) {
        EXPECT_GT(a.samples, 0);
        EXPECT_LT(a.samples, job.samples);
      }
      if (k == 0)
        sum = a;
      else
        sum.add(a);
    }
    expectSameAccumulation(sum, whole);
  }
}

TEST(GpuParts, ZBufferPartsSumToTheWholeRender) {
  GpuChaosRenderer gpu;
  checkPartsSumToTheWhole(gpu, false);
}

TEST(GpuParts, FlamePartsSumToTheWholeRender) {
  GpuChaosRenderer gpu;
  checkPartsSumToTheWhole(gpu, true);
}

TEST(GpuParts, PartsSumToTheWholeWithForced32BitKeys) {
  GpuChaosRenderer::Options options;
  options.allowAtomic64 = false;
  GpuChaosRenderer gpu(options);
  for (const bool flame : {false, true}) {
    SCOPED_TRACE(flame ? "flame" : "zbuffer");
    checkPartsSumToTheWhole(gpu, flame);
    EXPECT_FALSE(gpu.exactDepth());
  }
}

TEST(GpuParts, MorePartsThanChainsLeavesSomeEmpty) {
  // 64 chains (the least a job has) in 100 parts: 36 parts have no chain, finish at once with
  // an empty accumulation, and the parts still sum to the whole.
  const Project p = loadProject(fs::path(GRIDIFS_ASSETS) / "twisted_functions.gridifs");
  const auto ifs = compileIfs(p);
  RenderJob job = testJob(p, true);
  job.width = 32;
  job.height = 24;
  job.samples = 50'000;
  ASSERT_EQ(gpu::chainCount(job, false), 64u);
  GpuChaosRenderer gpu;
  const Accumulation whole = accumulate(gpu, ifs, job);
  Accumulation sum;
  int empty = 0;
  for (std::int64_t k = 0; k < 100; ++k) {
    RenderJob part = job;
    part.part = RenderPart{k, 100};
    const Accumulation a = accumulate(gpu, ifs, part);
    if (a.samples == 0) {
      ++empty;
      EXPECT_TRUE(gpu.stats().done);
      EXPECT_EQ(a.plotted, 0);
    }
    if (k == 0)
      sum = a;
    else
      sum.add(a);
  }
  EXPECT_EQ(empty, 36);
  expectSameAccumulation(sum, whole);
}

TEST(GpuParts, AutoKeepsAPartOnTheGpu) {
  const Project p = loadProject(fs::path(GRIDIFS_ASSETS) / "twisted_functions.gridifs");
  RenderJob job = testJob(p, false);
  job.part = RenderPart{1, 3};
  gpu::RendererChoice choice;
  choice.renderer = std::make_unique<GpuChaosRenderer>();
  choice.gpu = true;
  gpu::restartOrFallBack(choice, gpu::RenderDevice::Auto, compileIfs(p), job);
  EXPECT_TRUE(choice.gpu);
  EXPECT_TRUE(choice.fallbackReason.empty()) << choice.fallbackReason;
  EXPECT_TRUE(choice.renderer->waitUntilDone());
}

// The command line: `render --device gpu` against `render --device gpu --part K/N` + `merge`.

using test_support::CommandResult;
using test_support::quote;
using test_support::runGridifs;
using test_support::ScratchDir;
using test_support::slurp;

std::string example() { return quote(std::string(GRIDIFS_ASSETS) + "/twisted_functions.gridifs"); }

TEST(GpuPartsCli, MergedGpuPartsAreTheWholeRendersBytes) {
  ScratchDir dir("gpu-parts-cli");
  const std::string common = " --width 80 --height 60 --samples 400000 --device gpu";
  for (const char* mode : {"zbuffer", "flame"}) {
    SCOPED_TRACE(mode);
    const std::string args = common + " --mode " + mode;
    const fs::path whole = dir.path / (std::string(mode) + "-whole.png");
    const CommandResult r = runGridifs("render " + example() + " -o " + quote(whole.string()) + args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const int n : {2, 3, 5}) {
      SCOPED_TRACE("N = " + std::to_string(n));
      std::string parts;
      std::int64_t next = 0;  // the parts' chain ranges follow each other
      for (int k = 0; k < n; ++k) {
        const fs::path part =
            dir.path / (std::string(mode) + "-" + std::to_string(k) + "of" + std::to_string(n) + ".gpart");
        const CommandResult p = runGridifs("render " + example() + " -o " + quote(part.string()) + args + " --part " +
                                           std::to_string(k) + "/" + std::to_string(n));
        ASSERT_EQ(p.exitCode, 0) << p.err;
        EXPECT_EQ(p.err, "");  // no note: the GPU was asked for and rendered the part
        // The header names the GPU and the chains the part played (400000 samples at skip 20:
        // 256 chains), not CPU chunks.
        const RenderPartHeader h = RenderPartReader(part).header();
        EXPECT_EQ(h.device.rfind("gpu (", 0), 0u) << h.device;
        EXPECT_EQ(h.chunkBegin, next);
        next = h.chunkEnd;
        parts = quote(part.string()) + " " + parts;  // in reverse order: merge takes any order
      }
      EXPECT_EQ(next, 256);
      const fs::path merged = dir.path / (std::string(mode) + "-merged" + std::to_string(n) + ".png");
      const CommandResult m = runGridifs("merge " + parts + "-o " + quote(merged.string()));
      ASSERT_EQ(m.exitCode, 0) << m.err;
      EXPECT_TRUE(slurp(merged) == slurp(whole)) << merged << " differs from " << whole;
    }
  }
}

TEST(GpuPartsCli, MergeRefusesPartsFromAnotherDevice) {
  ScratchDir dir("gpu-parts-device");
  const std::string args = " --width 40 --height 30 --samples 200000";
  const fs::path gpuPart = dir.path / "p0.gpart", cpuPart = dir.path / "p1.gpart", out = dir.path / "out.png";
  ASSERT_EQ(
      runGridifs("render " + example() + " -o " + quote(gpuPart.string()) + args + " --device gpu --part 0/2").exitCode,
      0);
  ASSERT_EQ(
      runGridifs("render " + example() + " -o " + quote(cpuPart.string()) + args + " --device cpu --part 1/2").exitCode,
      0);
  const CommandResult m =
      runGridifs("merge " + quote(gpuPart.string()) + " " + quote(cpuPart.string()) + " -o " + quote(out.string()));
  EXPECT_EQ(m.exitCode, 2) << m.err;
  EXPECT_NE(m.err.find("p0.gpart was rendered on gpu ("), std::string::npos) << m.err;
  EXPECT_NE(m.err.find("p1.gpart on cpu"), std::string::npos) << m.err;
  EXPECT_NE(m.err.find("all parts of a render must come from one device"), std::string::npos) << m.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace gridifs
