#include "edit/matrix_edits.h"

#include "base/errors.h"
#include "edit/edit_refs.h"
#include "freeform/free_form_resize.h"
#include "model/final_function.h"

namespace gridifs {

std::vector<std::vector<double>> transitionPreset(std::size_t n, TransitionPreset preset) {
  std::vector<std::vector<double>> t(n, std::vector<double>(n, preset == TransitionPreset::Cycle ? 0.0 : 1.0));
  for (std::size_t i = 0; i < n; ++i) {
    if (preset == TransitionPreset::NoRepeats && n > 1) t[i][i] = 0.0;
    if (preset == TransitionPreset::Cycle) t[i][(i + 1) % n] = 1.0;
  }
  return t;
}

void SetTransitionPreset::apply(Project& project) const {
  project.transitions = transitionPreset(project.functions.size(), preset);
}

std::string SetTransitionPreset::label() const {
  switch (preset) {
    case TransitionPreset::NoRepeats:
      return "Transitions: No repeats";
    case TransitionPreset::Cycle:
      return "Transitions: Cycle i to i+1";
    case TransitionPreset::All:
      break;
  }
  return "Transitions: All";
}

void RemoveTransitions::apply(Project& project) const { project.transitions.clear(); }

void SetMatrixEntry::apply(Project& project) const {
  Function& f = functionAt(project, function);
  if (row >= f.matrix.size() || column >= f.matrix[row].size())
    throw ModelError("functions[" + std::to_string(function) + "].matrix[" + std::to_string(row) + "][" +
                         std::to_string(column) + "]",
                     "the function's matrix has no such entry");
  auto& r = f.matrix[row];
  const std::size_t balance = column != row ? row : (row + 1) % r.size();
  r[balance] += r[column] - value;
  r[column] = value;
}

void MoveControlPoint::apply(Project& project) const {
  if (!project.space || index >= project.space->control_points.size())
    throw ModelError("space.control_points[" + std::to_string(index) + "]", "the project has no such control point");
  project.space->control_points[index] = point;
}

void ApplyFreeFormPreset::apply(Project& project) const {
  applyFreeFormPreset(project, preset, options);
  removeFinalFunction(project);
}

std::string ApplyFreeFormPreset::label() const { return std::string("Preset: ") + freeFormPresetName(preset); }

void AddControlPoint::apply(Project& project) const { addControlPoint(project, point); }

void RemoveControlPoint::apply(Project& project) const { removeControlPoint(project, index); }

void MapOntoControlNet::apply(Project& project) const { project = mapOntoControlNet(project, options).project; }

void BackToGridIfs::apply(Project& project) const {
  const Project fresh = defaultNewProject();
  project.space.reset();
  project.transitions.clear();
  project.functions = fresh.functions;
}

}  // namespace gridifs
