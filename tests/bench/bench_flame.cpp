// Flame display speed (issue 6 "Speed"): tone mapping + filters (log density, density estimation,
// spatial filter, gamma/vibrancy) at 1024² and 4096² against the chaos game that fills the
// histogram, on assets/twisted_functions.gridifs (3D, perspective) with color accumulation and
// per-sample palette lookup. The filters must not dominate a final render.
//
// Chaos-game cost is linear in samples, so the benchmark measures the rate once per size and
// prints, after the runs, develop time ÷ chaos time for a final render at a given quality
// (samples per output pixel): 25 (the project default, 20M samples at 1024×768) and 100.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>

#include "core/compiled_ifs.h"
#include "core/flame_render.h"
#include "core/project_io.h"

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

std::map<int, double> gChaosSecondsPerSample, gDevelopSeconds;

/// A snapshot at `size`² filled with quality 4 (4 samples per pixel: sparse, so the density
/// estimator does the most work) — reused by the develop benchmarks.
const RenderImage& snapshotFor(int size) {
  static std::map<int, RenderImage> cache;
  auto it = cache.find(size);
  if (it == cache.end())
    it = cache.emplace(size, renderToCompletion(scene().ifs, jobFor(size, std::int64_t(4) * size * size),
                                                DisplaySettings::fromProject(scene().project)))
             .first;
  return it->second;
}

void BM_ChaosGameFlame(benchmark::State& state) {
  const int size = int(state.range(0));
  const std::int64_t samples = 8'000'000;
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
    FlameImage image = developFlameSnapshot(snap, settings, scene().project.camera, size, size, Vec3{0.0}, false,
                                            kThreads, nullptr);
    benchmark::DoNotOptimize(image.rgba.data());
  }
}

BENCHMARK(BM_ChaosGameFlame)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(BM_DevelopFlame)->Args({1024, 1})->Args({1024, 0})->Args({4096, 1})->Args({4096, 0})
    ->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

/// Collects the real time per iteration of each run to print the ratios.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.run_type != Run::RT_Iteration) continue;
      const std::string name = r.benchmark_name();
      const double seconds = r.GetAdjustedRealTime() / 1e3;  // ms → s
      int size = 0, de = 0;
      if (std::sscanf(name.c_str(), "BM_ChaosGameFlame/%d", &size) == 1)
        gChaosSecondsPerSample[size] = seconds / 8e6;
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
  std::printf("\nFlame display cost vs the chaos game (%d threads, same run):\n", kThreads);
  for (int size : {1024, 4096}) {
    if (!gChaosSecondsPerSample.count(size) || !gDevelopSeconds.count(size * 2 + 1)) continue;
    for (int quality : {25, 100}) {
      const double chaos = gChaosSecondsPerSample[size] * double(size) * size * quality;
      const double withDe = gDevelopSeconds[size * 2 + 1], withoutDe = gDevelopSeconds[size * 2];
      std::printf("  %4d², quality %3d: chaos game %.2f s; develop %.3f s with density estimation (%.1f%% of the "
                  "render), %.3f s without (%.1f%%)\n",
                  size, quality, chaos, withDe, 100.0 * withDe / (chaos + withDe), withoutDe,
                  100.0 * withoutDe / (chaos + withoutDe));
    }
  }
  benchmark::Shutdown();
  return 0;
}
