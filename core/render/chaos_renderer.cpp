#include "render/chaos_renderer.h"

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

#include "base/system_memory.h"
#include "render/accumulation.h"
#include "render/barycentric_kernel.h"
#include "render/chaos_kernel.h"
#include "render/shaded_plot.h"

// snapshot() reinterprets the packed colour bytes (r in the low byte) as r, g, b, a in memory.
static_assert(std::endian::native == std::endian::little, "the renderer assumes a little-endian CPU");

namespace gridifs {
namespace {

using kernel::kEmptyKey;

std::int64_t nowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

/// Iterations per batch: a worker checks its generation, pause and quit flags between batches.
/// ~0.1–0.3 ms at this machine's rates, so a restart stops stale work well within 1 ms.
constexpr std::int64_t kBatch = 8192;
static_assert(kBatch % kernel::kLanes == 0);

/// The chunks a job plays: its part's range, or every chunk of the budget (an unlimited job's
/// chunks never end).
ChunkRange jobChunks(const RenderJob& job) {
  if (job.samples <= 0) return ChunkRange{0, std::numeric_limits<std::int64_t>::max()};
  return chunksOf(job.samples, job.part ? &*job.part : nullptr);
}

/// The samples of chunk `c` of `job` (every chunk is full in an unlimited job).
std::int64_t jobChunkSize(const RenderJob& job, std::int64_t c) {
  return job.samples <= 0 ? kChunkSamples : chunkSize(job.samples, c);
}

/// The lens samples of depth of field: a stream of their own per chunk, so the chaos game's
/// sequence is the one without depth of field.
kernel::Rng lensStream(const RenderJob& job, std::int64_t chunk) {
  return kernel::Rng::forStream(job.seed ^ 0x1E45D0F5A1E7ull, std::uint64_t(chunk));
}

/// Everything the workers need for one generation; immutable once published.
struct PreparedJob {
  std::shared_ptr<const CompiledIfs> ifs;
  std::vector<kernel::HotFunction> hot;  // functions, then the final function if any
  kernel::HotIfs hotIfs;
  kernel::HotCamera camera;
  RenderJob job;
  std::vector<kernel::v4f> palette;  // 257 entries when job.palette is set
  kernel::HotLens lens;
  /// Generations with the same epoch share the camera's buffers: a restart that changes only the
  /// shadowed lights keeps the epoch (ChaosRenderer::restart), and a worker that holds that epoch's
  /// buffers keeps them and re-fills only the light buffers that changed.
  std::uint64_t cameraEpoch = 0;
  /// The chunks to play and the next one to hand out; the workers take them in turn. Generations
  /// that keep the camera's buffers share the counter, so no chunk is played twice.
  ChunkRange chunks;
  std::shared_ptr<std::atomic<std::int64_t>> nextChunk;

  /// Whether samples go through a lens (HotLens) before the camera: the shaded display's depth of
  /// field, else the camera's lens blur.
  bool lensBlurs() const { return job.dofAperture > 0.0 || job.camera.lens_blur > 0.0; }
  bool shaded() const { return !job.shadowLights.empty() || lensBlurs(); }

