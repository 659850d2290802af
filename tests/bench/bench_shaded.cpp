// The shaded display's speed: developing a 1024² shaded image (normals, occlusion with 8
// directions, 2 shadowed lights) from a finished snapshot of the canonical scene, and the
// chaos-game rate with 0 to 3 shadowed lights (each fills one more depth buffer per sample).
#include <benchmark/benchmark.h>

#include <ctime>

#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "render/shaded_image.h"
#include "tests/bench/canonical_scene.h"

namespace gridifs {
namespace {

ShadingSettings twoShadowedLights() {
  ShadingSettings s;
  s.lights = {ShadingLight{Vec3{0.3, -0.5, 1.0}, Vec3{1.0}, 1.0, true},
              ShadingLight{Vec3{-0.8, 0.4, 0.5}, Vec3{0.6, 0.7, 1.0}, 0.5, true}};
  s.ao = AmbientOcclusionSettings{12.0, 0.8, 8};
  s.specular = 0.3;
  return s;
}

const RenderImage& shadedSnapshot() {
  static const RenderImage image = [] {
    Project p = canonicalScene();
    const auto ifs = compileIfs(p);
    RenderJob job = shadedRenderJob(RenderJob::fromProject(p, 2), twoShadowedLights(), *ifs);
    job.samples = 20'000'000;
    return renderToCompletion(ifs, job, shadedDisplaySettings(p));
  }();
  return image;
}

/// Develop only (what a light, occlusion or fog slider costs): items = pixels.
void BM_DevelopShaded(benchmark::State& state) {
  const RenderImage& snapshot = shadedSnapshot();
  const Project p = canonicalScene();
  const ShadingSettings settings = twoShadowedLights();
  ShadedImage out;
  for (auto _ : state) developShaded(snapshot, settings, p.camera, p.render.background, int(state.range(0)), out);
  state.SetItemsProcessed(state.iterations() * std::int64_t(snapshot.width) * snapshot.height);
}
BENCHMARK(BM_DevelopShaded)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

/// The same develop for the preview: the display colour only, without the compositing channels
/// (linear colour, normals, occlusion, shadow) that only the EXR output reads.
void BM_DevelopShadedDisplay(benchmark::State& state) {
  const RenderImage& snapshot = shadedSnapshot();
  const Project p = canonicalScene();
  const ShadingSettings settings = twoShadowedLights();
  ShadedImage out;
  for (auto _ : state)
    developShaded(snapshot, settings, p.camera, p.render.background, int(state.range(0)), out, ShadedChannels::Display);
  state.SetItemsProcessed(state.iterations() * std::int64_t(snapshot.width) * snapshot.height);
}
BENCHMARK(BM_DevelopShadedDisplay)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

/// The chaos game with `range(0)` shadowed lights on one thread: points_per_second to compare.
void BM_ChaosShadowLights(benchmark::State& state) {
  const Project p = canonicalScene();
  const auto ifs = compileIfs(p);
  ShadingSettings settings = twoShadowedLights();
  settings.lights.push_back(ShadingLight{Vec3{0.2, 0.9, 0.3}, Vec3{1.0, 0.8, 0.6}, 0.3, true});
  settings.lights.resize(std::size_t(state.range(0)));
  RenderJob job = shadedRenderJob(RenderJob::fromProject(p, 1), settings, *ifs);
  job.samples = 30'000'000;
  ChaosRenderer renderer;
  std::int64_t samples = 0;
  double seconds = 0.0;
  // The process's CPU time (every thread: the worker's, and the waiting main thread's little):
  // on a shared machine the wall-clock rate swings with the other processes, the CPU time far less.
  const std::clock_t cpuStart = std::clock();
  for (auto _ : state) {
    renderer.restart(ifs, job);
    renderer.waitUntilDone({}, 0.005);
    const RenderStats s = renderer.stats();
    samples += s.samples;
    seconds += s.seconds;
  }
  const double cpuSeconds = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
  state.SetItemsProcessed(samples);
  state.counters["points_per_second"] = double(samples) / seconds;
  state.counters["cpu_ns_per_sample"] = 1e9 * cpuSeconds / double(samples);
}
BENCHMARK(BM_ChaosShadowLights)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(3.0);

}  // namespace
}  // namespace gridifs

BENCHMARK_MAIN();
