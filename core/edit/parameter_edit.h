#pragma once
// The one edit that sets any number of a project by its parameter path ("functions[0].ops[1].k",
// "render.flame.gamma", "camera.target[2]": the paths of keyframe tracks, schema/project_parameter.h).
// Panels, scripts and live control set numbers through it, so a value is accepted exactly when a
// project file holding it would be, with the file reader's words and path.
//
// Thread-safety: a plain value; apply() touches only the project given.
#include <string>

#include "model/project.h"

namespace gridifs {

struct SetParameter {
  std::string path;
  double value = 0.0;
  /// The undo step's name: the panel's label of the number ("Gamma"); empty: "Set " + path.
  std::string name{};
  /// Throws ModelError at `path` when it is not a path, names nothing this project holds (the
  /// numbers a file leaves out while they keep their defaults count: ParameterScope::Edit),
  /// names something that is not a number, or when the value is one a file could not hold
  /// there; the project is then unchanged.
  void apply(Project& project) const;
  std::string label() const { return name.empty() ? "Set " + path : name; }
};

/// The number at `path` as the project file holds it (a default the file leaves out reads as
/// that default). Throws ModelError as SetParameter does.
double parameterValue(const Project& project, const std::string& path);

}  // namespace gridifs
