#pragma once
// The stochastic renderer (Gröller & Wegenkittl 1994, §3.1; Draves & Reckase 2003, §2 and §5): a pool of worker
// threads plays the chaos game on an immutable CompiledIfs and streams the attractor into
// per-worker z-buffer / density buffers, which snapshot() merges into an image while they run.
//
// Threading model: one controlling thread (the UI thread, or a CLI verb) calls every public
// method; the workers are internal. No public method waits for a worker to finish a batch:
// restart() only publishes a new generation (workers notice it within one batch, ~0.1 ms, and
// drop their old buffers), snapshot() reads the workers' buffers with relaxed atomic loads while
// they keep writing. Only a change of thread count, stop() and the destructor join threads
// (which have stopped within one batch).
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "render/camera.h"
#include "render/compiled_ifs.h"
#include "render/light_view.h"
#include "render/renderer.h"
#include "render/sample_chunks.h"
#include "tone/palette.h"

namespace gridifs {

struct Accumulation;

namespace limits {
/// Images larger than this are refused: every render thread keeps a z-buffer and a density
/// buffer (12 bytes per pixel, 28 with flame colour sums), so 8192×8192 already needs ~1.6 GB
/// with two threads.
inline constexpr std::int64_t kMaxRenderPixels = std::int64_t(8192) * 8192;
inline constexpr int kMaxRenderSide = 16384;
/// Larger sample budgets are refused (10^11 is about half an hour on two cores).
inline constexpr std::int64_t kMaxRenderSamples = 100'000'000'000;
inline constexpr int kMaxRenderThreads = 64;
/// A point farther than this from the origin (in any coordinate) counts as escaped.
inline constexpr float kEscapeBound = 1e5f;
}  // namespace limits

/// What to render. `samples` is the total number of chaos-game iterations, cut into chunks of
/// kChunkSamples (render/sample_chunks.h) that the workers take in turn; ≤ 0 means "until
/// stopped" (the GUI's progressive preview). The image depends on (snapshot, camera, size,
/// samples, seed, skip, chunks) only, bit for bit — not on the thread count.
struct RenderJob {
  Camera camera;
  int width = 1024, height = 768;
  std::int64_t samples = 20'000'000;
  std::uint64_t seed = 1;
  int skip = 20;
  int threads = 1;
  /// Only this part's share of the budget (gridifs render --part K/N; on the CPU a contiguous
  /// range of chunks, on the GPU of chains, partChunks); absent: all of it.
  std::optional<RenderPart> part;
  /// Also accumulate per-pixel colour sums for the flame display. Costs a 16-byte
  /// read-modify-write per plotted sample, so it is off for the z-buffer preview.
  bool accumulateColor = false;
  /// With accumulateColor: when set, colorSums hold the sums of this palette's color
  /// at each sample's c (flam3's structural coloring, Draves & Reckase 2003, §5) instead of the blended RGB.
  std::shared_ptr<const Palette> palette;
  /// Whether the workers keep the z-buffer's keys (nearest depth and colour). The flame display
  /// develops hit counts and colour sums alone, so its command-line renders turn them off: the
  /// plotter then skips each sample's depth and colour packing and its key's compare and store,
  /// and accumulation() hands out no keys. The GPU renderer keeps them either way.
  bool depthKeys = true;
  /// Run the workers at a lower OS priority (Linux: nice 10) so that the UI thread always gets a
  /// core first on a machine with few cores (the GUI's preview). Does not change the image.
  bool lowPriority = false;
  /// The shaded display's chaos-game effects (core/render/shaded_plot.h): one depth buffer per
  /// light view (at most 3), filled by the same samples as the camera's z-buffer, and depth of
  /// field (aperture > 0: each point moves on a disc of radius aperture · |depth − focus|).
  std::vector<LightView> shadowLights;
  double dofAperture = 0.0, dofFocus = 0.0;