  PreparedJob(std::shared_ptr<const CompiledIfs> compiled, const RenderJob& renderJob)
      : ifs(std::move(compiled)), job(renderJob), chunks(jobChunks(renderJob)) {
    nextChunk = std::make_shared<std::atomic<std::int64_t>>(chunks.begin);
    if (ifs->functions.empty() || ifs->alias.size() != ifs->functions.size())
      throw ModelError("functions", "no unmuted function has a positive weight");
    hotIfs = kernel::makeHotIfs(*ifs, hot, job.skip, limits::kEscapeBound);
    camera = kernel::makeHotCamera(OrbitCamera(job.camera, job.width, job.height));
    if (lensBlurs()) {
      const OrbitCamera orbit(job.camera, job.width, job.height);
      const glm::dmat4& view = orbit.view();  // rows of the rotation: the view axes in world space
      for (int d = 0; d < 3; ++d) {
        lens.right[d] = float(view[d][0]);
        lens.up[d] = float(view[d][1]);
      }
      lens.right[3] = lens.up[3] = 0.0f;
      const kernel::v4f* columns[4] = {&camera.cx, &camera.cy, &camera.cz, &camera.c1};
      for (int d = 0; d < 4; ++d) lens.depthRow[d] = (*columns[d])[3];
      if (job.dofAperture > 0.0) {
        lens.aperture = float(job.dofAperture);
        lens.focus = float(job.dofFocus);
      } else {
        // flam3's cam_dof (Apophysis 7X): up to 0.1 · cam_dof times the distance from the plane
        // the camera pivots on (the target's), measured along the view axis.
        lens.aperture = float(0.1 * job.camera.lens_blur);
        lens.focus = float(job.camera.distance);
        lens.uniformRadius = true;
      }
    }
    if (job.palette) {
      for (const Rgb& c : job.palette->colors) palette.push_back(kernel::v4f{c.r, c.g, c.b, 0.0f});
      palette.push_back(palette.back());
    }
  }
  PreparedJob(const PreparedJob&) = delete;
  PreparedJob& operator=(const PreparedJob&) = delete;
};

/// Whether `next` plots the same camera buffers as `previous` and differs only in the shadowed
/// lights, so that a restart can keep the camera's buffers. Free-form IFSs plot no light buffers.
/// An identical job is rendered again (a benchmark's or a caller's explicit restart).
bool sameCameraPass(const PreparedJob& previous, const PreparedJob& next) {
  const RenderJob &a = previous.job, &b = next.job;
  if (a.shadowLights == b.shadowLights) return false;
  const bool samePalette = a.palette == b.palette || (a.palette && b.palette && *a.palette == *b.palette);
  return previous.ifs == next.ifs && !next.hotIfs.barycentricBlocks && a.camera == b.camera && a.width == b.width &&
         a.height == b.height && a.samples == b.samples && a.seed == b.seed && a.skip == b.skip &&
         a.threads == b.threads && a.part == b.part && a.accumulateColor == b.accumulateColor && samePalette &&
         a.dofAperture == b.dofAperture && a.dofFocus == b.dofFocus;
}

}  // namespace

struct ChaosRenderer::Shared {
  std::mutex mutex;
  std::condition_variable wake;      // workers wait here for work
  std::condition_variable finished;  // the controller waits here in waitUntilDone
  std::atomic<std::uint64_t> generation{0};
  std::atomic<bool> paused{false}, quit{false};
  std::shared_ptr<const PreparedJob> job;  // written by the controller under `mutex`
  // Controller-thread-only bookkeeping.
  std::uint64_t nextGeneration = 0;
  std::int64_t startNs = 0, pausedAtNs = 0, pausedTotalNs = 0;
};

struct ChaosRenderer::Worker {
  int index = 0;
  std::vector<kernel::PixelCell> cells;
  std::vector<std::uint64_t> colorSums;  // fixed point (render/accumulation.h)
  /// One depth buffer per shadowed light (kernel::kLightEmpty where empty), the light view each was
  /// filled for, and whether it holds every sample the camera's buffers hold; the lens samples.
  std::vector<std::uint16_t> lightDepth[kernel::kMaxShadowLights];
  LightView lightViews[kernel::kMaxShadowLights];
  bool lightComplete[kernel::kMaxShadowLights] = {};
  int lightCount = 0;
  kernel::Rng lensRng;  // the current chunk's lens stream
  /// The chunks whose samples are in the buffers (with how many of each, the current one last
  /// and possibly unfinished): the light-only pass replays exactly these.
  struct PlayedChunk {
    std::int64_t chunk, samples;
  };
  std::vector<PlayedChunk> played;
  /// The camera epoch (PreparedJob::cameraEpoch) of `cells` and `colorSums`; 0: none yet.
  std::uint64_t cameraEpoch = 0;
  /// The generation the buffers and counters belong to; 0 while they are being reset.
  std::atomic<std::uint64_t> bufferGeneration{0};
  alignas(64) std::atomic<std::int64_t> samples{0};
  std::atomic<std::int64_t> bad{0}, plotted{0};
  std::atomic<std::int64_t> finishedNs{0};  // when the budget ran out; 0 while running

  void resetBuffers(const RenderJob& job) {
    const std::size_t n = std::size_t(job.width) * std::size_t(job.height);
    cells.assign(n, kernel::PixelCell{});
    if (job.accumulateColor)
      colorSums.assign(n * 4, 0);
    else
      std::vector<std::uint64_t>().swap(colorSums);
    for (int l = 0; l < kernel::kMaxShadowLights; ++l) {
      if (l < int(job.shadowLights.size())) {
        const std::size_t size = std::size_t(job.shadowLights[std::size_t(l)].size());
        lightDepth[l].assign(size * size, kernel::kLightEmpty);
        lightViews[l] = job.shadowLights[std::size_t(l)];
        lightComplete[l] = true;  // as complete as the (empty) camera buffers
      } else {
        std::vector<std::uint16_t>().swap(lightDepth[l]);
      }
    }
    lightCount = int(job.shadowLights.size());
    played.clear();
  }

