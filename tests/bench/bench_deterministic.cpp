// The deterministic algorithm F^n(A) (Gröller & Wegenkittl 1994, §3.2): building the mesh and writing it.
// Reference (2 cores, loaded machine): Sierpinski cube depth 10 (6.3 M faces) builds in ~1.3 s
// and writes a 258 MB binary PLY in ~2.6 s.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "io/project_io.h"
#include "mesh/deterministic_ifs.h"
#include "mesh/mesh_io.h"

using namespace gridifs;

namespace {

DeterministicIfs assetIfs(const char* name) {
  return snapshotDeterministicIfs(loadProject(std::string(GRIDIFS_ASSETS) + "/" + name));
}

// args: depth, subdivision, threads (0 = all cores)
void BM_BuildTwisted(benchmark::State& state) {
  const DeterministicIfs ifs = assetIfs("twisted_functions.gridifs");
  BaseMeshSpec spec;
  spec.subdivision = int(state.range(1));
  const IfsMesh base = refineBase(loadCoarseBase(spec), spec);
  DeterministicOptions options;
  options.depth = int(state.range(0));
  options.threads = int(state.range(2));
  std::uint64_t faces = 0;
  for (auto _ : state) {
    const DeterministicMesh out = buildDeterministicMesh(ifs, base, options);
    faces = out.mesh.n_faces();
    benchmark::DoNotOptimize(faces);
  }
  state.counters["faces"] = double(faces);
}
BENCHMARK(BM_BuildTwisted)->Args({5, 2, 0})->Args({6, 2, 0})->Args({6, 2, 1})->Unit(benchmark::kMillisecond);

void BM_BuildSierpinskiCube(benchmark::State& state) {
  const DeterministicIfs ifs = assetIfs("sierpinski_tetrahedron.gridifs");
  DeterministicOptions options;
  options.depth = int(state.range(0));
  for (auto _ : state) {
    const DeterministicMesh out = buildDeterministicMesh(ifs, makeCube(), options);
    benchmark::DoNotOptimize(out.mesh.n_faces());
  }
}
BENCHMARK(BM_BuildSierpinskiCube)->Arg(8)->Arg(9)->Unit(benchmark::kMillisecond);

void BM_WriteBinaryPly(benchmark::State& state) {
  const DeterministicIfs ifs = assetIfs("sierpinski_tetrahedron.gridifs");
  DeterministicOptions options;
  options.depth = 8;
  const DeterministicMesh out = buildDeterministicMesh(ifs, makeCube(), options);
  const auto file = std::filesystem::temp_directory_path() / "gridifs-bench-deterministic.ply";
  for (auto _ : state) writeMeshFile(out.mesh, file);
  std::filesystem::remove(file);
  state.counters["faces"] = double(out.mesh.n_faces());
}
BENCHMARK(BM_WriteBinaryPly)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
