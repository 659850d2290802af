// Density-volume speed (Sokolov & Gentil, §4.2: a 256³ measure attractor of two condensation
// functions "in less than 1 minute" on a 1.6 GHz Xeon): two median functions for 300 set
// iterations at 128³ and 256³ on all threads, and point binning of the Sierpinski tetrahedron
// into a 256³ volume on one thread (samples per second per thread).
#include <benchmark/benchmark.h>

#include <chrono>

#include "io/project_io.h"
#include "volume/measure_attractor.h"

namespace gridifs {
namespace {

const char* kTwoMedians = R"({"format": "gridifs", "version": 1, "functions": [
  {"name": "A", "kind": "median", "weight": 1, "set": {"primitive": "sphere", "center": [-0.45, 0, 0], "radius": 0.35}},
  {"name": "B", "kind": "median", "weight": 1, "set": {"primitive": "box", "center": [0.45, 0, 0], "size": [0.5, 0.5, 0.5]}}]})";

void BM_TwoMedians(benchmark::State& state) {
  const Project project = parseProject(kTwoMedians);
  VolumeJob job;
  job.settings.resolution = int(state.range(0));
  job.settings.iterations = 300;
  job.settings.skip = 20;
  job.threads = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const DensityVolume v = computeDensityVolume(project, job);
    benchmark::DoNotOptimize(v.density.data());
    state.counters["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.counters["mass"] = v.totalMass;
  }
}
BENCHMARK(BM_TwoMedians)->Arg(128)->Arg(256)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

void BM_PointBinning(benchmark::State& state) {
  const Project project = loadProject(std::string(GRIDIFS_ASSETS) + "/sierpinski_tetrahedron.gridifs");
  VolumeJob job;
  job.settings.resolution = 256;
  job.settings.samples = 100'000'000;
  job.threads = int(state.range(0));
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const DensityVolume v = computeDensityVolume(project, job);
    benchmark::DoNotOptimize(v.density.data());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.counters["samples_per_second_per_thread"] = double(job.settings.samples) / seconds / job.threads;
  }
}
BENCHMARK(BM_PointBinning)->Arg(1)->Arg(2)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
}  // namespace gridifs

BENCHMARK_MAIN();
