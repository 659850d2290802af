#include "gpu/render_device.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <system_error>

#include "gpu/chaos_compute.h"
#include "gpu/gpu_chaos_renderer.h"

namespace gridifs::gpu {

bool parseRenderDevice(const std::string& text, RenderDevice& device) {
  if (text == "auto")
    device = RenderDevice::Auto;
  else if (text == "gpu")
    device = RenderDevice::Gpu;
  else if (text == "cpu")
    device = RenderDevice::Cpu;
  else
    return false;
  return true;
}

namespace {

/// A walk with a fixed budget needs samples and a function to choose (`samples`: the JSON path
/// that set the budget).
void checkWalk(const CompiledIfs& ifs, const RenderJob& job, const char* samples) {
  if (job.samples <= 0) throw ModelError(samples, "must be at least 1");
  if (ifs.functions.empty() || ifs.alias.size() != ifs.functions.size())
    throw ModelError("functions", "no unmuted function has a positive weight");
}

std::string softwareReason(const GpuInfo& info) {
  return "the only OpenGL here is " + info.renderer + ", a software rasterizer slower than the CPU renderer";
}

/// Whether the system has a device node through which EGL can reach a hardware GPU: a DRM render
/// node (Mesa's drivers), NVIDIA's control device or WSL's GPU. Without one, `auto` skips the EGL
/// probe, which loads Mesa only to find its software rasterizer (tens of milliseconds before the
/// first sample of every render on such a machine).
bool hasGpuDeviceNode() {
  std::error_code error;
  for (const char* node : {"/dev/nvidiactl", "/dev/dxg"})
    if (std::filesystem::exists(node, error)) return true;
  for (const auto& entry : std::filesystem::directory_iterator("/dev/dri", error))
    if (entry.path().filename().string().rfind("renderD", 0) == 0) return true;
  return false;
}

constexpr const char* kNoGpuDeviceNode =
    "this machine has no GPU device (no /dev/dri render node, /dev/nvidiactl or /dev/dxg)";

}  // namespace

RendererChoice openRenderer(RenderDevice device) {
  RendererChoice choice;
  if (device == RenderDevice::Auto && !hasGpuDeviceNode()) {
    choice.fallbackReason = kNoGpuDeviceNode;
  } else if (device != RenderDevice::Cpu) {
    try {
      auto gpu = std::make_unique<GpuChaosRenderer>();
      if (device == RenderDevice::Gpu || !gpu->info().software) {
        choice.renderer = std::move(gpu);
        choice.gpu = true;
        return choice;
      }
      choice.fallbackReason = softwareReason(gpu->info());
    } catch (const GpuUnavailable& e) {
      if (device == RenderDevice::Gpu) throw;
      choice.fallbackReason = e.what();
    }
  }
  choice.renderer = std::make_unique<ChaosRenderer>();
  return choice;
}

std::uint64_t restartOrFallBack(RendererChoice& choice, RenderDevice device, std::shared_ptr<const CompiledIfs> ifs,
                                const RenderJob& job) {
  try {
    return choice.renderer->restart(ifs, job);
  } catch (const GpuUnavailable& e) {
    if (device != RenderDevice::Auto) throw;
    choice.fallbackReason = e.what();
    choice.gpu = false;
    choice.renderer = std::make_unique<ChaosRenderer>();
    return choice.renderer->restart(std::move(ifs), job);
  }
}

DeviceReport reportDevice(RenderDevice device) {
  DeviceReport report;
  if (device == RenderDevice::Cpu) {
    report.description = "cpu (as asked)";
    return report;
  }
  if (device == RenderDevice::Auto && !hasGpuDeviceNode()) {
    report.description = std::string("cpu: ") + kNoGpuDeviceNode;
    return report;
  }
  try {
    report.info = probeGpu();
    report.haveContext = true;
    if (device == RenderDevice::Gpu || !report.info.software) {
      report.gpu = true;
      report.description = "gpu: " + report.info.renderer + ", OpenGL " + report.info.version +
                           (report.info.atomic64 ? ", exact 64-bit depth keys" : ", 32-bit depth keys");
    } else {
      report.description = "cpu: " + softwareReason(report.info);
    }
  } catch (const GpuUnavailable& e) {
    if (device == RenderDevice::Gpu) throw;
    report.description = std::string("cpu: ") + e.what();
  }
  return report;
}

RenderStats generatePointsGpu(const CompiledIfs& ifs, const RenderJob& job,
                              const std::function<bool(const PointBatch&, const RenderStats&)>& sink) {
  checkWalk(ifs, job, "render.samples");
  const auto context = HeadlessGlContext::create();
  ChaosCompute compute(context->info(), ChaosOutput::Points, false, false);
  RenderJob pointJob = job;
  pointJob.width = pointJob.height = 1;  // no image; the camera is not used
  compute.setup(ifs, pointJob, ChainRange::all(chainCount(job, context->info().software)));
  RenderStats stats;
  stats.budget = job.samples;
  const auto start = std::chrono::steady_clock::now();
  std::vector<float> slots, xyz, rgb;
  const std::uint32_t perDispatch = 256;
  ChaosReadback tallies;
  while (!compute.finished()) {
    compute.dispatch(perDispatch);
    compute.finish();
    compute.readPoints(slots, perDispatch);
    xyz.clear();
    rgb.clear();
    for (std::size_t s = 0; s + 8 <= slots.size(); s += 8)
      if (slots[s + 3] == 1.0f) {
        xyz.insert(xyz.end(), {slots[s], slots[s + 1], slots[s + 2]});
        rgb.insert(rgb.end(), {slots[s + 4], slots[s + 5], slots[s + 6]});
      }
    compute.readback(tallies);
    stats.samples = tallies.samples;
    stats.badSamples = tallies.bad;
    stats.plotted = tallies.plotted;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats.pointsPerSecond = stats.seconds > 0 ? double(stats.samples) / stats.seconds : 0.0;
    stats.done = compute.finished();
    if (!sink(PointBatch{xyz.data(), rgb.data(), xyz.size() / 3}, stats)) return stats;
  }
  return stats;
}

GpuVoxelCounts binVoxelsGpu(const CompiledIfs& ifs, const RenderJob& job, int resolution, bool color,
                            const std::function<bool(double)>& progress) {
  checkWalk(ifs, job, "volume.samples");
  const auto context = HeadlessGlContext::create();
  ChaosCompute compute(context->info(), ChaosOutput::Voxels, color, false);
  RenderJob voxelJob = job;
  voxelJob.width = voxelJob.height = 1;  // no image; the camera is not used
  compute.setup(ifs, voxelJob, ChainRange::all(chainCount(job, context->info().software)), resolution);
  // Slices of a few million samples keep each dispatch short (a driver may reset a GPU whose
  // dispatch runs for seconds) and let progress and cancelling answer.
  const std::uint32_t perDispatch =
      std::uint32_t(std::clamp<std::int64_t>((std::int64_t(1) << 24) / compute.chains(), 1, 4096));
  while (!compute.finished()) {
    compute.dispatch(perDispatch);
    compute.finish();
    if (progress && !progress(double(compute.samplesDone()) / double(job.samples))) break;
  }
  ChaosReadback back;
  compute.readback(back);
  GpuVoxelCounts out;
  out.counts = std::move(back.density);
  if (color) {
    // 16 fraction bits in 64-bit sums (two words): exact, whatever order the atomics ran in.
    out.colorSums.resize(out.counts.size() * 3);
    for (std::size_t i = 0; i < out.colorSums.size(); ++i)
      out.colorSums[i] =
          float((double(back.colorSums[2 * i + 1]) * 4294967296.0 + double(back.colorSums[2 * i])) / 65536.0);
  }
  out.samples = back.samples;
  out.plotted = back.plotted;
  return out;
}

}  // namespace gridifs::gpu
