// The GPU compute renderer's speed on the canonical scene (tests/bench/canonical_scene.h) at
// 1024²: z-buffer + density, and with the flame display's colour sums; the CPU renderer on one
// thread in the same run for the ratio. Without a GPU this measures Mesa's llvmpipe (the device is
// printed in the context). docs/RENDERER.md has the figures.
#include <benchmark/benchmark.h>

#include <string>

#include "gpu/gpu_chaos_renderer.h"
#include "io/flame_genome.h"
#include "io/flame_import.h"
#include "io/project_io.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "tests/bench/canonical_scene.h"

namespace gridifs {
namespace {

const std::shared_ptr<const CompiledIfs>& ifs() {
  static const auto compiled = compileIfs(canonicalScene());
  return compiled;
}

gpu::GpuChaosRenderer::Options benchOptions(bool allowAtomic64) {
  gpu::GpuChaosRenderer::Options options;
  options.sliceSeconds = 0.05;  // a render to completion: long dispatches
  options.allowAtomic64 = allowAtomic64;
  return options;
}

gpu::GpuChaosRenderer& gpuRenderer() {
  static gpu::GpuChaosRenderer renderer{benchOptions(true)};
  return renderer;
}

/// The same GPU with the 32-bit keys forced: what the quantised z-buffer costs or saves where
/// 64-bit atomics exist.
gpu::GpuChaosRenderer& gpuRenderer32() {
  static gpu::GpuChaosRenderer renderer{benchOptions(false)};
  return renderer;
}

/// A flame genome with native variations (random julia, blur and julian, a deterministic blend and
/// a post map): tests/data/flame/bench/mixed_random.flame at 1024².
const Project& variationScene() {
  static const Project project = [] {
    Project p = importFlameGenome(parseFlameFile(R"(<flame name="mixed-random" size="1024 1024" center="0.2 -0.1"
        scale="280" rotate="30" quality="200" brightness="4" gamma="3" palette="12">
      <xform weight="1" color="0" julia="0.8" spherical="0.2" coefs="0.7 0.3 -0.3 0.7 0.3 0.1"/>
      <xform weight="0.7" color="0.7" blur="0.3" heart="0.7" coefs="0.5 -0.2 0.2 0.5 -0.5 0.3" post="0.9 0.1 -0.1 0.9 0.1 0"/>
      <xform weight="0.5" color="1" julian="1" julian_power="5" julian_dist="0.5" coefs="0.8 0 0 0.8 0 -0.4"/>
    </flame>)")[0],
                                  {})
                    .project;
    return p;
  }();
  return project;
}

const std::shared_ptr<const CompiledIfs>& variationIfs() {
  static const auto compiled = compileIfs(variationScene());
  return compiled;
}

/// An IFS matrix with states at 1024² (Thollot, Zair, Tosan & Vandorpe, §4: the tensor product of
/// two state IFSs of their fig. 4.3, assets/matrices/fig4_3_tensor_product.gridifs): the chains
/// walk transition rows, with hidden and peek steps, on both devices.
const Project& stateScene() {
  static const Project project = [] {
    Project p = loadProject(std::string(GRIDIFS_ASSETS) + "/matrices/fig4_3_tensor_product.gridifs");
    p.render.width = 1024;
    p.render.height = 1024;
    return p;
  }();
  return project;
}

const std::shared_ptr<const CompiledIfs>& stateIfs() {
  static const auto compiled = compileIfs(stateScene());
  return compiled;
}

void run(benchmark::State& state, Renderer& renderer, RenderJob job,
         const std::shared_ptr<const CompiledIfs>& compiled = ifs()) {
  std::int64_t samples = 0;
  double seconds = 0.0;
  for (auto _ : state) {
    renderer.restart(compiled, job);
    renderer.waitUntilDone({}, 0.002);
    const RenderStats s = renderer.stats();
    samples += s.samples;
    seconds += s.seconds;
  }
  state.SetItemsProcessed(samples);
  state.counters["points_per_s"] = seconds > 0 ? double(samples) / seconds : 0.0;
}

void BM_GpuZBuffer(benchmark::State& state) {
  RenderJob job = RenderJob::fromProject(canonicalScene(), 1);
  job.samples = state.range(0);
  state.SetLabel(gpuRenderer().info().renderer + (gpuRenderer().info().atomic64 ? ", 64-bit keys" : ", 32-bit keys"));
  run(state, gpuRenderer(), job);
}

void BM_GpuZBuffer32BitKeys(benchmark::State& state) {
  RenderJob job = RenderJob::fromProject(canonicalScene(), 1);
  job.samples = state.range(0);
  state.SetLabel(gpuRenderer32().info().renderer + ", 32-bit keys forced");
  run(state, gpuRenderer32(), job);
}

void BM_GpuFlameColourSums(benchmark::State& state) {
  RenderJob job = RenderJob::fromProject(canonicalScene(), 1);
  job.samples = state.range(0);
  job.accumulateColor = true;
  state.SetLabel(gpuRenderer().info().renderer);
  run(state, gpuRenderer(), job);
}

void BM_GpuFlameVariations(benchmark::State& state) {
  RenderJob job = RenderJob::fromProject(variationScene(), 1);
  job.samples = state.range(0);
  job.accumulateColor = true;
  state.SetLabel(gpuRenderer().info().renderer);
  run(state, gpuRenderer(), job, variationIfs());
}

void BM_CpuFlameVariations(benchmark::State& state) {
  RenderJob job = RenderJob::fromProject(variationScene(), int(state.range(1)));
  job.samples = state.range(0);
  job.accumulateColor = true;
  job.depthKeys = false;  // as `gridifs render --mode flame` asks
  ChaosRenderer cpu;
  run(state, cpu, job, variationIfs());
}

void BM_GpuStateMatrix(benchmark::State& state) {
  RenderJob job = RenderJob::fromProject(stateScene(), 1);
  job.samples = state.range(0);
  state.SetLabel(gpuRenderer().info().renderer);
  run(state, gpuRenderer(), job, stateIfs());
}

void BM_CpuStateMatrix(benchmark::State& state) {
  RenderJob job = RenderJob::fromProject(stateScene(), int(state.range(1)));
  job.samples = state.range(0);
  ChaosRenderer cpu;
  run(state, cpu, job, stateIfs());
}

void BM_CpuOneThread(benchmark::State& state) {
  RenderJob job = RenderJob::fromProject(canonicalScene(), 1);
  job.samples = state.range(0);
  job.accumulateColor = state.range(1) != 0;
  ChaosRenderer cpu;
  run(state, cpu, job);
}

// Sample counts: the GPU needs enough chains to fill itself (chainCount: 2^18 chains from
// 2^18·64·21 ≈ 3.5·10^8 samples); on llvmpipe 5·10^7 is a few seconds. A hardware GPU also gets
// 4·10^9 and 1.6·10^10 (registered in main once the device is known), where a render lasts long
// enough to time at ~10^10 points/s.
BENCHMARK(BM_GpuZBuffer)
    ->Arg(50'000'000)
    ->Arg(400'000'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK(BM_GpuFlameColourSums)->Arg(50'000'000)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_GpuFlameVariations)->Arg(50'000'000)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_CpuFlameVariations)
    ->Args({20'000'000, 1})
    ->Args({50'000'000, 16})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK(BM_GpuStateMatrix)->Arg(50'000'000)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_CpuStateMatrix)
    ->Args({20'000'000, 1})
    ->Args({50'000'000, 16})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK(BM_CpuOneThread)
    ->Args({50'000'000, 0})
    ->Args({50'000'000, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

void registerHardwareSizes() {
  bool software = true;
  try {
    software = gpuRenderer().info().software;
  } catch (const std::exception&) {
    return;  // no GPU: the registered benchmarks report the error themselves
  }
  if (software) return;
  for (const std::int64_t samples : {std::int64_t(4'000'000'000), std::int64_t(16'000'000'000)}) {
    benchmark::RegisterBenchmark("BM_GpuZBuffer/large", BM_GpuZBuffer)
        ->Arg(samples)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(1);
    benchmark::RegisterBenchmark("BM_GpuZBuffer32BitKeys/large", BM_GpuZBuffer32BitKeys)
        ->Arg(samples)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(1);
    benchmark::RegisterBenchmark("BM_GpuFlameColourSums/large", BM_GpuFlameColourSums)
        ->Arg(samples)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(1);
    benchmark::RegisterBenchmark("BM_GpuFlameVariations/large", BM_GpuFlameVariations)
        ->Arg(samples / 4)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(1);
    benchmark::RegisterBenchmark("BM_GpuStateMatrix/large", BM_GpuStateMatrix)
        ->Arg(samples)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(1);
  }
}

}  // namespace
}  // namespace gridifs

// `bench_gpu --write-scene FILE.gridifs` saves the canonical scene for whole-process timings
// (gridifs render against flam3-render, docs/RENDERER.md).
int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--write-scene") {
    gridifs::saveProject(gridifs::canonicalScene(), argv[2]);
    return 0;
  }
  gridifs::registerHardwareSizes();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
