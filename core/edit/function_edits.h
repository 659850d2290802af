#pragma once
// Named edits of the function list and of each function's own fields (Gröller & Wegenkittl 1994,
// §4.5: each grid is placed in the common initial grid by an affine placement). Each edit is a
// plain value: apply() changes a project, label() names its undo step. They gather in
// ProjectEdit (edit/project_edit.h), which the Document applies as one undo step or gesture update.
//
// Thread-safety: plain values; apply() touches only the project given. apply() throws ModelError
// when the function (or index) it names is not in the project, and may leave that project half
// changed: the Document applies edits to a copy and keeps its own when one throws.
#include <string>

#include "model/function_ref.h"
#include "model/project.h"

namespace gridifs {

/// Appends `function` (a new row and column of weight 1 in the transition matrix). The defaults of
/// a new function are in edit/new_function.h.
struct AddFunction {
  Function function;
  void apply(Project& project) const;
  /// "Add function", "Add condensation function" or "Add median function", by the function's kind.
  std::string label() const;
};

/// Inserts a copy of function `index` after it, named after the original with "_<n>".
struct DuplicateFunction {
  int index = 0;
  void apply(Project& project) const;
  std::string label() const { return "Duplicate function"; }
};

/// Removes function `index` with its row and column of the transition matrix.
struct RemoveFunction {
  int index = 0;
  void apply(Project& project) const;
  std::string label() const { return "Delete function"; }
};

/// Swaps functions `from` and `to` (neighbours when moving up or down), with the transition
/// matrix's rows and columns.
struct MoveFunction {
  int from = 0, to = 0;
  void apply(Project& project) const;
  /// "Move function up" when `to` is before `from`, else "Move function down".
  std::string label() const;
};

/// Adds the identity final function (model/final_function.h); throws ModelError when there is one.
struct AddFinalFunction {
  void apply(Project& project) const;
  std::string label() const { return "Add final function"; }
};

/// Removes the final function and its keyframe tracks; throws ModelError when there is none.
struct RemoveFinalFunction {
  void apply(Project& project) const;
  std::string label() const { return "Remove final function"; }
};

struct RenameFunction {
  FunctionRef function;
  std::string name;
  void apply(Project& project) const;
  std::string label() const { return "Rename function"; }
};

struct SetFunctionMuted {
  FunctionRef function;
  bool muted = true;
  void apply(Project& project) const;
  /// "Mute function", "Unmute final function", ...
  std::string label() const;
};

/// The grid's nodes per axis; the stack is evaluated again on the new grid.
struct SetFunctionResolution {
  FunctionRef function;
  Index3 resolution{6, 6, 6};
  void apply(Project& project) const;
  std::string label() const { return "Grid resolution"; }
};

struct SetPlacement {
  FunctionRef function;
  Placement placement;
  void apply(Project& project) const;
  std::string label() const { return "Move placement"; }
};

/// Only the translation of the placement (a drag in the IFS view).
struct MovePlacement {
  FunctionRef function;
  Vec3 translate{0.0};
  void apply(Project& project) const;
  std::string label() const { return "Move placement"; }
};

/// How the final function's lattice maps points (trilinear cells or a Bézier volume).
struct SetInterpolation {
  FunctionRef function = FunctionRef::finalFunction();
  LatticeInterpolation interpolation = LatticeInterpolation::Trilinear;
  void apply(Project& project) const;
  /// "Trilinear final lattice" or "Bézier final lattice".
  std::string label() const;
};

struct SetFunctionColor {
  FunctionRef function;
  Vec3 color{1.0};
  void apply(Project& project) const;
  std::string label() const { return "Function color"; }
};

/// Appends the functions that make the attractor symmetric about the project camera's view axis,
/// so the symmetry is what the preview shows (Draves & Reckase 2003, §7; edit/flame_symmetry.h).
struct AddSymmetry {
  int symmetry = 2;
  void apply(Project& project) const;
  std::string label() const { return "Add symmetry"; }
};

}  // namespace gridifs
