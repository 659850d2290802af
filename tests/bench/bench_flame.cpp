// Flame display speed: tone mapping + filters (log density, density estimation,
// spatial filter, gamma/vibrancy) at 1024² and 4096² against the chaos game that fills the
// histogram, on assets/twisted_functions.gridifs (3D, perspective) with color accumulation and
// per-sample palette lookup. The filters must not dominate a final render.
//
// Chaos-game cost is linear in samples, so the benchmark measures the rate once per size and
// prints, after the runs, develop time ÷ chaos time for a final render at a given quality
// (samples per output pixel): 25 (the project default, 20M samples at 1024×768) and 100.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <map>

#include "io/project_io.h"
#include "render/compiled_ifs.h"
#include "render/flame_render.h"

namespace gridifs {
namespace {

constexpr int kThreads = 2;

struct Scene {
  Project project;
  std::shared_ptr<const CompiledIfs> ifs;
  std::shared_ptr<const Palette> palette;
};

const Scene& scene() {
  static const Scene s = [] {
    Scene sc;
    sc.project = loadProject(std::string(GRIDIFS_ASSETS) + "/twisted_functions.gridifs");
    sc.ifs = compileIfs(sc.project);
    sc.palette = std::make_shared<const Palette>(builtinPalette("ember"));
    return sc;
  }();
  return s;
}

RenderJob jobFor(int size, std::int64_t samples) {
  Project p = scene().project;
  p.render.width = p.render.height = size;
  p.render.samples = samples;
  return flameRenderJob(p, scene().palette, kThreads);
}

std::map<int, std::map<long long, double>> gChaos;  // size → samples → process CPU seconds
std::map<int, double> gDevelopSeconds;              // size·2 + estimator → process CPU seconds

/// A snapshot at `size`² filled with quality 4 (4 samples per pixel: sparse, so the density
/// estimator does the most work) — reused by the develop benchmarks.
const RenderImage& snapshotFor(int size) {
  static std::map<int, RenderImage> cache;
  auto it = cache.find(size);
  if (it == cache.end())
    it = cache
             .emplace(size, renderToCompletion(scene().ifs, jobFor(size, std::int64_t(4) * size * size),
                                               DisplaySettings::fromProject(scene().project)))
             .first;
  return it->second;
}

void BM_ChaosGameFlame(benchmark::State& state) {
  const int size = int(state.range(0));
  const std::int64_t samples = state.range(1);
  const RenderJob job = jobFor(size, samples);
  for (auto _ : state) {
    RenderImage image = renderToCompletion(scene().ifs, job, DisplaySettings::fromProject(scene().project));
    benchmark::DoNotOptimize(image.colorSums.data());
  }
  state.counters["samples/s"] = benchmark::Counter(double(samples), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_DevelopFlame(benchmark::State& state) {
  const int size = int(state.range(0));
  const bool estimator = state.range(1) != 0;
  const RenderImage& snap = snapshotFor(size);
  FlameSettings settings = scene().project.render.flame;
  if (!estimator) settings.estimator_radius = 0.0;
  for (auto _ : state) {
    FlameImage image =
        developFlameSnapshot(snap, settings, scene().project.camera, size, size, Vec3{0.0}, false, kThreads, nullptr);
    benchmark::DoNotOptimize(image.rgba.data());
  }
}

// Process CPU time (all threads) is what the ratios use: it does not depend on what else the
// machine is doing, while wall time on a shared 2-core machine does.
// Two sample counts per size: the slope is the cost per sample, the intercept the fixed cost
// (per-thread buffers, snapshot merge), which matters at 4096².
BENCHMARK(BM_ChaosGameFlame)
    ->Args({1024, 4'000'000})
    ->Args({1024, 16'000'000})
    ->Args({4096, 4'000'000})
    ->Args({4096, 16'000'000})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK(BM_DevelopFlame)
    ->Args({1024, 1})
    ->Args({1024, 0})
    ->Args({4096, 1})
    ->Args({4096, 0})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->MinTime(1.0);

/// Collects the real time per iteration of each run to print the ratios.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.run_type != Run::RT_Iteration) continue;
      const std::string name = r.benchmark_name();
      const double seconds = r.GetAdjustedCPUTime() / 1e3;  // process CPU ms → s
      int size = 0, de = 0;
      long long samples = 0;
      if (std::sscanf(name.c_str(), "BM_ChaosGameFlame/%d/%lld", &size, &samples) == 2)
        gChaos[size][samples] = seconds;
      else if (std::sscanf(name.c_str(), "BM_DevelopFlame/%d/%d", &size, &de) == 2)
        gDevelopSeconds[size * 2 + de] = seconds;
    }
  }
};

}  // namespace
}  // namespace gridifs

int main(int argc, char** argv) {
  using namespace gridifs;
  benchmark::Initialize(&argc, argv);
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::printf("\nFlame display cost vs the chaos game (%d threads, process CPU time, same run):\n", kThreads);
  for (int size : {1024, 4096}) {
    if (gChaos[size].size() < 2 || !gDevelopSeconds.count(size * 2 + 1)) continue;
    const auto lo = gChaos[size].begin(), hi = std::prev(gChaos[size].end());
    const double perSample = (hi->second - lo->second) / double(hi->first - lo->first);
    const double fixed = std::max(0.0, lo->second - perSample * double(lo->first));
    std::printf("  %4d²: chaos game %.1f M samples per CPU second, %.2f CPU s fixed (buffers, merge)\n", size,
                1e-6 / perSample, fixed);
    for (int quality : {25, 100}) {
      const double chaos = fixed + perSample * double(size) * size * quality;
      const double withDe = gDevelopSeconds[size * 2 + 1], withoutDe = gDevelopSeconds[size * 2];
      std::printf(
          "    quality %3d: chaos game %.2f CPU s; develop %.3f CPU s with density estimation (%.1f%% of the "
          "render), %.3f without (%.1f%%)\n",
          quality, chaos, withDe, 100.0 * withDe / (chaos + withDe), withoutDe,
          100.0 * withoutDe / (chaos + withoutDe));
    }
  }
  benchmark::Shutdown();
  return 0;
}