  /// Keeps the camera's buffers for `views`: a buffer whose light view is unchanged moves to its
  /// new place, every other light gets an empty buffer that is not complete. Returns whether any
  /// buffer was emptied (the light-only pass must then start over from the chain's beginning).
  bool adoptLights(const std::vector<LightView>& views) {
    std::vector<std::uint16_t> oldDepth[kernel::kMaxShadowLights];
    LightView oldViews[kernel::kMaxShadowLights];
    bool oldComplete[kernel::kMaxShadowLights] = {}, taken[kernel::kMaxShadowLights] = {};
    const int oldCount = lightCount;
    for (int l = 0; l < oldCount; ++l) {
      oldDepth[l].swap(lightDepth[l]);
      oldViews[l] = lightViews[l];
      oldComplete[l] = lightComplete[l];
    }
    bool emptied = false;
    for (int l = 0; l < int(views.size()); ++l) {
      const LightView& view = views[std::size_t(l)];
      int match = -1;
      for (int j = 0; j < oldCount && match < 0; ++j)
        if (!taken[j] && oldViews[j] == view) match = j;
      lightViews[l] = view;
      if (match >= 0) {
        taken[match] = true;
        lightDepth[l].swap(oldDepth[match]);
        lightComplete[l] = oldComplete[match];
      } else {
        lightDepth[l].assign(std::size_t(view.size()) * std::size_t(view.size()), kernel::kLightEmpty);
        lightComplete[l] = false;
        emptied = true;
      }
    }
    for (int l = int(views.size()); l < kernel::kMaxShadowLights; ++l) std::vector<std::uint16_t>().swap(lightDepth[l]);
    lightCount = int(views.size());
    return emptied;
  }
};

namespace {

template <bool kColor>
[[gnu::always_inline]] inline void runBatchImpl(kernel::ChainState& chain, const PreparedJob& job,
                                                ChaosRenderer::Worker& w, std::int64_t count,
                                                kernel::ChainCounters& counters) {
  kernel::ZBufferPlot<kColor> plot{job.camera, w.cells.data(), w.colorSums.data(),
                                   job.palette.empty() ? nullptr : job.palette.data()};
  plot.keys = job.job.depthKeys;
  kernel::runChain(chain, job.hotIfs, count, plot, counters);
}

GRIDIFS_KERNEL_CLONES void runBatchPlain(kernel::ChainState& chain, const PreparedJob& job, ChaosRenderer::Worker& w,
                                         std::int64_t count, kernel::ChainCounters& counters) {
  runBatchImpl<false>(chain, job, w, count, counters);
}

GRIDIFS_KERNEL_CLONES void runBatchColor(kernel::ChainState& chain, const PreparedJob& job, ChaosRenderer::Worker& w,
                                         std::int64_t count, kernel::ChainCounters& counters) {
  runBatchImpl<true>(chain, job, w, count, counters);
}

/// The light half of the plotter for the worker's buffers: every light, or (onlyIncomplete) the
/// lights whose buffers the light-only pass is re-filling.
kernel::LightPlot lightPlot(const PreparedJob& job, ChaosRenderer::Worker& w, bool onlyIncomplete) {
  kernel::LightPlot plot;
  for (int l = 0; l < int(job.job.shadowLights.size()); ++l)
    if (!onlyIncomplete || !w.lightComplete[l])
      plot.lights[plot.lightCount++] =
          kernel::makeHotLight(job.job.shadowLights[std::size_t(l)], w.lightDepth[l].data());
  if (!job.job.shadowLights.empty()) {
    plot.lightSize = float(job.job.shadowLights[0].size());
    plot.lightStride = std::uint32_t(job.job.shadowLights[0].size());
  }
  return plot;
}

template <bool kColor>
[[gnu::always_inline]] inline void runShadedImpl(kernel::ChainState& chain, const PreparedJob& job,
                                                 ChaosRenderer::Worker& w, std::int64_t count,
                                                 kernel::ChainCounters& counters) {
  kernel::ShadedPlot<kColor> plot;
  plot.camera = kernel::ZBufferPlot<kColor>{job.camera, w.cells.data(), w.colorSums.data(),
                                            job.palette.empty() ? nullptr : job.palette.data()};
  plot.camera.keys = job.job.depthKeys;
  plot.light = lightPlot(job, w, false);
  plot.lens = job.lens;
  plot.jitter = job.lensBlurs();
  plot.rng = w.lensRng;
  kernel::runChain(chain, job.hotIfs, count, plot, counters);
  w.lensRng = plot.rng;
}

GRIDIFS_KERNEL_CLONES void runBatchShaded(kernel::ChainState& chain, const PreparedJob& job, ChaosRenderer::Worker& w,
                                          std::int64_t count, kernel::ChainCounters& counters) {
  runShadedImpl<false>(chain, job, w, count, counters);
}

GRIDIFS_KERNEL_CLONES void runBatchShadedColor(kernel::ChainState& chain, const PreparedJob& job,
                                               ChaosRenderer::Worker& w, std::int64_t count,
                                               kernel::ChainCounters& counters) {
  runShadedImpl<true>(chain, job, w, count, counters);
}

/// A batch of the light-only pass: the same chain, projected only into the lights being re-filled.
GRIDIFS_KERNEL_CLONES void runLightBatch(kernel::ChainState& chain, const PreparedJob& job, ChaosRenderer::Worker& w,
                                         std::int64_t count, kernel::ChainCounters& counters) {
  kernel::LightPlot plot = lightPlot(job, w, true);
  kernel::runChain(chain, job.hotIfs, count, plot, counters);
}

/// A free-form IFS's batch (barycentric_kernel.h); kept out of the grid kernel's clones.
GRIDIFS_KERNEL_CLONES void runBarycentricBatch(kernel::ChainState& chain, kernel::BarycentricState& bary,
                                               const PreparedJob& job, ChaosRenderer::Worker& w, std::int64_t count,
                                               kernel::ChainCounters& counters) {
  if (job.lensBlurs()) {
    // Free-form IFSs plot no light buffers: only the lens.
    auto blurred = [&]<bool kColor>() {
      kernel::ShadedPlot<kColor> plot;
      plot.camera = kernel::ZBufferPlot<kColor>{job.camera, w.cells.data(), w.colorSums.data(),
                                                job.palette.empty() ? nullptr : job.palette.data()};
      plot.camera.keys = job.job.depthKeys;
      plot.lens = job.lens;
      plot.jitter = true;
      plot.rng = w.lensRng;
      kernel::runBarycentricChain(chain, bary, job.hotIfs, count, plot, counters);
      w.lensRng = plot.rng;
    };
    if (job.job.accumulateColor)
      blurred.template operator()<true>();
    else
      blurred.template operator()<false>();
  } else if (job.job.accumulateColor) {
    kernel::ZBufferPlot<true> plot{job.camera, w.cells.data(), w.colorSums.data(),
                                   job.palette.empty() ? nullptr : job.palette.data()};
    plot.keys = job.job.depthKeys;
    kernel::runBarycentricChain(chain, bary, job.hotIfs, count, plot, counters);
  } else {
    kernel::ZBufferPlot<false> plot{job.camera, w.cells.data(), w.colorSums.data(), nullptr};
    plot.keys = job.job.depthKeys;
    kernel::runBarycentricChain(chain, bary, job.hotIfs, count, plot, counters);
  }
}

/// Lowers the calling thread's priority once (an unprivileged thread cannot raise it again).
void lowerThreadPriority() {
#if defined(__linux__)
  setpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid)), 10);
