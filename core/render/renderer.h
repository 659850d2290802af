#pragma once
// The progressive renderer's interface, implemented by the CPU worker pool (ChaosRenderer) and by
// the OpenGL compute renderer (gpu/gpu_chaos_renderer.h), so that the command line and the
// modeller's preview pick one at run time. The job, stats and image types live in
// core/chaos_renderer.h; both implementations fill the same RenderImage, so the image, EXR and
// flame code downstream does not know which one ran.
//
// Threading model (both implementations): one controlling thread calls every method; restart()
// publishes a new generation, snapshot() never waits for the render to finish.
#include <cstdint>
#include <functional>
#include <memory>

namespace gridifs {

struct CompiledIfs;
struct RenderJob;
struct RenderStats;
struct RenderImage;
struct DisplaySettings;
struct Accumulation;

class Renderer {
 public:
  virtual ~Renderer() = default;
  /// Starts `ifs` with `job` as a new generation and returns its number. Throws ModelError for an
  /// invalid job (the previous generation keeps running); the GPU renderer also throws
  /// GpuUnavailable when the device cannot hold the job (e.g. the image does not fit its memory).
  virtual std::uint64_t restart(std::shared_ptr<const CompiledIfs> ifs, const RenderJob& job) = 0;
  virtual void stop() = 0;
  virtual void pause() = 0;
  virtual void resume() = 0;
  virtual bool paused() const = 0;
  virtual std::uint64_t generation() const = 0;
  virtual RenderStats stats() const = 0;
  /// The buffers of the current generation as an image (see ChaosRenderer::snapshot).
  virtual void snapshot(RenderImage& out, const DisplaySettings& display) const = 0;
  /// The same buffers undeveloped (render/accumulation.h): what snapshot() develops, and what a
  /// render part stores.
  virtual void accumulation(Accumulation& out) const = 0;
  /// accumulation() of a finished render whose renderer is then restarted or dropped, never read:
  /// a renderer may hand over its own buffers instead of copying them.
  virtual void takeAccumulation(Accumulation& out) { accumulation(out); }
  /// Blocks until the budget is done; `progress` as in ChaosRenderer::waitUntilDone.
  virtual bool waitUntilDone(const std::function<bool(const RenderStats&)>& progress = {},
                             double intervalSeconds = 0.1) = 0;
  /// "cpu (2 threads)", "gpu (NVIDIA H100 ...)": for messages and file metadata.
  virtual const char* deviceName() const = 0;

 protected:
  /// waitUntilDone's loop, the same for every renderer: reports `progress` every interval until
  /// the budget is done (true, after a last report), the render is paused or has no budget
  /// (false), or `progress` returns false (then it pauses; false). `waitForProgress(seconds)`
  /// blocks until the render is done or `seconds` passed, and returns false when the job is gone.
  bool waitForBudget(const std::function<bool(const RenderStats&)>& progress, double intervalSeconds,
                     const std::function<bool(double)>& waitForProgress);
};

}  // namespace gridifs
