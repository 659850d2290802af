#include "gpu/gpu_chaos_renderer.h"

#include "render/accumulation.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <limits>
#include <map>
#include <mutex>

#include "gpu/chaos_compute.h"

namespace gridifs::gpu {
namespace {

std::int64_t nowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

/// While rendering, the thread reads the buffers back at most this often for snapshot().
constexpr std::int64_t kReadbackIntervalNs = 50'000'000;

}  // namespace

struct GpuChaosRenderer::Shared {
  std::mutex mutex;
  std::condition_variable wake, answered, finished;
  Options options;
  // Set once by the thread before `ready`.
  GpuInfo info;
  std::string deviceName, startError;
  bool ready = false;
  // Controller → thread (under mutex).
  bool quit = false, paused = false, stopPending = false, readbackWanted = false;
  bool jobPending = false;
  std::shared_ptr<const CompiledIfs> pendingIfs;
  RenderJob pendingJob;
  std::uint64_t pendingGeneration = 0;
  // Thread → controller (under mutex).
  bool setupAnswered = false;
  std::string setupError;
  ChaosReadback staged;  // the last read-back, of staged.generation
  bool exactDepth = false;
  std::int64_t finishedNs = 0;
  bool done = false;
  std::atomic<std::int64_t> samples{0};
  // Controller only.
  std::atomic<std::uint64_t> generation{0};
  std::uint64_t nextGeneration = 0;
  bool hasJob = false;
  RenderJob job;
  std::int64_t budget = 0;  // the samples of job's chains (a part's share)
  std::int64_t startNs = 0, pausedAtNs = 0, pausedTotalNs = 0;
};

namespace {

void rendererThread(std::shared_ptr<GpuChaosRenderer::Shared> shared) {
  std::unique_ptr<HeadlessGlContext> context;
  try {
    context = HeadlessGlContext::create();
  } catch (const GpuUnavailable& e) {
    std::lock_guard lock(shared->mutex);
    shared->startError = e.what();
    shared->ready = true;
    shared->answered.notify_all();
    return;
  }
  {
    std::lock_guard lock(shared->mutex);
    shared->info = context->info();
    shared->deviceName = "gpu (" + shared->info.renderer + ")";
    shared->ready = true;
  }
  shared->answered.notify_all();

  std::map<bool, std::unique_ptr<ChaosCompute>> programs;  // by accumulateColor
  ChaosCompute* compute = nullptr;
  std::uint64_t generation = 0;
  std::uint32_t iterations = 1;
  std::int64_t lastReadback = 0;
  ChaosReadback scratch;
  auto stage = [&](bool final) {
    compute->readback(scratch);
    scratch.generation = generation;
    std::lock_guard lock(shared->mutex);
    std::swap(shared->staged, scratch);
    shared->readbackWanted = false;
    if (final) {
      shared->samples.store(shared->staged.samples);
      shared->done = true;
      shared->finishedNs = nowNs();
    }
    lastReadback = nowNs();
  };
  for (;;) {
    std::unique_lock lock(shared->mutex);
    shared->wake.wait(lock, [&] {
      return shared->quit || shared->jobPending || shared->stopPending ||
             (compute && !shared->paused && !compute->finished()) || (compute && shared->readbackWanted);
    });
    if (shared->quit) break;
    if (shared->stopPending) {
      shared->stopPending = false;
      compute = nullptr;
      continue;
    }
    if (shared->jobPending) {
      shared->jobPending = false;
      auto ifs = std::move(shared->pendingIfs);
      const RenderJob job = shared->pendingJob;
      generation = shared->pendingGeneration;
      lock.unlock();
      std::string error;
      bool empty = false;
      try {
        auto& program = programs[job.accumulateColor];
        if (!program)
          program = std::make_unique<ChaosCompute>(shared->info, ChaosOutput::Image, job.accumulateColor,
                                                   shared->options.allowAtomic64);
        program->setup(*ifs, job, chainsOf(job, shared->info.software));
        compute = program.get();
        // A part with no chains (more parts than the job has chains) is done at once: its
        // accumulation (the cleared buffers) is staged before restart() returns, so that
        // waitUntilDone never sees an unfinished job without a budget.
        empty = compute->finished();
        if (empty) {
          compute->readback(scratch);
          scratch.generation = generation;
        }
      } catch (const GpuUnavailable& e) {
        error = e.what();
        compute = nullptr;
      }
      lock.lock();
      shared->setupError = error;
      shared->setupAnswered = true;
      shared->done = false;
      shared->finishedNs = 0;
      shared->samples.store(0);
      shared->exactDepth = compute && compute->atomic64();
      iterations = 1;
      lastReadback = 0;
      if (empty) {
        std::swap(shared->staged, scratch);
        shared->samples.store(shared->staged.samples);
        shared->done = true;
        shared->finishedNs = nowNs();
      }
      shared->answered.notify_all();
      if (empty) shared->finished.notify_all();
      continue;
    }
    const bool run = !shared->paused && !compute->finished();
    lock.unlock();
    if (run) {
      const std::int64_t t0 = nowNs();
      compute->dispatch(iterations);
      compute->finish();
      const double seconds = double(nowNs() - t0) * 1e-9;
      // The next slice aims at sliceSeconds (at most twice as long as this one).
      const double scale = std::min(2.0, shared->options.sliceSeconds / std::max(seconds, 1e-6));
      iterations = std::uint32_t(std::clamp(double(iterations) * scale, 1.0, 65536.0));
      if (compute->finished()) {
        stage(true);
        shared->finished.notify_all();
        continue;
      }
      shared->samples.store(compute->samplesDone());
      bool want;
      {
        std::lock_guard guard(shared->mutex);
        want = shared->readbackWanted;
      }
      if (want && nowNs() - lastReadback >= kReadbackIntervalNs) stage(false);
    } else {
      stage(false);
    }
  }
  programs.clear();
}

}  // namespace

GpuChaosRenderer::GpuChaosRenderer(Options options) : shared_(std::make_shared<Shared>()) {
  shared_->options = options;
  thread_ = std::thread(rendererThread, shared_);
  std::unique_lock lock(shared_->mutex);
  shared_->answered.wait(lock, [&] { return shared_->ready; });
  if (!shared_->startError.empty()) {
    const std::string error = shared_->startError;
    lock.unlock();
    thread_.join();
    throw GpuUnavailable(error);
  }
}

GpuChaosRenderer::~GpuChaosRenderer() {
  {
    std::lock_guard lock(shared_->mutex);
    shared_->quit = true;
  }
  shared_->wake.notify_all();
  if (thread_.joinable()) thread_.join();
}

const GpuInfo& GpuChaosRenderer::info() const { return shared_->info; }

bool GpuChaosRenderer::exactDepth() const {
  std::lock_guard lock(shared_->mutex);
  return shared_->exactDepth;
}

const char* GpuChaosRenderer::deviceName() const { return shared_->deviceName.c_str(); }

std::uint64_t GpuChaosRenderer::restart(std::shared_ptr<const CompiledIfs> ifs, const RenderJob& job) {
  validateRenderJob(job);
  if (!ifs) throw ModelError("", "there is no compiled IFS to render");
  if (ifs->functions.empty() || ifs->alias.size() != ifs->functions.size())
    throw ModelError("functions", "no unmuted function has a positive weight");
  if (job.part && (job.part->count < 1 || job.part->index < 0 || job.part->index >= job.part->count))
    throw ModelError("render", "part " + std::to_string(job.part->index) + " of " + std::to_string(job.part->count) +
                                   " is not a part of a render");
  std::unique_lock lock(shared_->mutex);
  const std::uint64_t generation = ++shared_->nextGeneration;
  shared_->pendingIfs = std::move(ifs);
  shared_->pendingJob = job;
  shared_->pendingGeneration = generation;
  shared_->jobPending = true;
  shared_->stopPending = false;
  shared_->setupAnswered = false;
  shared_->generation.store(generation);
  shared_->wake.notify_all();
  shared_->answered.wait(lock, [&] { return shared_->setupAnswered; });
  shared_->startNs = nowNs();
  shared_->pausedTotalNs = 0;
  shared_->pausedAtNs = shared_->startNs;
  if (!shared_->setupError.empty()) {
    shared_->hasJob = false;
    throw GpuUnavailable(shared_->setupError);
  }
  shared_->hasJob = true;
  shared_->job = job;
  shared_->budget = chainBudget(job, chainsOf(job, shared_->info.software));
  return generation;
}

void GpuChaosRenderer::stop() {
  std::lock_guard lock(shared_->mutex);
  shared_->stopPending = true;
  shared_->hasJob = false;
  shared_->generation.store(++shared_->nextGeneration);
  shared_->wake.notify_all();
}

void GpuChaosRenderer::pause() {
  std::lock_guard lock(shared_->mutex);
  if (shared_->paused) return;
  shared_->paused = true;
  shared_->pausedAtNs = nowNs();
}

void GpuChaosRenderer::resume() {
  std::lock_guard lock(shared_->mutex);
  if (!shared_->paused) return;
  shared_->paused = false;
  shared_->pausedTotalNs += nowNs() - shared_->pausedAtNs;
  shared_->wake.notify_all();
}

bool GpuChaosRenderer::paused() const {
  std::lock_guard lock(shared_->mutex);
  return shared_->paused;
}

std::uint64_t GpuChaosRenderer::generation() const { return shared_->generation.load(); }

RenderStats GpuChaosRenderer::stats() const {
  std::lock_guard lock(shared_->mutex);
  RenderStats s;
  s.generation = shared_->generation.load();
  s.paused = shared_->paused;
  if (!shared_->hasJob) return s;
  s.budget = shared_->budget;
  s.samples = shared_->samples.load();
  if (shared_->staged.generation == s.generation) {
    s.badSamples = shared_->staged.bad;
    s.plotted = shared_->staged.plotted;
  }
  s.done = shared_->done;
  const std::int64_t end = s.done ? shared_->finishedNs : (s.paused ? shared_->pausedAtNs : nowNs());
  s.seconds = std::max(0.0, double(end - shared_->startNs - shared_->pausedTotalNs) * 1e-9);
  s.pointsPerSecond = s.seconds > 0.0 ? double(s.samples) / s.seconds : 0.0;
  return s;
}

void readbackToAccumulation(const ChaosReadback& r, bool accumulateColor, Accumulation& out) {
  const std::size_t n = std::size_t(r.width) * std::size_t(r.height);
  out = Accumulation{};
  out.width = r.width;
  out.height = r.height;
  out.density = r.density;
  out.density.resize(n, 0);
  if (r.atomic64) {
    out.keys = r.keys64;
    out.keys.resize(n, ~std::uint64_t(0));
  } else {
    out.keys32 = r.keys32;
    out.keys32.resize(n, 0xFFFFFFFFu);
    out.depthMin = r.depthMin;
    out.depthScale = r.depthScale;
  }
  if (accumulateColor) {
    out.colorSums.assign(n * 4, 0);
    if (r.colorSums.size() == n * 8)
      for (std::size_t i = 0; i < n * 4; ++i)
        out.colorSums[i] = std::uint64_t(r.colorSums[2 * i + 1]) << 32 | r.colorSums[2 * i];
  }
  out.samples = r.samples;
  out.badSamples = r.bad;
  out.plotted = r.plotted;
}

void readbackToImage(const ChaosReadback& r, bool accumulateColor, RenderImage& out, const DisplaySettings& display) {
  Accumulation acc;
  readbackToAccumulation(r, accumulateColor, acc);
  toRenderImage(acc, display, out);
}

void GpuChaosRenderer::accumulation(Accumulation& out) const {
  const RenderStats s = stats();
  std::lock_guard lock(shared_->mutex);
  if (!shared_->hasJob) {
    out = Accumulation{};
    return;
  }
  ChaosReadback empty;
  const bool current = shared_->staged.generation == s.generation;
  if (!current) {
    empty.width = shared_->job.width;
    empty.height = shared_->job.height;
  }
  readbackToAccumulation(current ? shared_->staged : empty, shared_->job.accumulateColor, out);
}

void GpuChaosRenderer::snapshot(RenderImage& out, const DisplaySettings& display) const {
  const RenderStats s = stats();
  std::lock_guard lock(shared_->mutex);
  if (!shared_->hasJob) {
    out.clear();
    out.generation = s.generation;
    out.stats = s;
    return;
  }
  if (!shared_->done) {
    shared_->readbackWanted = true;
    shared_->wake.notify_all();
  }
  ChaosReadback empty;
  const bool current = shared_->staged.generation == s.generation;
  if (!current) {
    empty.width = shared_->job.width;
    empty.height = shared_->job.height;
  }
  readbackToImage(current ? shared_->staged : empty, shared_->job.accumulateColor, out, display);
  out.generation = s.generation;
  out.stats = s;
}

bool GpuChaosRenderer::waitUntilDone(const std::function<bool(const RenderStats&)>& progress, double intervalSeconds) {
  return waitForBudget(progress, intervalSeconds, [this](double seconds) {
    std::unique_lock lock(shared_->mutex);
    shared_->finished.wait_for(lock, std::chrono::duration<double>(seconds),
                               [&] { return shared_->done || !shared_->hasJob; });
    return shared_->hasJob;
  });
}

}  // namespace gridifs::gpu