#endif
}

void workerMain(std::shared_ptr<ChaosRenderer::Shared> shared, ChaosRenderer::Worker* w) {
  const kernel::DenormalsAreZero flushDenormals;
  bool lowered = false;
  std::shared_ptr<const PreparedJob> job;
  std::uint64_t myGeneration = 0;
  kernel::ChainState chain;
  auto bary = std::make_unique<kernel::BarycentricState>();  // used by free-form IFSs only
  kernel::ChainCounters counters;
  // The chunk being played (-1: none yet) and its samples still to play; `exhausted` once the
  // job has no chunk left for this worker.
  std::int64_t left = 0;
  bool exhausted = true;
  // The light-only pass: the chunks in the camera's buffers (Worker::played) replayed, plotting
  // only into the lights being re-filled. A chunk's samples depend only on (seed, chunk, skip),
  // so the re-filled buffers are those of a render from scratch; the chain being played is kept.
  bool replaying = false;
  std::vector<ChaosRenderer::Worker::PlayedChunk> replay;
  std::size_t replayNext = 0;
  std::int64_t replayLeft = 0;
  kernel::ChainState replayChain;
  for (;;) {
    bool fresh = false;
    {
      std::unique_lock lock(shared->mutex);
      shared->wake.wait(lock, [&] {
        return shared->quit.load() || shared->generation.load() != myGeneration ||
               ((!exhausted || replaying) && !shared->paused.load());
      });
      if (shared->quit.load()) return;
      if (shared->generation.load() != myGeneration) {
        job = shared->job;
        myGeneration = shared->generation.load();
        fresh = true;
      }
    }
    if (fresh) {
      if (job->job.lowPriority && !lowered) {
        lowerThreadPriority();
        lowered = true;
      }
      // Old-generation points stay in buffers that snapshot() ignores from here on.
      w->bufferGeneration.store(0, std::memory_order_release);
      if (job->cameraEpoch == w->cameraEpoch) {
        // Only shadowed lights changed: keep the camera's buffers, counters and chunk.
        if (w->adoptLights(job->job.shadowLights)) {
          replaying = true;
          replay = w->played;
          replayNext = 0;
          replayLeft = 0;
        }
      } else {
        w->resetBuffers(job->job);
        w->cameraEpoch = job->cameraEpoch;
        counters = {};
        replaying = false;
        left = 0;
        exhausted = false;
      }
      w->samples.store(counters.samples, std::memory_order_relaxed);
      w->bad.store(counters.bad, std::memory_order_relaxed);
      w->plotted.store(counters.plotted, std::memory_order_relaxed);
      w->finishedNs.store(0, std::memory_order_relaxed);
      w->bufferGeneration.store(myGeneration, std::memory_order_release);
    }
    while (!exhausted || replaying) {
      if (shared->generation.load(std::memory_order_relaxed) != myGeneration ||
          shared->paused.load(std::memory_order_relaxed) || shared->quit.load(std::memory_order_relaxed))
        break;
      if (replaying) {
        if (replayLeft == 0) {
          if (replayNext == replay.size()) {
            replaying = false;
            for (bool& complete : w->lightComplete) complete = true;
            continue;
          }
          const auto& next = replay[replayNext++];
          replayChain = kernel::ChainState::start(job->job.seed, std::uint64_t(next.chunk), job->job.skip);
          replayLeft = next.samples;
        }
        // The same batch boundaries as the pass that filled the camera's buffers.
        const std::int64_t n = std::min(replayLeft, kBatch);
        kernel::ChainCounters scratch;
        runLightBatch(replayChain, *job, *w, n, scratch);
        replayLeft -= n;
        continue;
      }
      if (left == 0) {
        const std::int64_t chunk = job->nextChunk->fetch_add(1, std::memory_order_relaxed);
        if (chunk >= job->chunks.end) {
          exhausted = true;
          break;
        }
        left = jobChunkSize(job->job, chunk);
        w->played.push_back({chunk, 0});
        chain = kernel::ChainState::start(job->job.seed, std::uint64_t(chunk), job->job.skip);
        if (job->hotIfs.barycentricBlocks) bary->start(chain, job->hotIfs);
        w->lensRng = lensStream(job->job, chunk);
      }
      const std::int64_t n = std::min(left, kBatch);
      if (job->hotIfs.barycentricBlocks)
        runBarycentricBatch(chain, *bary, *job, *w, n, counters);
      else if (job->shaded())
        (job->job.accumulateColor ? runBatchShadedColor : runBatchShaded)(chain, *job, *w, n, counters);
      else if (job->job.accumulateColor)
        runBatchColor(chain, *job, *w, n, counters);
      else
        runBatchPlain(chain, *job, *w, n, counters);
      left -= n;
      w->played.back().samples += n;
      // Release: a reader that sees this count (stats(), then snapshot()) also sees the batch's points.
      w->samples.store(counters.samples, std::memory_order_release);
      w->bad.store(counters.bad, std::memory_order_relaxed);
      w->plotted.store(counters.plotted, std::memory_order_relaxed);
    }
    if (exhausted && !replaying && w->finishedNs.load(std::memory_order_relaxed) == 0) {
      w->finishedNs.store(nowNs(), std::memory_order_release);
      { std::lock_guard lock(shared->mutex); }
      shared->finished.notify_all();
    }
  }
}

}  // namespace

