#pragma once
// Named edits of the keyframe tracks: set or remove keys at the project's current time on
// numbers named by their path in the project file ("render.flame.gamma", "camera.target[1]").
// Each edit is a plain value gathered in ProjectEdit (edit/project_edit.h).
//
// Thread-safety: plain values; apply() touches only the project given. They never throw: a key on
// a path that names no number of the project is refused where tracks are evaluated or saved
// (schema/project_time.h checkTrackPaths), as a track read from a file would be.
#include <string>
#include <vector>

#include "model/project.h"

namespace gridifs {

/// A number of the project by its path, with the value a key on it holds.
struct KeyedNumber {
  std::string path;
  double value = 0.0;
  bool operator==(const KeyedNumber&) const = default;
};

/// A key at the current time on each number, holding its value; a key already there keeps its
/// interpolation (new ones are linear). Several numbers keyed together are one undo step (the
/// camera's yaw, pitch, distance and target).
struct SetKeys {
  std::vector<KeyedNumber> numbers;
  void apply(Project& project) const;
  std::string label() const { return "Set key"; }
};

/// Removes the key at the current time from each path's track; a track left without keys goes.
struct RemoveKeys {
  std::vector<std::string> paths;
  void apply(Project& project) const;
  std::string label() const { return "Remove key"; }
};

}  // namespace gridifs
