// Speed of `gridifs render --mode volume`'s ray march (render/volume_raymarch.h): the cloud
// creature (two median sets, Sokolov & Gentil) as a 256³ volume drawn at 1024² on 2 threads,
// lit with its self-shadowing and as an X-ray. The volume is built once, before the timed part,
// and its time reported apart (counter volume_seconds); each stage is a counter of its own:
// classify (transfer function and the shadow's optical depth), shade, march, and the CPU seconds
// of all threads for the whole render (render_cpu_seconds).
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <chrono>

#include "io/project_io.h"
#include "render/volume_raymarch.h"
#include "volume/measure_attractor.h"

namespace gridifs {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
/// CPU seconds of every thread of the process (on a loaded machine wall time says little).
double processCpu() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

struct Scene {
  Project project;
  VolumeSource source;
  double volumeSeconds = 0.0;
};

const Scene& cloud() {
  static const Scene scene = [] {
    Scene s;
    const std::string file = std::string(GRIDIFS_ASSETS) + "/volumes/cloud_creature.gridifs";
    s.project = loadProject(file);
    VolumeJob job;
    job.settings = s.project.volume.value_or(VolumeSettings{});
    job.settings.resolution = 256;
    job.threads = 2;
    job.projectFolder = std::string(GRIDIFS_ASSETS) + "/volumes";
    const auto start = Clock::now();
    DensityVolume v = computeDensityVolume(s.project, job);
    s.volumeSeconds = since(start);
    s.source.n = 256;
    s.source.density = std::move(v.density);
    s.source.color = std::move(v.color);
    return s;
  }();
  return scene;
}

void BM_VolumeRender1024(benchmark::State& state) {
  const Scene& s = cloud();
  VolumeLook look = volumeLookOf(s.project);
  look.settings.display = state.range(0) ? VolumeDisplay::Xray : VolumeDisplay::Lit;
  for (auto _ : state) {
    const double cpu0 = processCpu();
    const auto start = Clock::now();
    const ClassifiedVolume c = classifyVolume(s.source, look, 2);
    const double classify = since(start);
    const auto shadeStart = Clock::now();
    const ShadedVolume shaded = shadeVolume(c, look, 2);
    const double shade = since(shadeStart);
    const auto marchStart = Clock::now();
    const VolumeImage image = marchVolume(shaded, look, s.project.camera, 1024, 1024, 2);
    const double march = since(marchStart);
    benchmark::DoNotOptimize(image.rgba.data());
    state.counters["volume_seconds"] = s.volumeSeconds;
    state.counters["classify_seconds"] = classify;
    state.counters["shade_seconds"] = shade;
    state.counters["march_seconds"] = march;
    state.counters["render_seconds"] = since(start);
    state.counters["render_cpu_seconds"] = processCpu() - cpu0;
  }
}
BENCHMARK(BM_VolumeRender1024)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
}  // namespace gridifs

BENCHMARK_MAIN();