RenderJob RenderJob::fromProject(const Project& project, int threads) {
  RenderJob job;
  job.camera = project.camera;
  job.width = project.render.width;
  job.height = project.render.height;
  job.samples = renderSampleCount(project.render);
  job.seed = project.render.seed;
  job.skip = project.render.skip;
  job.threads = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
  job.threads = std::min(job.threads, limits::kMaxRenderThreads);
  return job;
}

DisplaySettings DisplaySettings::fromProject(const Project& project) {
  return DisplaySettings{project.render.background, project.render.depth_cue};
}

void validateRenderJob(const RenderJob& job) {
  if (job.width < 1 || job.height < 1)
    throw ModelError("render", "the image must be at least 1×1 pixel, not " + std::to_string(job.width) + "×" +
                                   std::to_string(job.height));
  const std::int64_t pixels = std::int64_t(job.width) * job.height;
  if (job.width > limits::kMaxRenderSide || job.height > limits::kMaxRenderSide || pixels > limits::kMaxRenderPixels) {
    const double gb = double(pixels) * (12.0 * std::max(1, job.threads) + 12.0) / 1e9;
    throw ModelError("render", std::to_string(job.width) + "×" + std::to_string(job.height) +
                                   " is too large: GridIFS renders at most 67 megapixels (e.g. 8192×8192), "
                                   "because every render thread keeps its own z-buffer (this image would need "
                                   "about " +
                                   std::to_string(int(std::ceil(gb))) + " GB)");
  }
  if (job.samples > limits::kMaxRenderSamples)
    throw ModelError("render.samples", std::to_string(job.samples) + " samples is more than the limit of " +
                                           std::to_string(limits::kMaxRenderSamples));
  if (job.skip < 0 || job.skip > 1'000'000) throw ModelError("render.skip", "must be between 0 and 1000000");
  if (job.threads < 1 || job.threads > limits::kMaxRenderThreads)
    throw ModelError("render", "the thread count must be between 1 and " + std::to_string(limits::kMaxRenderThreads));
  OrbitCamera(job.camera, job.width, job.height);  // throws for an unusable camera
  if (job.shadowLights.size() > std::size_t(kernel::kMaxShadowLights))
    throw ModelError("render.shading.lights",
                     "at most " + std::to_string(kernel::kMaxShadowLights) + " lights can cast shadows");
  for (const LightView& light : job.shadowLights)
    if (light.size() != job.shadowLights[0].size())
      throw ModelError("render.shading.lights", "every shadow map of a render must have the same size");
  if (job.dofAperture < 0.0 || !std::isfinite(job.dofAperture) || !std::isfinite(job.dofFocus))
    throw ModelError("render.shading.dof", "the aperture and focus must be finite and the aperture not negative");
  const std::uint64_t needed = renderBufferBytes(job);
  if (const auto available = availableMemoryBytes(); available && needed > *available)
    throw ModelError("render", "a " + std::to_string(job.width) + "×" + std::to_string(job.height) + " render on " +
                                   std::to_string(job.threads) + " thread" + (job.threads == 1 ? "" : "s") +
                                   " needs about " + describeBytes(needed) + " of memory for its buffers, but only " +
                                   describeBytes(*available) + " is free (use fewer threads or a smaller image)");
}

std::uint64_t renderBufferBytes(const RenderJob& job) {
  const std::uint64_t pixels = std::uint64_t(job.width) * std::uint64_t(job.height);
  // Per worker: a 16-byte z-buffer cell per pixel, plus 4 floats of colour sums with the flame
  // display. The merged snapshot: RGBA8, depth, density (+ colour sums), and as much again for
  // the image that is developed or written from it.
  const std::uint64_t colour = job.accumulateColor ? 16 : 0;
  const std::uint64_t perWorker = sizeof(kernel::PixelCell) + colour;
  const std::uint64_t snapshot = 4 + 4 + 4 + colour;
  std::uint64_t lightTexels = 0;  // per worker 2 bytes a texel, and the merged float copy
  for (const LightView& light : job.shadowLights)
    lightTexels += std::uint64_t(light.size()) * std::uint64_t(light.size());
  return pixels * (std::uint64_t(std::max(1, job.threads)) * perWorker + 2 * snapshot) +
         lightTexels * (2 * std::uint64_t(std::max(1, job.threads)) + 4);
}

ChaosRenderer::ChaosRenderer() : shared_(std::make_shared<Shared>()) {}

ChaosRenderer::~ChaosRenderer() { joinThreads(); }

