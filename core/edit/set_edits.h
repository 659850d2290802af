#pragma once
// Named edits of the set of a condensation or median function (Sokolov & Gentil, §3.1–3.2): its
// shape, its file, and the rotation of a median. Each edit is a plain value gathered in
// ProjectEdit (edit/project_edit.h).
//
// Thread-safety: plain values; apply() touches only the project given. apply() throws ModelError
// when the function it names is not in the project (the Document applies edits to a copy and
// keeps its own project then).
#include <optional>
#include <string>

#include "model/function_ref.h"
#include "model/project.h"

namespace gridifs {

/// Replaces the whole set (a drag of its centre, size or placement).
struct SetCondensationSet {
  FunctionRef function;
  CondensationSet set;
  void apply(Project& project) const;
  std::string label() const { return "Move set"; }
};

/// A new shape; with `path`, the file of a mesh or VDB set too (one undo step: a mesh path is no
/// VDB path, and the other way round).
struct SetSetShape {
  FunctionRef function;
  SetShape shape = SetShape::Sphere;
  std::optional<std::string> path;
  void apply(Project& project) const;
  /// "Set shape: " and the shape's name ("Set shape: torus").
  std::string label() const;
};

/// The file of a mesh or VDB set, relative to the project file's folder.
struct SetSetFile {
  FunctionRef function;
  std::string path;
  void apply(Project& project) const;
  std::string label() const { return "Set set file"; }
};

/// Whether a mesh set is its enclosed volume or its surface.
struct SetSetFill {
  FunctionRef function;
  SetFill fill = SetFill::Solid;
  void apply(Project& project) const;
  /// "Fill solid" or "Fill surface".
  std::string label() const;
};

/// The name of the float grid a VDB set reads.
struct SetSetGrid {
  FunctionRef function;
  std::string grid;
  void apply(Project& project) const;
  std::string label() const { return "VDB grid name"; }
};

/// The axis of the rotated median (Sokolov & Gentil, §4.1); its angle per unit of distance
/// between the sets' centres is a number set by SetParameter ("functions[i].rotate").
struct SetMedianAxis {
  FunctionRef function;
  Vec3 axis{0.0, 0.0, 1.0};
  void apply(Project& project) const;
  std::string label() const { return "Median rotation axis"; }
};

}  // namespace gridifs
