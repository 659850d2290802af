// Chaos-game speed: the canonical scene — 3 functions, 16×16×16 grids with
// non-trivial distortions, 1024×1024 z-buffer + density, perspective camera — with 1 and 2 render
// threads, the plot-only limit (random scattered z-buffer + density writes at 1024²) and the preview
// latency (first image with points after a restart). scripts/bench-vs-flam3 runs this next to
// flam3-render and prints the ratios.
#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>
#include <optional>
#include <thread>

#include "freeform/free_form_presets.h"
#include "render/barycentric_kernel.h"
#include "render/chaos_kernel.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "tests/bench/canonical_scene.h"
#include "tests/bench/process_cpu_time.h"
#include "tone/palette.h"

namespace gridifs {
namespace {

const std::shared_ptr<const CompiledIfs>& canonicalIfs() {
  static const auto ifs = compileIfs(canonicalScene());
  return ifs;
}

/// The full renderer (worker pool, per-thread buffers) for a fixed budget; items = samples.
void BM_ChaosRender(benchmark::State& state) {
  const int threads = int(state.range(0));
  RenderJob job = RenderJob::fromProject(canonicalScene(), threads);
  job.samples = 30'000'000 * std::int64_t(threads);
  ChaosRenderer renderer;
  std::int64_t samples = 0;
  double computeSeconds = 0.0, cpuSeconds = 0.0;
  for (auto _ : state) {
    const double cpu0 = processCpuSeconds();
    renderer.restart(canonicalIfs(), job);
    renderer.waitUntilDone({}, 0.005);
    cpuSeconds += processCpuSeconds() - cpu0;
    const RenderStats s = renderer.stats();
    samples += s.samples;
    computeSeconds += s.seconds;
    state.counters["bad_fraction"] = s.badFraction();
    state.counters["plotted_fraction"] = double(s.plotted) / double(s.samples);
  }
  state.SetItemsProcessed(samples);
  state.counters["points_per_second"] = samples / computeSeconds;
  state.counters["points_per_16ms_per_thread"] = samples / computeSeconds * 0.016 / threads;
  // Per CPU second of the whole process: what one core delivers, less sensitive to other load.
  state.counters["points_per_cpu_second"] = samples / cpuSeconds;
}
/// 1 and 2 threads everywhere (the ratio the docs compare), then powers of two up to the machine's
/// cores: the scaling figure (16 threads against one) comes from a 16-core machine.
void renderThreadCounts(benchmark::internal::Benchmark* b) {
  const int cores = int(std::thread::hardware_concurrency());
  for (int threads = 1; threads <= 64; threads *= 2)
    if (threads <= 2 || threads <= cores) b->Arg(threads);
}
BENCHMARK(BM_ChaosRender)->Apply(renderThreadCounts)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

GRIDIFS_KERNEL_CLONES void runKernel(kernel::ChainState& chain, const kernel::HotIfs& ifs, std::int64_t count,
                                     kernel::ZBufferPlot<false>& plot, kernel::ChainCounters& counters) {
  kernel::runChain(chain, ifs, count, plot, counters);
}

GRIDIFS_KERNEL_CLONES void runKernel(kernel::ChainState& chain, const kernel::HotIfs& ifs, std::int64_t count,
                                     kernel::ZBufferPlot<true>& plot, kernel::ChainCounters& counters) {
  kernel::runChain(chain, ifs, count, plot, counters);
}

/// The canonical scene varied: 0 as is (palette indices 0, 0.5, 1), 1 every palette index 0
/// (the default of a new function), 2 an all-red IFS (green and blue 0 in every function), 3 with
/// a transition matrix in which no function follows itself (the Markov-chain walk), 4 as 0 walked
/// as a Markov chain whose every row is the weights (an all-ones matrix: the same attractor, so
/// 0 against 4 is the cost of the walk alone). In 1 and 2 a colour channel decays towards 0 and,
/// without flushing, sits on a denormal.
Project kernelScene(int variant) {
  Project p = canonicalScene();
  for (Function& f : p.functions) {
    if (variant == 1) f.palette_index = 0.0;
    if (variant == 2) f.color = Vec3{1.0, 0.0, 0.0};
  }
  if (variant == 3) {
    const std::size_t n = p.functions.size();
    p.transitions.assign(n, std::vector<double>(n, 1.0));
    for (std::size_t i = 0; i < n; ++i) p.transitions[i][i] = 0.0;
  }
  return p;
}

/// The kernel alone on the calling thread (no pool) for scene `variant` (see kernelScene), with
/// denormals flushed as the renderer's workers do (`flush` 1) or not (0); with `flameColours`
/// the flame display's palette colour sums too (a 1024² sum buffer, the ember palette).
void runKernelBenchmark(benchmark::State& state, int variant, bool flush, bool flameColours = false) {
  const Project scene = kernelScene(variant);
  const RenderJob job = RenderJob::fromProject(scene, 1);
  const auto compiled = compileIfs(scene);
  const auto& ifs = *compiled;
  std::vector<kernel::HotFunction> hot;
  kernel::HotIfs hotIfs = kernel::makeHotIfs(ifs, hot, job.skip, limits::kEscapeBound);
  // compileIfs drops an all-ones matrix (it restricts nothing); variant 4 walks its rows anyway:
  // every row is the weights' alias table.
  std::vector<TransitionStep> onesWalk;
  if (variant == 4) {
    const auto n = std::uint32_t(hot.size());
    for (std::uint32_t row = 0; row <= n; ++row)
      for (std::uint32_t c = 0; c < n; ++c)
        onesWalk.push_back({ifs.alias[c].threshold, ifs.alias[c].alias, (c + 1) * n, (ifs.alias[c].alias + 1) * n});
    hotIfs.transitionWalk = onesWalk.data();
  }
  const kernel::HotCamera cam = kernel::makeHotCamera(OrbitCamera(job.camera, job.width, job.height));
  std::vector<kernel::PixelCell> cells(std::size_t(job.width) * job.height);
  std::vector<std::uint64_t> sums(flameColours ? cells.size() * 4 : 0);
  std::vector<kernel::v4f> palette;
  for (const Rgb& c : builtinPalette("ember").colors) palette.push_back(kernel::v4f{c.r, c.g, c.b, 0.0f});
  palette.push_back(palette.back());
  kernel::ZBufferPlot<false> plot{cam, cells.data(), nullptr};
  kernel::ZBufferPlot<true> flamePlot{cam, cells.data(), sums.data(), palette.data()};
  kernel::ChainState chain = kernel::ChainState::start(1, 0, job.skip);
  kernel::ChainCounters counters;
  std::optional<kernel::DenormalsAreZero> flushDenormals;
  if (flush) flushDenormals.emplace();
  const double cpu0 = processCpuSeconds();
  for (auto _ : state) {
    if (flameColours)
      runKernel(chain, hotIfs, 1 << 22, flamePlot, counters);
    else
      runKernel(chain, hotIfs, 1 << 22, plot, counters);
  }
  state.SetItemsProcessed(counters.samples);
  state.counters["points_per_cpu_second"] = double(counters.samples) / (processCpuSeconds() - cpu0);
  state.counters["plotted_fraction"] = double(counters.plotted) / double(counters.samples);
}

/// Points per CPU second, robust to a busy machine. Arg 0: no transition matrix; 1: no function
/// follows itself; 2: an all-ones matrix walked as a Markov chain (same attractor as 0).
void BM_Kernel(benchmark::State& state) {
  static const int kVariant[] = {0, 3, 4};
  runKernelBenchmark(state, kVariant[state.range(0)], true);
}
BENCHMARK(BM_Kernel)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->MinTime(1.0);

/// The z-buffer (arg 0) against the flame display's colour sums (arg 1), same scene and thread.
void BM_KernelFlame(benchmark::State& state) { runKernelBenchmark(state, 0, true, state.range(0) == 1); }
BENCHMARK(BM_KernelFlame)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(1.0);

/// The denormal pair: every colour variant at the same rate with flushing (within noise), and the
/// stall it prevents without (args: variant, flush).
void BM_KernelColours(benchmark::State& state) { runKernelBenchmark(state, int(state.range(0)), state.range(1) != 0); }
BENCHMARK(BM_KernelColours)
    ->ArgNames({"variant", "flush"})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Args({2, 1})
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({2, 0})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0);

GRIDIFS_KERNEL_CLONES void runFreeFormKernel(kernel::ChainState& chain, kernel::BarycentricState& bary,
                                             const kernel::HotIfs& ifs, std::int64_t count,
                                             kernel::ZBufferPlot<false>& plot, kernel::ChainCounters& counters) {
  kernel::runBarycentricChain(chain, bary, ifs, count, plot, counters);
}

/// A free-form IFS in the kernel (Thollot et al. 1997, §3.1), on the canonical scene's camera and
/// buffers: arg 4, the cubic Bézier curve (2 matrices, m = 4); arg 16, the bicubic patch (4
/// matrices, m = 16). Compare points_per_cpu_second with BM_Kernel/0 (three 16³ grids).
void BM_FreeFormKernel(benchmark::State& state) {
  Project scene = canonicalScene();
  applyFreeFormPreset(scene, state.range(0) == 4 ? FreeFormPreset::BezierCurve : FreeFormPreset::BezierPatch);
  const RenderJob job = RenderJob::fromProject(scene, 1);
  const auto compiled = compileIfs(scene);
  const auto& ifs = *compiled;
  std::vector<kernel::HotFunction> hot;
  const kernel::HotIfs hotIfs = kernel::makeHotIfs(ifs, hot, job.skip, limits::kEscapeBound);
  const kernel::HotCamera cam = kernel::makeHotCamera(OrbitCamera(job.camera, job.width, job.height));
  std::vector<kernel::PixelCell> cells(std::size_t(job.width) * job.height);
  kernel::ZBufferPlot<false> plot{cam, cells.data(), nullptr};
  kernel::ChainState chain = kernel::ChainState::start(1, 0, job.skip);
  auto bary = std::make_unique<kernel::BarycentricState>();
  bary->start(chain, hotIfs);
  kernel::ChainCounters counters;
  const kernel::DenormalsAreZero flushDenormals;
  const double cpu0 = processCpuSeconds();
  for (auto _ : state) runFreeFormKernel(chain, *bary, hotIfs, 1 << 22, plot, counters);
  state.SetItemsProcessed(counters.samples);
  state.counters["points_per_cpu_second"] = double(counters.samples) / (processCpuSeconds() - cpu0);
  state.counters["plotted_fraction"] = double(counters.plotted) / double(counters.samples);
}
BENCHMARK(BM_FreeFormKernel)->Arg(4)->Arg(16)->Unit(benchmark::kMillisecond)->MinTime(1.0);

/// The plot-only limit: the same RNG, random pixels of a 1024² z-buffer + density (the renderer's
/// 16-byte cells), no function evaluation. One thread; the canonical scene's plotted fraction is close to 1.
void BM_PlotOnly(benchmark::State& state) {
  const int width = 1024, height = 1024;
  std::vector<kernel::PixelCell> cells(std::size_t(width) * height);
  kernel::Rng rng = kernel::Rng::forStream(1, 0);
  std::int64_t items = 0;
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    constexpr int kCount = 1 << 22;
    for (int n = 0; n < kCount; ++n) {
      const std::uint64_t r = rng.next();
      const std::size_t pixel = std::size_t((std::uint64_t(std::uint32_t(r)) * (std::uint64_t(width) * height)) >> 32);
      const std::uint64_t key = (r >> 32) | 0x3F80000000000000ull;
      std::atomic_ref<std::uint64_t> z(cells[pixel].key);
      if (key < z.load(std::memory_order_relaxed)) z.store(key, std::memory_order_relaxed);
      std::atomic_ref<std::uint32_t> d(cells[pixel].density);
      const std::uint32_t c = d.load(std::memory_order_relaxed);
      d.store(c + (c != 0xFFFFFFFFu), std::memory_order_relaxed);
    }
    items += kCount;
  }
  benchmark::DoNotOptimize(cells.data());
  state.SetItemsProcessed(items);  // per CPU second, like BM_Kernel
  state.counters["wall_points_per_second"] =
      double(items) / std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
BENCHMARK(BM_PlotOnly)->Unit(benchmark::kMillisecond)->MinTime(1.0);

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// Preview latency: with the renderer running (unlimited budget), time from restart() with an
/// edited snapshot until snapshot() first returns an image of the new generation with points.
void BM_FirstImageAfterRestart(benchmark::State& state) {
  const int threads = int(state.range(0));
  RenderJob job = RenderJob::fromProject(canonicalScene(), threads);
  job.samples = 0;
  Project edited = canonicalScene();
  edited.functions[0].placement.rotate.x += 5.0;
  const auto a = canonicalIfs(), b = compileIfs(edited);
  ChaosRenderer renderer;
  renderer.restart(a, job);
  RenderImage image;
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  double worst = 0.0, total = 0.0, snapshotTotal = 0.0, snapshotCpu = 0.0;
  int count = 0, snapshots = 0;
  bool flip = false;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::uint64_t generation = renderer.restart(flip ? a : b, job);
    flip = !flip;
    for (;;) {
      const auto s0 = std::chrono::steady_clock::now();
      const double c0 = threadCpuSeconds();
      renderer.snapshot(image, DisplaySettings{});
      snapshotCpu += threadCpuSeconds() - c0;
      snapshotTotal += std::chrono::duration<double>(std::chrono::steady_clock::now() - s0).count();
      ++snapshots;
      if (image.generation == generation && image.hitPixels > 0) break;
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    worst = std::max(worst, ms);
    total += ms;
    ++count;
    std::this_thread::sleep_for(std::chrono::milliseconds(16));  // a frame of rendering
  }
  state.counters["first_image_ms_mean"] = total / count;
  state.counters["first_image_ms_worst"] = worst;
  state.counters["snapshot_ms_mean"] = 1e3 * snapshotTotal / snapshots;
  state.counters["snapshot_cpu_ms_mean"] = 1e3 * snapshotCpu / snapshots;
}
BENCHMARK(BM_FirstImageAfterRestart)->Arg(2)->Iterations(40)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace gridifs

BENCHMARK_MAIN();