void ChaosRenderer::joinThreads() {
  {
    std::lock_guard lock(shared_->mutex);
    shared_->quit.store(true);
  }
  shared_->wake.notify_all();
  for (std::thread& t : threads_) t.join();
  threads_.clear();
  shared_->quit.store(false);
}

void ChaosRenderer::startThreads(int count) {
  while (int(workers_.size()) < count) {
    workers_.push_back(std::make_unique<Worker>());
    workers_.back()->index = int(workers_.size()) - 1;
  }
  workers_.resize(std::size_t(count));
  for (int i = 0; i < count; ++i) threads_.emplace_back(workerMain, shared_, workers_[std::size_t(i)].get());
}

std::uint64_t ChaosRenderer::restart(std::shared_ptr<const CompiledIfs> ifs, const RenderJob& job) {
  validateRenderJob(job);
  if (!ifs) throw ModelError("", "there is no compiled IFS to render");
  auto prepared = std::make_shared<PreparedJob>(std::move(ifs), job);
  std::uint64_t generation;
  {
    std::lock_guard lock(shared_->mutex);
    generation = ++shared_->nextGeneration;
    const PreparedJob* previous = shared_->job.get();
    const bool keepCamera = previous && sameCameraPass(*previous, *prepared);
    prepared->cameraEpoch = keepCamera ? previous->cameraEpoch : generation;
    if (keepCamera) prepared->nextChunk = previous->nextChunk;  // the same chunks, none played twice
    shared_->job = prepared;
    shared_->generation.store(generation);
  }
  if (int(threads_.size()) != job.threads) {
    joinThreads();
    startThreads(job.threads);
  }
  shared_->wake.notify_all();
  shared_->startNs = nowNs();
  shared_->pausedTotalNs = 0;
  shared_->pausedAtNs = shared_->startNs;
  return generation;
}

void ChaosRenderer::stop() {
  joinThreads();
  std::lock_guard lock(shared_->mutex);
  shared_->job.reset();
  shared_->generation.store(++shared_->nextGeneration);
}

void ChaosRenderer::pause() {
  if (shared_->paused.load()) return;
  {
    std::lock_guard lock(shared_->mutex);
    shared_->paused.store(true);
  }
  shared_->pausedAtNs = nowNs();
}

void ChaosRenderer::resume() {
  if (!shared_->paused.load()) return;
  {
    std::lock_guard lock(shared_->mutex);
    shared_->paused.store(false);
  }
  shared_->pausedTotalNs += nowNs() - shared_->pausedAtNs;
  shared_->wake.notify_all();
}

bool ChaosRenderer::paused() const { return shared_->paused.load(); }

std::uint64_t ChaosRenderer::generation() const { return shared_->generation.load(); }

RenderStats ChaosRenderer::stats() const {
  RenderStats s;
  s.generation = shared_->generation.load();
  s.paused = shared_->paused.load();
  const PreparedJob* job = shared_->job.get();
  if (!job) return s;
  s.budget = job->job.samples > 0 ? rangeSamples(job->job.samples, job->chunks) : 0;
  s.keptCamera = job->cameraEpoch != s.generation;
  bool allFinished = s.budget > 0;
  std::int64_t lastFinish = 0;
  // A part with no chunk (more parts than chunks) has nothing to do: done at once, its buffers
  // empty, whether or not the workers have seen the generation yet.
  const bool emptyPart = job->job.samples > 0 && s.budget == 0;
  for (const auto& w : workers_) {
    if (w->bufferGeneration.load(std::memory_order_acquire) != s.generation) {
      allFinished = false;
      continue;
    }
    s.samples += w->samples.load(std::memory_order_acquire);
    s.badSamples += w->bad.load(std::memory_order_relaxed);
    s.plotted += w->plotted.load(std::memory_order_relaxed);
    const std::int64_t f = w->finishedNs.load(std::memory_order_acquire);
    if (f == 0) allFinished = false;
    lastFinish = std::max(lastFinish, f);
  }
  s.done = allFinished || emptyPart;
  if (emptyPart) s.samples = s.badSamples = s.plotted = 0;
  std::int64_t end = s.done ? std::max(lastFinish, shared_->startNs) : (s.paused ? shared_->pausedAtNs : nowNs());
  if (s.paused && !s.done) end = shared_->pausedAtNs;
  s.seconds = std::max(0.0, double(end - shared_->startNs - shared_->pausedTotalNs) * 1e-9);
  s.pointsPerSecond = s.seconds > 0.0 ? double(s.samples) / s.seconds : 0.0;
  return s;
}

void ChaosRenderer::accumulation(Accumulation& out) const { mergeBuffers(out, nullptr); }

void ChaosRenderer::takeAccumulation(Accumulation& out) {
  const std::uint64_t generation = shared_->generation.load();
  // The giver is the worker that played the most samples: one that found every chunk taken
  // before it started holds an empty buffer, and giving that would leave all the work to copy.
  Worker* giver = nullptr;
  if (shared_->job && shared_->job->job.accumulateColor && stats().done)
    for (const auto& w : workers_)
      if (w->bufferGeneration.load(std::memory_order_acquire) == generation &&
          (!giver || w->samples.load(std::memory_order_relaxed) > giver->samples.load(std::memory_order_relaxed)))
        giver = w.get();
  mergeBuffers(out, giver);
}

