#pragma once
// What the GPU tier's tests share: block sums of a picture (single pixels are dominated by
// sampling noise at test sample counts) and a volume job that bins its points on the GPU.
#include <gtest/gtest.h>

#include <vector>

#include "gpu/render_device.h"
#include "render/chaos_renderer.h"
#include "volume/measure_attractor.h"

namespace gridifs::test {

/// Sums over 2×2 blocks of `value(pixel index)`.
template <class Value>
std::vector<double> blockSums(const RenderImage& image, Value value) {
  std::vector<double> out;
  for (int y = 0; y + 1 < image.height; y += 2)
    for (int x = 0; x + 1 < image.width; x += 2) {
      double s = 0;
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) s += value(std::size_t(y + dy) * std::size_t(image.width) + std::size_t(x + dx));
      out.push_back(s);
    }
  return out;
}

/// Hit counts over 2×2 blocks.
inline std::vector<double> blockDensity(const RenderImage& image) {
  return blockSums(image, [&](std::size_t i) { return double(image.density[i]); });
}

/// Alpha over 2×2 blocks.
inline std::vector<double> blockAlpha(const RenderImage& image) {
  return blockSums(image, [&](std::size_t i) { return double(image.rgba[i * 4 + 3]); });
}

/// A volume job whose points are binned by the GPU's chaos game (every sample of the budget).
inline VolumeJob gpuVolumeJob(const VolumeSettings& settings) {
  VolumeJob job;
  job.settings = settings;
  job.binner = [](const CompiledIfs& ifs, const VolumeJob& j, std::vector<std::uint32_t>& counts,
                  std::vector<float>& colors) {
    RenderJob chaos;
    chaos.samples = j.settings.samples;
    chaos.seed = j.settings.seed;
    chaos.skip = j.settings.skip;
    gpu::GpuVoxelCounts out = gpu::binVoxelsGpu(ifs, chaos, j.settings.resolution, !colors.empty(), {});
    EXPECT_EQ(out.samples, j.settings.samples);
    counts = std::move(out.counts);
    if (!colors.empty()) colors = std::move(out.colorSums);
    return true;
  };
  return job;
}

}  // namespace gridifs::test
