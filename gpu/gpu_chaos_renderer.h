#pragma once
// The chaos game as an OpenGL 4.3 compute shader (shaders/chaos_game.comp.glsl) behind the same
// Renderer interface as the CPU worker pool: many independent chains, one per invocation, each
// with its own random stream from (seed, chain); the z-buffer, the density and the flame display's
// colour sums in storage buffers; snapshot() fills the same RenderImage as ChaosRenderer.
//
// The context is a headless EGL one (gpu/headless_gl_context.h), owned by the renderer's own
// thread, for the command line and the modeller alike: the UI thread never waits for a dispatch,
// and the same code runs in tests on Mesa's llvmpipe.
//
// Determinism: the chain count depends on the job only (chainCount), every chain iterates its
// share of the budget in order, depth order is an atomic minimum and the sums are integer atomics,
// so the same job gives the same bytes on one GPU and driver, however the work was sliced.
// Render parts (job.part = K of N) play the contiguous share partChunks(chainCount(job), K, N) of
// the whole job's chains, each chain seeded and budgeted by its index in the whole job, so the
// accumulations of the N parts sum to the whole render's, bit for bit (same device kind only:
// the GPU's chains are not the CPU's chunks).
// Z-buffer keys: with GL_NV_shader_atomic_int64 the CPU renderer's 64-bit key (depth bits << 32 |
// rgba8): depth order and colour exact. Without it, a 32-bit key: depth quantised to 16 bits
// linearly over the depth range of the IFS's nodes (with flame variations: of a short pilot chaos
// game; 1/65536 of the scene's depth) and colour to RGB565; nearer points still win except within
// that step, and colours have 5-6-5 bits.
//
// Threading: as ChaosRenderer (one controlling thread calls the public methods). snapshot() shows
// the buffers as of the renderer thread's last read-back (it asks for a new one, at most every
// 50 ms while rendering, and always when the budget is done).
#include <memory>
#include <thread>

#include "gpu/headless_gl_context.h"
#include "render/chaos_renderer.h"

namespace gridifs::gpu {

class GpuChaosRenderer final : public Renderer {
 public:
  struct Options {
    /// Use 64-bit atomics where the GPU has them (off: force the 32-bit keys, for tests).
    bool allowAtomic64 = true;
    /// Aim for dispatches of about this long, so restart and pause take effect quickly.
    double sliceSeconds = 0.008;
  };
  /// Starts the renderer thread and creates its context. Throws GpuUnavailable (one sentence).
  explicit GpuChaosRenderer(Options options);
  GpuChaosRenderer() : GpuChaosRenderer(Options{}) {}
  ~GpuChaosRenderer() override;
  GpuChaosRenderer(const GpuChaosRenderer&) = delete;
  GpuChaosRenderer& operator=(const GpuChaosRenderer&) = delete;

  const GpuInfo& info() const;
  /// Whether the current job's z-buffer uses exact 64-bit keys.
  bool exactDepth() const;

  /// Waits until the renderer thread has uploaded the job (milliseconds); throws ModelError for an
  /// invalid job and GpuUnavailable when the device cannot hold it (then nothing is rendering).
  std::uint64_t restart(std::shared_ptr<const CompiledIfs> ifs, const RenderJob& job) override;
  void stop() override;
  /// The current generation; stats() counts the samples the renderer thread has dispatched for it.
  std::uint64_t generation() const override;
  RenderStats stats() const override;
  /// Pausing holds the renderer thread between dispatches.
  void pause() override;
  void resume() override;
  bool paused() const override;
  void snapshot(RenderImage& out, const DisplaySettings& display) const override;
  /// The staged read-back, undeveloped (render/accumulation.h); 32-bit keys without 64-bit atomics.
  void accumulation(Accumulation& out) const override;
  bool waitUntilDone(const std::function<bool(const RenderStats&)>& progress = {},
                     double intervalSeconds = 0.1) override;
  const char* deviceName() const override;

  struct Shared;  // internal

 private:
  std::shared_ptr<Shared> shared_;
  std::thread thread_;
};

/// The readback as an image (internal; exposed for tests): keys → depth and packed colour,
/// densities, fixed-point sums → float colour sums, then depth cue and background.
void readbackToImage(const struct ChaosReadback& readback, bool accumulateColor, RenderImage& out,
                     const DisplaySettings& display);

}  // namespace gridifs::gpu