void ChaosRenderer::mergeBuffers(Accumulation& out, Worker* giver) const {
  const std::uint64_t generation = shared_->generation.load();
  const PreparedJob* job = shared_->job.get();
  const RenderStats s = stats();
  out = Accumulation{};
  if (!job) return;
  const int width = job->job.width, height = job->job.height;
  const std::size_t n = std::size_t(width) * std::size_t(height);
  out.width = width;
  out.height = height;
  std::vector<const Worker*> ready;
  for (const auto& w : workers_)
    if (w->bufferGeneration.load(std::memory_order_acquire) == generation) ready.push_back(w.get());

  // The workers' buffers combine by minimum (keys) and integer sums (counts, colour sums), which
  // do not depend on the order of the workers or on which chunks each one played.
  if (job->job.depthKeys)
    out.keys.assign(n, kEmptyKey);
  else
    out.keys.clear();  // RenderJob::depthKeys: the flame display's job keeps none
  out.density.assign(n, 0);
  auto keyOf = [](const kernel::PixelCell& c) {
    return std::atomic_ref<const std::uint64_t>(c.key).load(std::memory_order_relaxed);
  };
  auto countOf = [](const kernel::PixelCell& c) {
    return std::uint64_t(std::atomic_ref<const std::uint32_t>(c.density).load(std::memory_order_relaxed));
  };
  for (const Worker* w : ready) {
    const kernel::PixelCell* cells = w->cells.data();
    if (!out.keys.empty())
      for (std::size_t i = 0; i < n; ++i) out.keys[i] = std::min(out.keys[i], keyOf(cells[i]));
    for (std::size_t i = 0; i < n; ++i)
      out.density[i] = std::uint32_t(std::min<std::uint64_t>(out.density[i] + countOf(cells[i]), 0xFFFFFFFFu));
  }
  // The giver's sums become the total's start: no second 32 MB at 1024², and no pass to copy it.
  Worker* const from = job->job.accumulateColor && giver && giver->colorSums.size() == n * 4 &&
                               std::find(ready.begin(), ready.end(), giver) != ready.end()
                           ? giver
                           : nullptr;
  if (job->job.accumulateColor) {
    if (from)
      out.colorSums = std::move(from->colorSums);
    else
      out.colorSums.assign(n * 4, 0);
    for (const Worker* w : ready) {
      if (w == from) continue;
      for (std::size_t i = 0; i < n * 4; ++i)
        out.colorSums[i] += std::atomic_ref<const std::uint64_t>(w->colorSums[i]).load(std::memory_order_relaxed);
    }
  }
  // The light depth buffers: the nearest sample per texel over all workers.
  out.lightViews = job->job.shadowLights;
  out.lightDepth.resize(out.lightViews.size());
  for (std::size_t l = 0; l < out.lightViews.size(); ++l) {
    const std::size_t texels = std::size_t(out.lightViews[l].size()) * std::size_t(out.lightViews[l].size());
    std::vector<std::uint16_t>& merged = out.lightDepth[l];
    merged.assign(texels, kernel::kLightEmpty);
    for (const Worker* w : ready) {
      const std::uint16_t* src = w->lightDepth[l].data();
      for (std::size_t i = 0; i < texels; ++i)
        merged[i] = std::min(merged[i], std::atomic_ref<const std::uint16_t>(src[i]).load(std::memory_order_relaxed));
    }
  }
  out.samples = s.samples;
  out.badSamples = s.badSamples;
  out.plotted = s.plotted;
  // Its colour sums are gone: a later accumulation() or snapshot() leaves the giver out.
  if (from) from->bufferGeneration.store(0, std::memory_order_release);
}

void ChaosRenderer::snapshot(RenderImage& out, const DisplaySettings& display) const {
  Accumulation merged;
  accumulation(merged);
  const RenderStats s = stats();
  if (!shared_->job) {
    out.clear();
  } else {
    toRenderImage(merged, display, out);
  }
  out.generation = s.generation;
  out.stats = s;
}

void shadeRenderImage(RenderImage& out, const DisplaySettings& display) {
  const std::size_t n = std::size_t(out.width) * std::size_t(out.height);
  std::uint32_t* packed = reinterpret_cast<std::uint32_t*>(out.rgba.data());
  const std::int64_t hits = out.hitPixels;
  const float minDepth = out.minDepth, maxDepth = out.maxDepth;
  // Pass 2: depth cueing (Gröller & Wegenkittl 1994, §3.1: colours attenuated with distance) over the depth range
  // of this image, and the background where nothing was plotted.
  const float cue = float(std::clamp(display.depthCue, 0.0, 1.0));
  const float range = maxDepth - minDepth;
  const float scale = hits && range > 0.0f ? cue / range : 0.0f;
  std::uint8_t bg[4] = {0, 0, 0, 0};
  for (int c = 0; c < 3; ++c) bg[c] = std::uint8_t(std::lround(std::clamp(display.background[c], 0.0, 1.0) * 255.0));
  std::uint32_t background;
  std::memcpy(&background, bg, 4);
  for (std::size_t i = 0; i < n; ++i) {
    const float depth = out.depth[i];
    if (depth == std::numeric_limits<float>::infinity()) {
      packed[i] = background;
      continue;
    }
    const float attenuation = 1.0f - (depth - minDepth) * scale;
    const std::uint32_t p = packed[i];
    std::uint32_t result = 0xFF000000u;  // alpha 255
    for (int c = 0; c < 3; ++c) {
      const float v = float((p >> (8 * c)) & 0xFFu) * attenuation + 0.5f;
      result |= std::uint32_t(std::min(255.0f, v)) << (8 * c);
    }
    packed[i] = result;  // bytes r, g, b, a in memory (little-endian)
  }
}

