#include "app/render_device_option.h"

#include "render/accumulation.h"

#include <cstdio>
#include <mutex>

#include "app/cli.h"
#if GRIDIFS_HAVE_GPU
#include "gpu/chaos_compute.h"
#include "gpu/render_device.h"
#endif

namespace gridifs::cli {
namespace {

// The first reason auto fell back to the CPU in this process; the Python module renders from
// several threads at once.
std::mutex gFallbackMutex;
std::string gFallbackReason;
bool gFallbackSaid = false;

void noteFallback(const std::string& reason) {
  const std::lock_guard lock(gFallbackMutex);
  if (gFallbackReason.empty()) gFallbackReason = reason;
}

[[noreturn]] void gpuFailed(const std::string& reason) {
  throw CliError(kFailure, "cannot render on the GPU: " + reason);
}

#if GRIDIFS_HAVE_GPU
/// Whether a walk on `device` (not Cpu) takes the GPU: `used` names it. Gpu without a usable GPU
/// fails with one sentence; Auto without a hardware GPU notes the fallback and returns false.
bool gpuChosen(gpu::RenderDevice device, std::string& used) {
  try {
    const gpu::DeviceReport report = gpu::reportDevice(device);
    if (!report.gpu) {
      noteFallback(report.description.substr(report.description.find(": ") + 2));
      return false;
    }
    used = "gpu (" + report.info.renderer + ")";
  } catch (const gpu::GpuUnavailable& e) {
    gpuFailed(e.what());
  }
  return true;
}
#endif

}  // namespace

void printDeviceNote() {
  const std::lock_guard lock(gFallbackMutex);
  if (gFallbackSaid || gFallbackReason.empty()) return;  // once per process
  gFallbackSaid = true;
  std::fprintf(stderr, "note: rendered on the CPU: %s.\n", gFallbackReason.c_str());
}

void addDeviceOption(CLI::App& app, std::optional<std::string>& device) {
  app.add_option("--device", device,
                 "auto (default: a GPU with OpenGL 4.3 compute when there is one, else the CPU), gpu or cpu");
}

std::string checkedDevice(const std::optional<std::string>& device) {
  const std::string d = device.value_or("auto");
  if (d != "auto" && d != "gpu" && d != "cpu")
    throw CliError(kBadInput, "--device must be auto, gpu or cpu, not \"" + d + "\"");
  return d;
}

#if GRIDIFS_HAVE_GPU

Accumulation accumulateOnDevice(const std::string& device, std::shared_ptr<const CompiledIfs> ifs, const RenderJob& job,
                                const std::function<bool(const RenderStats&)>& progress, std::string& used) {
  gpu::RenderDevice d = gpu::RenderDevice::Auto;
  gpu::parseRenderDevice(device, d);
  if (d == gpu::RenderDevice::Cpu) {
    used = "cpu";
    return accumulateToCompletion(std::move(ifs), job, progress);
  }
  gpu::RendererChoice choice;
  try {
    choice = gpu::openRenderer(d);
    gpu::restartOrFallBack(choice, d, ifs, job);
  } catch (const gpu::GpuUnavailable& e) {
    gpuFailed(e.what());
  }
  if (!choice.fallbackReason.empty()) noteFallback(choice.fallbackReason);
  used = choice.renderer->deviceName();
  if (!choice.renderer->waitUntilDone(progress)) throw RenderCancelled();
  Accumulation acc;
  choice.renderer->takeAccumulation(acc);
  return acc;
}

ChunkRange playedRange(const std::string& used, const RenderJob& job) {
  if (used == "cpu") return chunksOf(job.samples, job.part ? &*job.part : nullptr);
  const gpu::ChainRange chains = gpu::chainsOf(job, false);  // `software` matters for previews only
  return ChunkRange{chains.begin, chains.end};
}

PointGenerator pointGeneratorOn(const std::string& device, std::string& used) {
  gpu::RenderDevice d = gpu::RenderDevice::Auto;
  gpu::parseRenderDevice(device, d);
  used = "cpu";
  if (d == gpu::RenderDevice::Cpu) return {};
  if (!gpuChosen(d, used)) return {};
  return [d](const CompiledIfs& ifs, const RenderJob& job,
             const std::function<bool(const PointBatch&, const RenderStats&)>& sink) {
    try {
      return gpu::generatePointsGpu(ifs, job, sink);
    } catch (const gpu::GpuUnavailable& e) {
      if (d == gpu::RenderDevice::Gpu) gpuFailed(e.what());
      noteFallback(e.what());
      return generatePoints(ifs, job, sink);
    }
  };
}

VoxelBinner voxelBinnerOn(const std::string& device, bool setIteration, std::string& used) {
  gpu::RenderDevice d = gpu::RenderDevice::Auto;
  gpu::parseRenderDevice(device, d);
  used = "cpu";
  if (d == gpu::RenderDevice::Cpu) return {};
  const std::string sets = "the GPU renderer does not run the iteration over voxel sets of median functions";
  if (setIteration) {
    if (d == gpu::RenderDevice::Gpu) gpuFailed(sets + "; the CPU does");
    noteFallback(sets);
    return {};
  }
  if (!gpuChosen(d, used)) return {};
  return [d](const CompiledIfs& ifs, const VolumeJob& job, std::vector<std::uint32_t>& counts,
             std::vector<float>& colors) {
    RenderJob chaos;
    chaos.samples = job.settings.samples;
    chaos.seed = job.settings.seed;
    chaos.skip = job.settings.skip;
    try {
      gpu::GpuVoxelCounts out =
          gpu::binVoxelsGpu(ifs, chaos, job.settings.resolution, !colors.empty(), [&](double done) {
            if (job.progress) job.progress(done);
            return !(job.cancel && job.cancel->load(std::memory_order_relaxed));
          });
      counts = std::move(out.counts);
      if (!colors.empty()) colors = std::move(out.colorSums);
      return true;
    } catch (const gpu::GpuUnavailable& e) {
      if (d == gpu::RenderDevice::Gpu) gpuFailed(e.what());
      noteFallback(e.what());
      return false;
    }
  };
}

std::string deviceReport(const std::string& device, bool& gpuUsed) {
  gpu::RenderDevice d = gpu::RenderDevice::Auto;
  gpu::parseRenderDevice(device, d);
  try {
    const gpu::DeviceReport report = gpu::reportDevice(d);
    gpuUsed = report.gpu;
    return report.description;
  } catch (const gpu::GpuUnavailable& e) {
    gpuUsed = false;
    return std::string("none: ") + e.what();
  }
}

#else  // a build without the GPU renderer

Accumulation accumulateOnDevice(const std::string& device, std::shared_ptr<const CompiledIfs> ifs, const RenderJob& job,
                                const std::function<bool(const RenderStats&)>& progress, std::string& used) {
  if (device == "gpu") gpuFailed("this build of gridifs has no GPU renderer");
  if (device == "auto") noteFallback("this build of gridifs has no GPU renderer");
  used = "cpu";
  return accumulateToCompletion(std::move(ifs), job, progress);
}

ChunkRange playedRange(const std::string&, const RenderJob& job) {
  return chunksOf(job.samples, job.part ? &*job.part : nullptr);
}

PointGenerator pointGeneratorOn(const std::string& device, std::string& used) {
  if (device == "gpu") gpuFailed("this build of gridifs has no GPU renderer");
  if (device == "auto") noteFallback("this build of gridifs has no GPU renderer");
  used = "cpu";
  return {};
}

VoxelBinner voxelBinnerOn(const std::string& device, bool, std::string& used) {
  if (device == "gpu") gpuFailed("this build of gridifs has no GPU renderer");
  if (device == "auto") noteFallback("this build of gridifs has no GPU renderer");
  used = "cpu";
  return {};
}

std::string deviceReport(const std::string& device, bool& gpuUsed) {
  gpuUsed = false;
  return device == "cpu" ? "cpu (as asked)" : "cpu: this build of gridifs has no GPU renderer";
}

#endif

}  // namespace gridifs::cli
