// From a slider edit to the preview's first image, through core as the modeller does it
// (job/preview_plan.h): the Document applies the edit (a SetParameter, what a panel's slider
// sends), decidePreview says what it asks for, preparePreview compiles (or reuses) the IFS and
// validates the job, the CPU ChaosRenderer restarts, and the first snapshot with points in it is
// developed. Scene: the canonical one (canonical_scene.h) in an 800×600 preview on 2 threads.
// Goal: ≤ 20 ms of wall time per edit.
//
// BM_TwistEditToFirstImage: a twist's k moves (the function is evaluated and compiled again).
// BM_CameraEditToFirstImage: the camera turns (the same IFS, a new job).
#include <benchmark/benchmark.h>

#include <chrono>
#include <thread>

#include "canonical_scene.h"
#include "edit/parameter_edit.h"
#include "job/preview_plan.h"
#include "render/chaos_renderer.h"

using namespace gridifs;

namespace {

constexpr int kWidth = 800, kHeight = 600, kThreads = 2;

template <bool kGeometry>
void editToFirstImage(benchmark::State& state) {
  Document document(canonicalScene());
  ChaosRenderer renderer;
  PreviewInputs last;
  std::shared_ptr<const CompiledIfs> ifs;
  RenderImage image;
  int edit = 0;
  for (auto _ : state) {
    ++edit;
    const double value = kGeometry ? 0.8 + 0.001 * (edit % 100) : 35.0 + 0.1 * (edit % 100);
    document.apply(SetParameter{kGeometry ? "functions[0].ops[0].k" : "camera.yaw", value});
    const PreviewDecision decision = decidePreview(last, document.revisions(), kWidth, kHeight, kThreads);
    const PreparedRender prepared =
        preparePreview(document, kWidth, kHeight, kThreads, decision.recompile ? nullptr : ifs);
    renderer.restart(prepared.ifs, prepared.job);
    last = PreviewInputs{document.revisions(), kWidth, kHeight, kThreads, true, true};
    ifs = prepared.ifs;
    while (renderer.stats().samples == 0) std::this_thread::sleep_for(std::chrono::microseconds(100));
    renderer.snapshot(image, prepared.display);
    benchmark::DoNotOptimize(image.hitPixels);
  }
  state.SetLabel("per edit");
}

void BM_TwistEditToFirstImage(benchmark::State& state) { editToFirstImage<true>(state); }
void BM_CameraEditToFirstImage(benchmark::State& state) { editToFirstImage<false>(state); }

BENCHMARK(BM_TwistEditToFirstImage)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CameraEditToFirstImage)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