RenderImage ChaosRenderer::snapshot(const DisplaySettings& display) const {
  RenderImage image;
  snapshot(image, display);
  return image;
}

bool ChaosRenderer::waitUntilDone(const std::function<bool(const RenderStats&)>& progress, double intervalSeconds) {
  return waitForBudget(progress, intervalSeconds, [this](double seconds) {
    std::unique_lock lock(shared_->mutex);
    shared_->finished.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return stats().done; });
    return true;  // the next stats() have no budget once the job is gone
  });
}

RenderImage renderToCompletion(std::shared_ptr<const CompiledIfs> ifs, const RenderJob& job,
                               const DisplaySettings& display,
                               const std::function<bool(const RenderStats&)>& progress) {
  if (job.samples <= 0) throw ModelError("render.samples", "must be at least 1");
  ChaosRenderer renderer;
  renderer.restart(std::move(ifs), job);
  if (!renderer.waitUntilDone(progress)) throw RenderCancelled();
  return renderer.snapshot(display);
}

Accumulation accumulateToCompletion(std::shared_ptr<const CompiledIfs> ifs, const RenderJob& job,
                                    const std::function<bool(const RenderStats&)>& progress) {
  if (job.samples <= 0) throw ModelError("render.samples", "must be at least 1");
  ChaosRenderer renderer;
  renderer.restart(std::move(ifs), job);
  if (!renderer.waitUntilDone(progress)) throw RenderCancelled();
  Accumulation acc;
  renderer.takeAccumulation(acc);
  return acc;
}

namespace {

/// Collects points instead of plotting them (export-points).
struct PointPlot {
  std::vector<float>* xyz;
  std::vector<float>* rgb;
  [[gnu::always_inline]] int operator()(kernel::v4f q, kernel::v4f col) const {
    xyz->insert(xyz->end(), {q[0], q[1], q[2]});
    rgb->insert(rgb->end(),
                {std::clamp(col[0], 0.0f, 1.0f), std::clamp(col[1], 0.0f, 1.0f), std::clamp(col[2], 0.0f, 1.0f)});
    return 1;
  }
};

}  // namespace

RenderStats generatePoints(const CompiledIfs& ifs, const RenderJob& job,
                           const std::function<bool(const PointBatch&, const RenderStats&)>& sink) {
  if (job.samples <= 0) throw ModelError("render.samples", "must be at least 1");
  if (job.samples > limits::kMaxRenderSamples)
    throw ModelError("render.samples", "more than the limit of " + std::to_string(limits::kMaxRenderSamples));
  if (job.threads < 1 || job.threads > limits::kMaxRenderThreads)
    throw ModelError("render", "the thread count must be between 1 and " + std::to_string(limits::kMaxRenderThreads));
  RenderJob pointJob = job;
  pointJob.width = pointJob.height = 1;  // no image; the camera is not used
  const PreparedJob prepared(std::shared_ptr<const CompiledIfs>(&ifs, [](const CompiledIfs*) {}), pointJob);
  RenderStats stats;
  stats.budget = job.samples;
  const std::int64_t start = nowNs();
  const kernel::DenormalsAreZero flushDenormals;  // as the renderer's workers do
  std::vector<float> xyz, rgb;
  constexpr std::int64_t kPointBatch = 1 << 16;
  static_assert(kPointBatch % kernel::kLanes == 0);
  xyz.reserve(kPointBatch * 3);
  rgb.reserve(kPointBatch * 3);
  // The chunks in order: the same samples as the renderer plots, whatever the thread count.
  const ChunkRange chunks = jobChunks(job);
  auto bary = std::make_unique<kernel::BarycentricState>();
  for (std::int64_t c = chunks.begin; c < chunks.end; ++c) {
    kernel::ChainState chain = kernel::ChainState::start(job.seed, std::uint64_t(c), job.skip);
    if (prepared.hotIfs.barycentricBlocks) bary->start(chain, prepared.hotIfs);
    kernel::ChainCounters counters;
    PointPlot plot{&xyz, &rgb};
    for (std::int64_t remaining = jobChunkSize(job, c); remaining > 0;) {
      const std::int64_t n = std::min(remaining, kPointBatch);
      xyz.clear();
      rgb.clear();
      const kernel::ChainCounters before = counters;
      if (prepared.hotIfs.barycentricBlocks)
        kernel::runBarycentricChain(chain, *bary, prepared.hotIfs, n, plot, counters);
      else
        kernel::runChain(chain, prepared.hotIfs, n, plot, counters);
      remaining -= n;
      stats.samples += counters.samples - before.samples;
      stats.badSamples += counters.bad - before.bad;
      stats.plotted += counters.plotted - before.plotted;
      stats.seconds = double(nowNs() - start) * 1e-9;
      stats.pointsPerSecond = stats.seconds > 0 ? double(stats.samples) / stats.seconds : 0.0;
      stats.done = c + 1 == chunks.end && remaining == 0;
      if (!sink(PointBatch{xyz.data(), rgb.data(), xyz.size() / 3}, stats)) return stats;
    }
  }
  return stats;
}

}  // namespace gridifs
