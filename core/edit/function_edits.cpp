#include "edit/function_edits.h"

#include "base/errors.h"
#include "edit/edit_refs.h"
#include "edit/flame_symmetry.h"
#include "edit/new_function.h"
#include "freeform/transition_matrix.h"
#include "model/final_function.h"

namespace gridifs {

void AddFunction::apply(Project& project) const { insertFunction(project, project.functions.size(), function); }

std::string AddFunction::label() const {
  switch (function.kind) {
    case FunctionKind::Condensation:
      return "Add condensation function";
    case FunctionKind::Median:
      return "Add median function";
    default:
      return "Add function";
  }
}

void DuplicateFunction::apply(Project& project) const {
  Function copy = functionAt(project, index);
  copy.name = uniqueFunctionName(project, copy.name + "_");
  insertFunction(project, std::size_t(index) + 1, std::move(copy));
}

void RemoveFunction::apply(Project& project) const {
  functionAt(project, index);
  eraseFunction(project, std::size_t(index));
}

void MoveFunction::apply(Project& project) const {
  functionAt(project, from);
  functionAt(project, to);
  swapFunctions(project, std::size_t(from), std::size_t(to));
}

std::string MoveFunction::label() const { return to < from ? "Move function up" : "Move function down"; }

void AddFinalFunction::apply(Project& project) const {
  if (project.final_function) throw ModelError("final", "the project already has a final function");
  project.final_function = identityFinalFunction();
}

void RemoveFinalFunction::apply(Project& project) const {
  if (!project.final_function) throw ModelError("final", "the project has no final function");
  removeFinalFunction(project);
}

void RenameFunction::apply(Project& project) const { function.in(project).name = name; }

void SetFunctionMuted::apply(Project& project) const { function.in(project).muted = muted; }

std::string SetFunctionMuted::label() const {
  return std::string(muted ? "Mute" : "Unmute") + (function.isFinal() ? " final function" : " function");
}

void SetFunctionResolution::apply(Project& project) const { function.in(project).resolution = resolution; }

void SetPlacement::apply(Project& project) const { function.in(project).placement = placement; }

void MovePlacement::apply(Project& project) const { function.in(project).placement.translate = translate; }

void SetInterpolation::apply(Project& project) const { function.in(project).interpolation = interpolation; }

std::string SetInterpolation::label() const {
  return interpolation == LatticeInterpolation::Bezier ? "Bézier final lattice" : "Trilinear final lattice";
}

void SetFunctionColor::apply(Project& project) const { function.in(project).color = color; }

void AddSymmetry::apply(Project& project) const {
  addSymmetry(project, symmetry, symmetryFrameForView(project.camera));
}

}  // namespace gridifs
