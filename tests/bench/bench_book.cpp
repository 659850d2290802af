// The book of drawings (Sokolov & Gentil, §3.3, figure 8): every page f_σ1 ∘ … ∘ f_σ6 (S) of two
// median functions at 128³, onto drawings starting from a third drawing, and onto solid meshes
// starting from X: 2 + 4 + … + 64 = 126 set
// images, computed as `gridifs volume --depth 6 --pages` does (without writing the 64 files), and
// with each page's density volume made as the VDB writer needs it. Also the set iterate A_6.
#include <benchmark/benchmark.h>

#include <chrono>

#include "io/project_io.h"
#include "volume/set_iterates.h"

namespace gridifs {
namespace {

const std::filesystem::path kFolder = std::string(GRIDIFS_ASSETS) + "/volumes";

void book(benchmark::State& state, const char* file) {
  const Project project = loadProject(kFolder / file);
  const VoxelLattice lattice{int(state.range(0))};
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const SetSystem system = buildSetSystem(project, lattice, kFolder);
    const VoxelSet s = startSet(project, lattice, kFolder);
    std::int64_t pages = 0;
    double voxels = 0.0;
    forEachBookPage(system, s, 6, 0, [&](std::int64_t, const VoxelSet& page) {
      const DensityVolume v = setDensityVolume(page);
      benchmark::DoNotOptimize(v.density.data());
      voxels += double(page.size());
      ++pages;
    });
    state.counters["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.counters["pages"] = double(pages);
    state.counters["mean_page_voxels"] = voxels / double(pages);
  }
}
/// The 2D book of figure 8: drawings as slabs, from the bananas.
void BM_BookOfDrawings(benchmark::State& state) { book(state, "book_of_drawings.gridifs"); }
BENCHMARK(BM_BookOfDrawings)->Arg(128)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

/// The same in 3D: solid comma and L meshes, from the whole of X (2 M voxels).
void BM_BookOfSolids(benchmark::State& state) { book(state, "comma_to_letter.gridifs"); }
BENCHMARK(BM_BookOfSolids)->Arg(128)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

void BM_SetIterate(benchmark::State& state) {
  const Project project = loadProject(kFolder / "book_of_drawings.gridifs");
  const VoxelLattice lattice{int(state.range(0))};
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const SetSystem system = buildSetSystem(project, lattice, kFolder);
    const VoxelSet a = iterateSets(system, startSet(project, lattice, kFolder), 6, 0);
    state.counters["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.counters["voxels"] = double(a.size());
  }
}
BENCHMARK(BM_SetIterate)->Arg(128)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
}  // namespace gridifs

BENCHMARK_MAIN();