  /// camera, size, samples, seed and skip from the project; `threads` as given
  /// (≤ 0: std::thread::hardware_concurrency()).
  static RenderJob fromProject(const Project& project, int threads = 0);
};

/// Checks a job against the limits above. Throws ModelError naming the field
/// ("render.width", "render.samples", ...) with one clear sentence.
/// Also refuses a job whose buffers (renderBufferBytes) would not fit the memory free now.
void validateRenderJob(const RenderJob& job);

/// The bytes the CPU renderer's buffers take for `job` (every worker's z-buffer and colour sums,
/// the merged snapshot and the image made from it).
std::uint64_t renderBufferBytes(const RenderJob& job);

/// How the merged buffers become colours (applied in snapshot(), so changing it needs no re-render).
struct DisplaySettings {
  Vec3 background{0.0};
  /// Gröller & Wegenkittl 1994, §3.1: colours are attenuated with distance. 0: none; 1: the farthest hit point is
  /// black. The depth range is that of the points in the image (nearest → farthest).
  double depthCue = 0.6;
  static DisplaySettings fromProject(const Project& project);
};

struct RenderStats {
  std::uint64_t generation = 0;
  std::int64_t samples = 0;      // iterations done in this generation (all workers)
  std::int64_t budget = 0;       // the job's sample budget (≤ 0: unlimited)
  std::int64_t badSamples = 0;   // non-finite or escaped points; each restarted its chain
  std::int64_t plotted = 0;      // samples past `skip` that landed in the frame, in front of the camera
  double seconds = 0.0;          // wall time since the generation started (excluding pauses)
  double pointsPerSecond = 0.0;  // samples / seconds
  bool paused = false;
  bool done = false;  // the budget is exhausted (never for an unlimited job)
  /// This generation kept the camera's buffers of the one before (only shadowed lights changed)
  /// and re-fills only the changed lights' buffers; `samples` counts the camera's samples.
  bool keptCamera = false;
  double badFraction() const { return samples > 0 ? double(badSamples) / double(samples) : 0.0; }
  double progress() const { return budget > 0 ? double(samples) / double(budget) : 0.0; }
};

/// A merged image. Row 0 is the top row. Reuse one instance across snapshot() calls to avoid
/// reallocating.
struct RenderImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;          // 4 per pixel: depth-cued colour over the background;
                                           // alpha 255 where a point was plotted, else 0
  std::vector<float> depth;                // view depth of the nearest point; +inf where none
  std::vector<std::uint32_t> density;      // hits per pixel (saturating)
  std::vector<float> colorSums;            // 4 per pixel (Σr, Σg, Σb, Σc) when job.accumulateColor, else empty
  std::int64_t hitPixels = 0;              // pixels with at least one point
  float minDepth = 0.0f, maxDepth = 0.0f;  // depth range of the hit pixels
  std::uint64_t generation = 0;
  RenderStats stats;
  /// One per job.shadowLights: the views and their merged depth buffers (size² light depths,
  /// +inf where no sample landed).
  std::vector<LightView> lightViews;
  std::vector<std::vector<float>> lightDepth;

  /// No picture (no job yet): size 0 and empty buffers, which keep their capacity.
  void clear() {
    width = height = 0;
    rgba.clear();
    depth.clear();
    density.clear();
    colorSums.clear();
    hitPixels = 0;
    lightViews.clear();
    lightDepth.clear();
  }
};

/// The progressive renderer. See the threading model at the top of this file.
class ChaosRenderer : public Renderer {
 public:
  ChaosRenderer();
  ~ChaosRenderer() override;  // stops and joins the workers
  ChaosRenderer(const ChaosRenderer&) = delete;
  ChaosRenderer& operator=(const ChaosRenderer&) = delete;

  /// Starts rendering `ifs` with `job` as a new generation and returns its number. Points of older
  /// generations never reach an image of this one, with one exception that changes no pixel: when
  /// only job.shadowLights differ from the current generation's job (same `ifs` object), the
  /// workers keep the camera's buffers and the unchanged lights' buffers and replay their chains
  /// into the changed lights' buffers only (stats().keptCamera); the result is the same, bit for
  /// bit, as a render from scratch. Throws ModelError when the job is invalid
  /// (validateRenderJob) or `ifs` is null; the previous generation keeps running in that case.
  std::uint64_t restart(std::shared_ptr<const CompiledIfs> ifs, const RenderJob& job) override;
  /// Stops the workers (joins them) and forgets the current generation's buffers' validity.
  void stop() override;
  /// Workers idle after their current batch; resume() continues the same generation.
  void pause() override;
  void resume() override;
  bool paused() const override;

