// Exploring's costs (core/explore).
//
// BM_AttractorVerdict: the "worth looking at" test alone (a 64×48 render of 4·10⁴ samples, 2·10⁴
// points, the stretch probes) on the canonical scene: what every draw of random and mutate pays.
// BM_NineThumbnailsAfterMutate: what the Explore window does after a click on Mutate: nine
// children of the canonical scene drawn (each judged), and each rendered as a 192×144 thumbnail
// of 10⁶ samples, on as many threads as the machine has (goal on 2 cores: ≤ 1 s for the set).
#include <benchmark/benchmark.h>

#include <atomic>
#include <thread>
#include <vector>

#include "explore/explore.h"
#include "explore/thumbnail.h"
#include "io/project_io.h"

using namespace gridifs;

namespace {

Project canonical() { return loadProject(std::string(GRIDIFS_ASSETS) + "/twisted_functions.gridifs"); }

void BM_AttractorVerdict(benchmark::State& state) {
  const Project p = canonical();
  for (auto _ : state) benchmark::DoNotOptimize(judgeAttractor(p).covered);
}
BENCHMARK(BM_AttractorVerdict)->Unit(benchmark::kMillisecond);

void BM_NineThumbnailsAfterMutate(benchmark::State& state) {
  const Project parent = canonical();
  const unsigned workers = std::max(1u, std::thread::hardware_concurrency());
  std::uint64_t seed = 1;
  for (auto _ : state) {
    std::atomic<int> next{0};
    std::vector<std::thread> pool;
    for (unsigned w = 0; w < workers; ++w)
      pool.emplace_back([&] {
        for (int i = next++; i < 9; i = next++) {
          MutationOptions options;
          options.seed = seed + std::uint64_t(i);
          const Project child = mutateProject(parent, options, {"twisted_functions.gridifs"}).project;
          benchmark::DoNotOptimize(renderThumbnail(child, {}, 192, 144, 1'000'000).rgba.data());
        }
      });
    for (std::thread& t : pool) t.join();
    seed += 9;
  }
  state.counters["threads"] = double(workers);
}
BENCHMARK(BM_NineThumbnailsAfterMutate)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
