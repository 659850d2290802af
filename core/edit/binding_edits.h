#pragma once
// Edits of a project's bindings (schema/live_binding.h) and of what live input recorded.
#include <map>
#include <string>
#include <vector>

#include "model/project.h"

namespace gridifs {

/// Adds `binding` (checked as the file reader checks it; ModelError when it is not valid).
/// A binding of the same path and source is replaced.
struct AddBinding {
  Binding binding;
  void apply(Project& project) const;
  std::string label() const { return "Bind " + binding.path; }
};

/// Removes the bindings of `path` (all of them when `source` is empty, else that one).
struct RemoveBinding {
  std::string path, source;
  void apply(Project& project) const;
  std::string label() const { return "Unbind " + path; }
};

/// A take of live input turned into keys: each path's keys replace its track's keys within
/// [start, end] (the take's span); other keys stay.
struct RecordTake {
  double start = 0.0, end = 0.0;
  std::map<std::string, std::vector<Keyframe>> keys;
  void apply(Project& project) const;
  std::string label() const { return "Record take"; }
};

}  // namespace gridifs