  std::uint64_t generation() const override;
  RenderStats stats() const override;
  bool done() const { return stats().done; }

  /// Merges the buffers of all workers that are already on the current generation into `out`
  /// (deterministic merge: the nearest depth wins, equal depths by the smaller packed colour, so the
  /// result does not depend on worker order). Does not stop or wait for workers. Cost: one pass
  /// over every worker's buffers (a few ms at 1024² with two workers).
  void snapshot(RenderImage& out, const DisplaySettings& display) const override;
  RenderImage snapshot(const DisplaySettings& display) const;
  /// The current generation's buffers, undeveloped (render/accumulation.h): what snapshot()
  /// develops, and what a render part stores. Same rules as snapshot().
  void accumulation(Accumulation& out) const override;
  /// accumulation() of a finished render whose renderer is then restarted or dropped, never read:
  /// the first worker's colour sums, the biggest buffer (32 bytes a pixel), move into `out`
  /// instead of being copied. That worker's buffers then count as empty. Before the budget is
  /// done it is accumulation().
  void takeAccumulation(Accumulation& out) override;

  /// Blocks until the current generation's budget is done (returns at once for unlimited jobs).
  /// `progress` is called about every `intervalSeconds` on this thread; returning false stops the
  /// render early (the result then holds what was done). Returns false when stopped early.
  bool waitUntilDone(const std::function<bool(const RenderStats&)>& progress = {},
                     double intervalSeconds = 0.1) override;
  const char* deviceName() const override { return "cpu"; }

  struct Worker;  // internal
  struct Shared;  // internal

 private:
  /// accumulation()'s merge; `giver`, one of the current generation's workers, hands over its
  /// colour sums (takeAccumulation).
  void mergeBuffers(Accumulation& out, Worker* giver) const;
  void startThreads(int count);
  void joinThreads();

  std::shared_ptr<Shared> shared_;
  std::vector<std::unique_ptr<Worker>> workers_;
  std::vector<std::thread> threads_;
};

/// Pass 2 of snapshot(), shared with the GPU renderer: `image` holds depth (+inf where empty),
/// hitPixels, the depth range and, in the 4 bytes of each rgba pixel, the nearest point's packed
/// colour (r in the low byte); this turns rgba into depth-cued colour over the background.
void shadeRenderImage(RenderImage& image, const DisplaySettings& display);

/// Thrown by renderToCompletion when its progress callback asks to stop.
struct RenderCancelled : std::runtime_error {
  RenderCancelled() : std::runtime_error("render cancelled") {}
};

/// Renders `job` to completion on `job.threads` workers and returns the merged image (the CLI's
/// `render`). `progress` as in waitUntilDone; returning false cancels and throws RenderCancelled.
/// Throws ModelError for an invalid job.
RenderImage renderToCompletion(std::shared_ptr<const CompiledIfs> ifs, const RenderJob& job,
                               const DisplaySettings& display,
                               const std::function<bool(const RenderStats&)>& progress = {});

/// renderToCompletion's buffers undeveloped (render/accumulation.h): what a render part stores.
Accumulation accumulateToCompletion(std::shared_ptr<const CompiledIfs> ifs, const RenderJob& job,
                                    const std::function<bool(const RenderStats&)>& progress = {});

/// The samples the renderer would plot, without projecting them (export-points): the same chunks
/// with their streams (seed, chunk), the same skip and restart rule, the final function applied.
/// Emits the chunks in order, in batches; `sink`
/// receives xyz (3 floats per point) and rgb (3 floats in [0, 1] per point) and returns false to
/// cancel. Runs on the calling thread. Returns the RenderStats of the walk (plotted = points emitted).
struct PointBatch {
  const float* xyz;
  const float* rgb;
  std::size_t count;
};
RenderStats generatePoints(const CompiledIfs& ifs, const RenderJob& job,
                           const std::function<bool(const PointBatch&, const RenderStats&)>& sink);

}  // namespace gridifs
