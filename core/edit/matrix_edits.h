#pragma once
// Named edits of a graph-directed IFS's transition matrix (which function may follow which;
// Thollot, Zair, Tosan & Vandorpe 1997, §3.2) and of a free-form IFS: its control points, its
// functions' barycentric matrices (§3.1) and its presets. Each edit is a plain value gathered in
// ProjectEdit (edit/project_edit.h).
//
// Thread-safety: plain values; apply() touches only the project given. apply() throws ModelError
// when a function, cell or control point it names is not in the project.
#include <optional>
#include <string>
#include <vector>

#include "freeform/free_form_deformation.h"
#include "freeform/free_form_presets.h"
#include "model/project.h"

namespace gridifs {

enum class TransitionPreset {
  All,        // every function may follow every function
  NoRepeats,  // none follows itself (where there are two or more)
  Cycle,      // function i is followed by i + 1 only, the last by the first
};

/// The n×n transition matrix of `preset`. Never throws.
std::vector<std::vector<double>> transitionPreset(std::size_t n, TransitionPreset preset);

/// Replaces the transition matrix by `preset`'s for the project's functions.
struct SetTransitionPreset {
  TransitionPreset preset = TransitionPreset::All;
  void apply(Project& project) const;
  /// "Transitions: All", "Transitions: No repeats", "Transitions: Cycle i to i+1".
  std::string label() const;
};

/// Back to an unrestricted IFS: no transition matrix.
struct RemoveTransitions {
  void apply(Project& project) const;
  std::string label() const { return "Remove transition matrix"; }
};

/// Entry (row, column) of matrix function `function`. The row's diagonal entry (the next one when
/// the diagonal itself is edited) takes up the difference, so the row keeps summing to 1 and every
/// state of a drag is a valid matrix.
struct SetMatrixEntry {
  int function = 0;
  std::size_t row = 0, column = 0;
  double value = 0.0;
  void apply(Project& project) const;
  std::string label() const { return "matrix entry"; }
};

/// Moves control point `index` of the free-form space.
struct MoveControlPoint {
  std::size_t index = 0;
  Vec3 point{0.0};
  void apply(Project& project) const;
  std::string label() const { return "Move control point"; }
};

/// Replaces the space, functions and transitions by a free-form preset and removes the final
/// function (the preset's points sit where a lattice around X would not expect them).
struct ApplyFreeFormPreset {
  FreeFormPreset preset = FreeFormPreset::BezierCurve;
  FreeFormPresetOptions options;
  void apply(Project& project) const;
  /// "Preset: " and the preset's name.
  std::string label() const;
};

/// Adds a control point; every matrix grows with it (freeform/free_form_resize.h says how: a
/// Bézier curve is degree-elevated, anything else gets a zero column and a mean row).
struct AddControlPoint {
  std::optional<Vec3> point;  // default: the centroid of the others
  void apply(Project& project) const;
  std::string label() const { return "Add control point"; }
};

/// Removes control point `index`; every matrix shrinks with it (freeform/free_form_resize.h).
struct RemoveControlPoint {
  std::size_t index = 0;
  void apply(Project& project) const;
  std::string label() const { return "Remove control point"; }
};

/// F̂: replaces a grid project by the free-form one whose matrices are its functions on a
/// control net (freeform/free_form_deformation.h); the final function is kept.
struct MapOntoControlNet {
  ControlNetOptions options;
  void apply(Project& project) const;
  std::string label() const { return "Map onto a control net"; }
};

/// Leaves a free-form IFS: no space, no transitions, and the functions of a new project.
struct BackToGridIfs {
  void apply(Project& project) const;
  std::string label() const { return "Back to a grid IFS"; }
};

}  // namespace gridifs
