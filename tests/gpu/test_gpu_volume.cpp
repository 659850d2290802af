// The density volume's chaos game on the GPU (voxel binning in the compute shader) against the
// CPU workers' binning: the same measure up to sampling noise, deterministic for a seed, and a
// clear refusal for what the shader does not run. On CI this is Mesa's llvmpipe.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "gpu/correlation.h"
#include "gpu/render_device.h"
#include "gpu_test_support.h"
#include "io/project_io.h"
#include "volume/measure_attractor.h"

namespace gridifs {
namespace {

using test::correlation;

/// Sums over 2×2×2 blocks: single voxels at test sample counts are mostly sampling noise.
std::vector<float> blocks(const std::vector<float>& v, int n, int channels = 1, int channel = 0) {
  const int m = n / 2;
  std::vector<float> out(std::size_t(m) * m * m, 0.0f);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        out[std::size_t(i / 2) + std::size_t(m) * (std::size_t(j / 2) + std::size_t(m) * std::size_t(k / 2))] +=
            v[(std::size_t(i) + std::size_t(n) * (std::size_t(j) + std::size_t(n) * std::size_t(k))) * channels +
              channel];
  return out;
}

VolumeSettings testSettings() {
  VolumeSettings s;
  s.resolution = 32;
  s.samples = 2'000'000;
  return s;
}

TEST(GpuVolume, EveryGridExampleMatchesTheCpuVolume) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(GRIDIFS_ASSETS))
    if (e.path().extension() == ".gridifs") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  int compared = 0;
  for (const auto& file : files) {
    const Project project = loadProject(file);
    if (project.space || !project.transitions.empty() || usesSetIteration(project)) continue;
    SCOPED_TRACE(file.filename().string());
    VolumeJob cpuJob;
    cpuJob.settings = testSettings();
    cpuJob.threads = 2;
    const DensityVolume cpu = computeDensityVolume(project, cpuJob);
    const DensityVolume g = computeDensityVolume(project, test::gpuVolumeJob(testSettings()));
    ASSERT_EQ(g.density.size(), cpu.density.size());
    EXPECT_NEAR(g.totalMass / cpu.totalMass, 1.0, 0.03);  // the same share of points lands in X
    const double density = correlation(blocks(cpu.density, 32), blocks(g.density, 32));
    EXPECT_GE(density, 0.99);
    RecordProperty(file.stem().string() + ".volume_density_correlation", std::to_string(density));
    ASSERT_EQ(g.color.size(), cpu.color.size());
    if (!cpu.color.empty()) {
      // Mean colours where both volumes have visits: the same structural colour.
      double worst = 0.0;
      std::size_t both = 0;
      for (std::size_t v = 0; v < cpu.density.size(); ++v) {
        if (cpu.density[v] < 0.05f || g.density[v] < 0.05f) continue;
        ++both;
        for (int d = 0; d < 3; ++d)
          worst = std::max(worst, double(std::abs(cpu.color[3 * v + d] - g.color[3 * v + d])));
      }
      EXPECT_GT(both, 0u);
      EXPECT_LT(worst, 0.25);
    }
    ++compared;
  }
  EXPECT_GE(compared, 8);
}

TEST(GpuVolume, SameSeedSameVolumeOtherSeedOtherVolume) {
  const Project project = loadProject(std::filesystem::path(GRIDIFS_ASSETS) / "twisted_functions.gridifs");
  VolumeSettings s = testSettings();
  s.samples = 500'000;
  const DensityVolume a = computeDensityVolume(project, test::gpuVolumeJob(s));
  const DensityVolume b = computeDensityVolume(project, test::gpuVolumeJob(s));
  EXPECT_EQ(a.density, b.density);
  EXPECT_EQ(a.color, b.color);
  s.seed = 2;
  const DensityVolume c = computeDensityVolume(project, test::gpuVolumeJob(s));
  EXPECT_NE(a.density, c.density);
}

TEST(GpuVolume, CountsEveryPointInsideX) {
  // Sierpiński's tetrahedron lies inside X: every sample after the skip lands in a voxel.
  const Project project = loadProject(std::filesystem::path(GRIDIFS_ASSETS) / "sierpinski_tetrahedron.gridifs");
  const auto ifs = compileIfs(project);
  RenderJob chaos;
  chaos.samples = 300'000;
  const gpu::GpuVoxelCounts out = gpu::binVoxelsGpu(*ifs, chaos, 16, false, {});
  std::uint64_t total = 0;
  for (std::uint32_t c : out.counts) total += c;
  EXPECT_EQ(out.samples, chaos.samples);
  EXPECT_EQ(std::int64_t(total), out.plotted);
  EXPECT_GT(out.plotted, chaos.samples * 9 / 10);
  EXPECT_TRUE(out.colorSums.empty());
}

TEST(GpuVolume, RefusesALatticeLargerThanItsStorageBuffers) {
  const Project project = loadProject(std::filesystem::path(GRIDIFS_ASSETS) / "sierpinski_tetrahedron.gridifs");
  const auto ifs = compileIfs(project);
  RenderJob chaos;
  chaos.samples = 1000;
  try {
    gpu::binVoxelsGpu(*ifs, chaos, 512, true, {});  // 3 GB of colour sums
    GTEST_SKIP() << "this GPU holds a 512³ colour volume";
  } catch (const gpu::GpuUnavailable& e) {
    EXPECT_NE(std::string(e.what()).find("512³ volume"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace gridifs
