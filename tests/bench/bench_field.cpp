// The field op (Colonna's fractal field) on a 32×32×32 grid with 8 octaves, per time step, on one
// core: the cost of scrubbing the timeline over a field. Target: ≤ 5 ms cubic.
#include <benchmark/benchmark.h>

#include "field/fractal_field.h"
#include "model/grid.h"

using namespace gridifs;

namespace {

void fieldStep(benchmark::State& state, FieldInterpolation interpolation) {
  FractalFieldParams p;
  p.octaves = 8;
  p.scale = 0.5;
  p.ratio = 0.5;
  p.interpolation = interpolation;
  p.wind = {0.2, 0.0, 0.0};
  const FractalField field(p);
  const Grid grid({32, 32, 32});
  const std::vector<unsigned char> mask(grid.nodes().size(), 1);
  double t = 0.0;
  for (auto _ : state) {
    std::vector<Vec3> nodes = grid.nodes();
    field.displaceNodes(nodes, mask, t, 1);
    benchmark::DoNotOptimize(nodes.data());
    t += 1.0 / 24.0;
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(grid.nodes().size()));
}

void BM_FieldStepLinear(benchmark::State& state) { fieldStep(state, FieldInterpolation::Linear); }
void BM_FieldStepCubic(benchmark::State& state) { fieldStep(state, FieldInterpolation::Cubic); }

BENCHMARK(BM_FieldStepLinear)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FieldStepCubic)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
