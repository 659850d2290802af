#include "ui/base/modeller_state.h"

#include <algorithm>

#include "edit/node_picking.h"
#include "edit/volume_render_edits.h"
#include "model/stack_evaluator.h"
#include "schema/project_time.h"

namespace gridifs::ui {

ModellerState::ModellerState() : document(defaultNewProject()) {
  // Animated parameters follow the timeline; editing one keys it at the current time.
  document.setRule(keyEditedParameters);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  // Leave one core to the UI thread (and llvmpipe) so the window stays smooth.
  renderThreads = int(std::max(1u, cores - 1));
}

void ModellerState::forgetDocumentViewState() {
  activeFunction = FunctionRef(0);
  activeOp = -1;
  selections.clear();
  finalSelection.clear();
  finalFunctionMessage.clear();
  clampIndices();
  // A project opens the way it was saved; one of sets only (median and condensation functions)
  // in the Volume mode, the only one that can show it.
  switch (previewModeOnOpen(document.project())) {
    case StoredPreviewMode::Flame:
      previewMode = PreviewMode::Flame;
      break;
    case StoredPreviewMode::Shaded:
      previewMode = PreviewMode::Shaded;
      break;
    case StoredPreviewMode::Mesh:
      previewMode = PreviewMode::Mesh;
      break;
    case StoredPreviewMode::Volume:
      previewMode = PreviewMode::Volume;
      break;
    case StoredPreviewMode::ZBuffer:
      previewMode = PreviewMode::ZBuffer;
      break;
  }
  ++documentOpens;
}

void ModellerState::clampIndices() {
  const Project& project = document.project();
  const int last = int(project.functions.size()) - 1;
  if (activeFunction.isFinal() ? !project.final_function : activeFunction.index() > last) {
    activeFunction = FunctionRef(last);
    activeOp = -1;
  }
  if (!project.final_function) finalSelection.clear();
  selections.resize(project.functions.size());
  const int ops = int(function().ops.size());
  if (activeOp >= ops) activeOp = ops - 1;
  if (activeOp < -1) activeOp = -1;
}

void ModellerState::activate(FunctionRef function) {
  if (!(function == activeFunction)) activeOp = -1;
  activeFunction = function;
  clampIndices();
}

const Operation* ModellerState::op() const {
  const Function& f = function();
  if (activeOp < 0 || activeOp >= int(f.ops.size())) return nullptr;
  return &f.ops[std::size_t(activeOp)];
}

Selection& ModellerState::selection() {
  clampIndices();
  return activeFunction.isFinal() ? finalSelection : selections[std::size_t(activeFunction.index())];
}

const std::vector<unsigned char>& ModellerState::selectionMask() {
  const Selection& s = selection();
  const Index3& res = function().resolution;
  if (!haveMask_ || s != maskSelection_ || res != maskResolution_) {
    const std::size_t count = std::size_t(res[0]) * res[1] * res[2];
    mask_ = s.empty() ? std::vector<unsigned char>(count, 0) : gridifs::selectionMask(s, res);
    maskSelection_ = s;
    maskResolution_ = res;
    haveMask_ = true;
  }
  return mask_;
}

bool ModellerState::hasSelection() {
  const auto& m = selectionMask();
  return std::any_of(m.begin(), m.end(), [](unsigned char v) { return v != 0; });
}

const Grid& ModellerState::localGrid() {
  clampIndices();
  const Function& f = function();
  if (!haveCache_ || !(f == cachedFunction_)) {
    cachedFunction_ = f;
    haveCache_ = true;
    try {
      localGrid_ = evaluateFunction(f, std::size_t(-1), false);
      gridError.clear();
    } catch (const ModelError& e) {
      gridError = e.what();
      if (localGrid_.resolution() != f.resolution) localGrid_ = Grid(f.resolution);
    }
  }
  return localGrid_;
}

void ModellerState::info(const std::string& text) {
  statusText = text;
  statusIsError = false;
  statusTime = now;
}

void ModellerState::error(const std::string& text) {
  statusText = text;
  statusIsError = true;
  statusTime = now;
}

}  // namespace gridifs::ui
