// The cost of one frame of a slider drag in the modeller: the Document copies the project,
// applies the change, validates it and bumps its revision. Scene: assets/universal_calculator
// (four 8×8×8 grids, each with a universal calculator). The drag moves v1 of the first function's
// calculator over 60 frames, as the parameter panel does.
//
// BM_DragValidation*: the validation alone, per frame (target: ≤ 1 ms). Full re-checks every
// calculator of the project; Change re-checks the edited function only (what the Document does).
// BM_DragDocumentFrame: a whole Document::updateGesture per frame.
#include <benchmark/benchmark.h>

#include <string>
#include <variant>
#include <vector>

#include "edit/document.h"
#include "edit/project_edit.h"
#include "io/project_io.h"
#include "schema/validation.h"

using namespace gridifs;

namespace {

constexpr int kFrames = 60;

const Project& scene() {
  static const Project project = loadProject(std::string(GRIDIFS_ASSETS) + "/universal_calculator.gridifs");
  return project;
}

// Frame i of the drag: v1 of function 0's calculator swept across its range.
void dragFrame(Project& project, int frame) {
  auto& calc = std::get<CalculatorOp>(project.functions[0].ops[0].params);
  calc.vars[0].value = calc.vars[0].min + (calc.vars[0].max - calc.vars[0].min) * double(frame % kFrames) / kFrames;
}

// The same frame as the panel's edit: the operation with v1 at that frame's value.
SetOperation dragEdit(int frame) {
  Project project = scene();
  dragFrame(project, frame);
  return SetOperation{FunctionRef(0), 0, project.functions[0].ops[0]};
}

template <bool kChangeOnly>
void validationPerFrame(benchmark::State& state) {
  Project previous = scene(), next = scene();
  int frame = 0;
  for (auto _ : state) {
    dragFrame(next, ++frame);
    if constexpr (kChangeOnly)
      validateProjectChange(next, previous);
    else
      validateProject(next);
    previous = next;  // the Document's current project after the frame (not timed separately)
  }
  state.SetLabel("per frame");
}

void BM_DragValidationFull(benchmark::State& state) { validationPerFrame<false>(state); }
void BM_DragValidationChange(benchmark::State& state) { validationPerFrame<true>(state); }

void BM_DragDocumentFrame(benchmark::State& state) {
  Document document(scene());
  document.apply("warm up", dragEdit(0));  // a checked edit, as after opening
  document.beginGesture("Drag v1");
  std::vector<SetOperation> frames;
  for (int frame = 0; frame < kFrames; ++frame) frames.push_back(dragEdit(frame));
  int frame = 0;
  for (auto _ : state) document.updateGesture(frames[std::size_t(++frame % kFrames)]);
  document.endGesture();
  state.SetLabel("per frame");
}

BENCHMARK(BM_DragValidationFull)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DragValidationChange)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DragDocumentFrame)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
