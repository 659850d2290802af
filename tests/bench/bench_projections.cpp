// The camera's projections on the canonical scene (canonical_scene.h): samples per CPU second of
// the whole renderer (one worker, 2·10^7 samples) with the perspective camera, a 180° fisheye (a
// dome master), a 360° equirectangular camera and its omni-directional stereo pair, each aimed
// so that the scene fills a similar part of the frame. Reported as ratios to perspective from
// the same run, the cameras interleaved over several rounds (these machines are noisy): the
// panoramic projections (atan2 and square roots per sample; sixteen at a time with AVX-512, else
// eight) should keep ≥ 90 %.
#include <benchmark/benchmark.h>

#include <ctime>

#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "tests/bench/canonical_scene.h"
#include "tests/bench/process_cpu_time.h"

namespace gridifs {
namespace {

Project sceneWith(CameraProjection projection, bool stereo) {
  Project p = canonicalScene();
  p.camera.projection = projection;
  if (projection == CameraProjection::Fisheye) p.camera.fov = 180.0;
  if (projection == CameraProjection::Equirectangular) {
    p.camera.fov = 360.0;
    p.render.width = 2048;
    p.render.height = stereo ? 1024 : 512;  // 2:1 per eye
  }
  if (stereo) p.camera.stereo = StereoSettings{0.065, StereoLayout::TopBottom, 4.0};
  return p;
}

void BM_Projection(benchmark::State& state) {
  const CameraProjection projection = CameraProjection(state.range(0));
  const Project scene = sceneWith(projection, state.range(1) != 0);
  const auto ifs = compileIfs(scene);
  RenderJob job = RenderJob::fromProject(scene, 1);
  job.samples = 20'000'000;
  ChaosRenderer renderer;
  std::int64_t samples = 0;
  double cpuSeconds = 0.0;
  for (auto _ : state) {
    const double cpu0 = processCpuSeconds();
    renderer.restart(ifs, job);
    renderer.waitUntilDone({}, 0.005);
    cpuSeconds += processCpuSeconds() - cpu0;
    samples += renderer.stats().samples;
    state.counters["plotted_fraction"] = double(renderer.stats().plotted) / double(renderer.stats().samples);
  }
  state.SetItemsProcessed(samples);
  state.counters["points_per_cpu_second"] = double(samples) / cpuSeconds;
}

void cameras(benchmark::internal::Benchmark* b) {
  b->ArgNames({"projection", "stereo"});
  // Perspective first and last: the ratio takes the better of its two runs.
  b->Args({int(CameraProjection::Perspective), 0});
  b->Args({int(CameraProjection::Fisheye), 0});
  b->Args({int(CameraProjection::Equirectangular), 0});
  b->Args({int(CameraProjection::Equirectangular), 1});
  b->Args({int(CameraProjection::Perspective), 0});
}
BENCHMARK(BM_Projection)->Apply(cameras)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

}  // namespace
}  // namespace gridifs

BENCHMARK_MAIN();
