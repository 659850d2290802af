// The chaos game's cost per shadowed light as CPU time, for a shared machine where wall-clock
// rates swing: each light count in turn renders on a fresh renderer with one worker thread, and
// the process's CPU time (every thread) is divided by the samples; rounds repeat the light counts
// back to back, and the minimum per light count is the run least disturbed by other processes.
//
//   bench_shadow_cost [ROUNDS=3] [SAMPLES=20000000] [MAX_LIGHTS=3] [cube]
//
// The canonical scene at 1024² (512² maps), the lights of bench_shaded plus a third; `cube`
// renders a solid cube instead (eight half-size copies), whose maps fill.
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "render/shaded_image.h"
#include "tests/bench/canonical_scene.h"

namespace gridifs {
namespace {

double cpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

Project solidCube() {
  Project p = canonicalScene();
  p.functions.clear();
  for (int i = 0; i < 8; ++i) {
    Function f;
    f.name = "c" + std::to_string(i);
    f.resolution = {2, 2, 2};
    f.placement.scale = Vec3{0.5};
    f.placement.translate = Vec3{(i & 1) ? 0.5 : -0.5, (i & 2) ? 0.5 : -0.5, (i & 4) ? 0.5 : -0.5};
    p.functions.push_back(f);
  }
  return p;
}

int run(int argc, char** argv) {
  const int rounds = argc > 1 ? std::atoi(argv[1]) : 3;
  const long long samples = argc > 2 ? std::atoll(argv[2]) : 20'000'000;
  const int maxLights = std::clamp(argc > 3 ? std::atoi(argv[3]) : 3, 0, 3);
  const bool cube = argc > 4 && std::strcmp(argv[4], "cube") == 0;
  const Project p = cube ? solidCube() : canonicalScene();
  const auto ifs = compileIfs(p);
  ShadingSettings settings;
  settings.lights = {ShadingLight{Vec3{0.3, -0.5, 1.0}, Vec3{1.0}, 1.0, true},
                     ShadingLight{Vec3{-0.8, 0.4, 0.5}, Vec3{0.6, 0.7, 1.0}, 0.5, true},
                     ShadingLight{Vec3{0.2, 0.9, 0.3}, Vec3{1.0, 0.8, 0.6}, 0.3, true}};
  double best[4] = {1e30, 1e30, 1e30, 1e30};
  for (int r = 0; r < rounds; ++r)
    for (int n = 0; n <= maxLights; ++n) {
      ShadingSettings s = settings;
      s.lights.resize(std::size_t(n));
      RenderJob job = shadedRenderJob(RenderJob::fromProject(p, 1), s, *ifs);
      job.samples = samples;
      ChaosRenderer renderer;  // fresh: a restart with only other lights would keep the camera's buffers
      const double start = cpuSeconds();
      renderer.restart(ifs, job);
      renderer.waitUntilDone({}, 0.005);
      const double ns = 1e9 * (cpuSeconds() - start) / double(renderer.stats().samples);
      best[n] = std::min(best[n], ns);
      std::printf("round %d, %d lights: %.1f CPU ns per sample\n", r, n, ns);
    }
  std::printf("minimum:");
  for (int n = 0; n <= maxLights; ++n) std::printf(" %.1f", best[n]);
  std::printf(" CPU ns per sample for 0..%d lights\ncost of each light over the rate before it:", maxLights);
  for (int n = 1; n <= maxLights; ++n) std::printf(" %+.0f %%", 100.0 * (best[n] - best[n - 1]) / best[n - 1]);
  std::printf("\n");
  return 0;
}

}  // namespace
}  // namespace gridifs

int main(int argc, char** argv) { return gridifs::run(argc, argv); }
