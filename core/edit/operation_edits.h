#pragma once
// Named edits of a function's operation stack (Gröller & Wegenkittl 1994, §2, §4.3): add, remove,
// reorder, mute and change operations, and drag nodes directly. Keyframe tracks on an
// operation's parameters ("functions[0].ops[2].k") follow the operation when the stack changes
// order. Each edit is a plain value gathered in ProjectEdit (edit/project_edit.h).
//
// Thread-safety: plain values; apply() touches only the project given. apply() throws ModelError
// when the function or operation it names is not in the project (the Document applies edits to
// a copy and keeps its own project then).
#include <string>
#include <vector>

#include "model/function_ref.h"
#include "model/grid.h"
#include "model/project.h"
#include "schema/operation_table.h"

namespace gridifs {

/// A new operation of kind `spec` as the modeller adds it: the table's defaults, the active
/// selection (Gröller & Wegenkittl 1994, §4.4: the active subset applies to new ops) and the
/// center of transformation. Magnets and morphs start where the artist is working: at `point`
/// for a point center, else at the centroid of `grid`'s selected nodes (all nodes when the
/// selection selects none). `grid` is the function's grid before its stack. Never throws.
Operation newOperation(const OperationSpec& spec, const Selection& selection, Center::Kind center, const Vec3& point,
                       const Grid& grid);

/// Inserts `operation` at `at` (0..size) of the function's stack.
struct AddOperation {
  FunctionRef function;
  int at = 0;
  Operation operation;
  void apply(Project& project) const;
  /// "Add " and the operation's title ("Add Twist").
  std::string label() const;
};

struct RemoveOperation {
  FunctionRef function;
  int index = 0;
  void apply(Project& project) const;
  std::string label() const { return "Delete operation"; }
};

/// Swaps operations `from` and `to` (neighbours when moving up or down).
struct MoveOperation {
  FunctionRef function;
  int from = 0, to = 0;
  void apply(Project& project) const;
  /// "Move operation up" when `to` is before `from`, else "Move operation down".
  std::string label() const;
};

/// Inserts a copy of operation `index` after it.
struct DuplicateOperation {
  FunctionRef function;
  int index = 0;
  void apply(Project& project) const;
  std::string label() const { return "Duplicate operation"; }
};

struct SetOperationMuted {
  FunctionRef function;
  int index = 0;
  bool muted = true;
  void apply(Project& project) const;
  /// "Mute operation" or "Unmute operation".
  std::string label() const;
};

/// Replaces operation `index` (a parameter panel's edited copy, a dragged handle).
struct SetOperation {
  FunctionRef function;
  int index = 0;
  Operation operation;
  void apply(Project& project) const;
  std::string label() const { return "Edit operation"; }
};

/// The nodes operation `index` applies to.
struct SetOperationSelection {
  FunctionRef function;
  int index = 0;
  Selection selection;
  void apply(Project& project) const;
  std::string label() const { return "Set operation selection"; }
};

/// Where the point center of transformation of operation `index` sits (Gröller & Wegenkittl
/// 1994, §4.3).
struct PlaceCenter {
  FunctionRef function;
  int index = 0;
  Vec3 point{0.0};
  void apply(Project& project) const;
  std::string label() const { return "Place center"; }
};

/// Moves the nodes of `start` (the function as it was when the drag began) where `mask` (one
/// entry per node, i fastest) is set by `displacement`. Successive drags extend one trailing
/// nodes operation (unmuted, on all nodes) instead of stacking many; otherwise one is appended.
/// The result replaces the function, so every update of a drag gesture gives the same function
/// for the same displacement.
struct MoveNodes {
  FunctionRef function;
  Function start;
  std::vector<unsigned char> mask;
  Vec3 displacement{0.0};
  void apply(Project& project) const;
  std::string label() const { return "Move nodes"; }
};

/// The index of the operation MoveNodes writes into when it starts from `start`.
int nodeMoveOperation(const Function& start);

}  // namespace gridifs
