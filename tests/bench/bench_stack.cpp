// Editing is live: re-evaluating a 32×32×32 grid through a 10-op stack,
// calculator included, must fit well inside a frame. Target: < 5 ms on one core.
#include <benchmark/benchmark.h>

#include "model/contractivity.h"
#include "model/stack_evaluator.h"

using namespace gridifs;

namespace {

Function tenOpFunction(int n) {
  Function f;
  f.resolution = {n, n, n};
  f.placement.scale = Vec3{0.5};
  auto add = [&](OpParams p, Selection s = {}) {
    Operation op;
    op.params = std::move(p);
    op.selection = std::move(s);
    f.ops.push_back(op);
  };
  add(TwistOp{Axis::Z, Profile::Linear, 1.2, 1.0});
  add(TaperOp{Axis::Z, Profile::Sine, 0.3, 3.14159}, {{{0, n / 2}, {0, n - 1}, {0, n - 1}, SelectionOp::Or}});
  add(BendOp{Axis::Z, Axis::Y, 0.8});
  add(TranslateOp{Vec3{0.1, 0, 0}});
  add(RotateOp{Vec3{0, 0, 30}});
  add(ScaleOp{Vec3{1, 1, 0.8}});
  add(MagnetOp{Vec3{0.2, 0, 0}, 0.8, 0.5, 2});
  add(MorphOp{{{Vec3{0, 0, 0}, Vec3{0.1, 0.2, 0}}, {Vec3{0.5, 0.5, 0.5}, Vec3{0.4, 0.5, 0.6}}}, 1.0});
  CalculatorOp calc;
  calc.x = "x*cos(v1*sqrt(x^2+y^2)) - y*sin(v1*sqrt(x^2+y^2))";
  calc.y = "x*sin(v1*sqrt(x^2+y^2)) + y*cos(v1*sqrt(x^2+y^2))";
  calc.z = "z";
  calc.vars[0].value = 0.2;
  add(calc);
  add(NodesOp{{{{1, 2, 3}, Vec3{0, 0.1, 0}}}});
  return f;
}

void BM_EvaluateTenOpStack(benchmark::State& state) {
  const Function f = tenOpFunction(int(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(evaluateFunction(f));
  state.counters["nodes"] = double(f.resolution[0]) * f.resolution[1] * f.resolution[2];
}
BENCHMARK(BM_EvaluateTenOpStack)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);

void BM_EvaluateCalculatorOnly(benchmark::State& state) {
  Function f = tenOpFunction(32);
  f.ops = {f.ops[8]};
  for (auto _ : state) benchmark::DoNotOptimize(evaluateFunction(f));
}
BENCHMARK(BM_EvaluateCalculatorOnly)->Unit(benchmark::kMillisecond);

void BM_ContractivityEstimate(benchmark::State& state) {
  const Grid g = evaluateFunction(tenOpFunction(int(state.range(0))));
  for (auto _ : state) benchmark::DoNotOptimize(estimateContractivity(g));
}
BENCHMARK(BM_ContractivityEstimate)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
