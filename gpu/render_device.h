#pragma once
// Which renderer runs a job: the GPU compute renderer or the CPU worker pool (`--device
// auto|gpu|cpu`). `auto` takes the GPU when a hardware GPU offers OpenGL 4.3 compute through
// headless EGL, and the CPU otherwise — including when the only OpenGL is a software rasterizer
// such as Mesa's llvmpipe, which runs the compute shader on the CPU more slowly than the CPU
// renderer does (and with 32-bit z-buffer keys). `gpu` takes the GPU whatever it is, llvmpipe
// included, and fails when there is none.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "gpu/headless_gl_context.h"
#include "render/chaos_renderer.h"

namespace gridifs::gpu {

enum class RenderDevice { Auto, Gpu, Cpu };

/// "auto", "gpu", "cpu" → device; false for anything else.
bool parseRenderDevice(const std::string& text, RenderDevice& device);

/// A renderer and, when `auto` chose the CPU, why (one sentence, for a notice on stderr).
struct RendererChoice {
  std::unique_ptr<Renderer> renderer;
  bool gpu = false;
  std::string fallbackReason;
};

/// Opens the renderer for `device`. Gpu: throws GpuUnavailable (one sentence) when there is no
/// usable GPU. Auto: never throws; falls back to the CPU with a reason. Cpu: the CPU renderer.
RendererChoice openRenderer(RenderDevice device);

/// choice.renderer->restart(ifs, job); when the GPU cannot hold the job (GpuUnavailable) and
/// `device` is Auto, switches `choice` to the CPU renderer (setting fallbackReason) and restarts
/// there. Throws GpuUnavailable for Gpu, ModelError for an invalid job.
std::uint64_t restartOrFallBack(RendererChoice& choice, RenderDevice device, std::shared_ptr<const CompiledIfs> ifs,
                                const RenderJob& job);

/// What `auto` would choose here, and why: for `gridifs info`. Creates and destroys a context.
struct DeviceReport {
  bool gpu = false;
  std::string description;  // "gpu: NVIDIA ..." or "cpu: <reason>"
  GpuInfo info;             // valid when a context could be created
  bool haveContext = false;
};
DeviceReport reportDevice(RenderDevice device);

/// The export-points walk on the GPU: the same skip, restart rule and final function as
/// generatePoints, with the GPU's chains (chainCount) instead of job.threads streams; points come
/// chain-interleaved per slice. Deterministic for a seed on one GPU. Throws GpuUnavailable.
RenderStats generatePointsGpu(const CompiledIfs& ifs, const RenderJob& job,
                              const std::function<bool(const PointBatch&, const RenderStats&)>& sink);

/// The density volume's chaos game on the GPU: the same skip, restart rule and final function as
/// the CPU's binning, with the GPU's chains (chainCount); every plotted point is counted in its
/// voxel of the resolution³ lattice over X = [-1, 1]³ (x fastest), and with `color` its rgb is
/// summed there (3 floats per voxel). Deterministic for a seed on one GPU. `progress` gets the
/// fraction done between slices and returns false to stop early (the counts so far come back).
/// Throws GpuUnavailable (no context, an IFS the shader does not run, a lattice too large).
struct GpuVoxelCounts {
  std::vector<std::uint32_t> counts;
  std::vector<float> colorSums;
  std::int64_t samples = 0, plotted = 0;
};
GpuVoxelCounts binVoxelsGpu(const CompiledIfs& ifs, const RenderJob& job, int resolution, bool color,
                            const std::function<bool(double)>& progress);

}  // namespace gridifs::gpu
