#include "edit/binding_edits.h"

#include <algorithm>
#include <cmath>

#include "base/errors.h"
#include "schema/live_binding.h"

namespace gridifs {

void AddBinding::apply(Project& project) const {
  auto& list = project.bindings;
  list.erase(std::remove_if(list.begin(), list.end(),
                            [&](const Binding& b) { return b.path == binding.path && b.source == binding.source; }),
             list.end());
  list.push_back(binding);
  checkBindings(project);
}

void RemoveBinding::apply(Project& project) const {
  auto& list = project.bindings;
  const std::size_t before = list.size();
  list.erase(std::remove_if(list.begin(), list.end(),
                            [&](const Binding& b) { return b.path == path && (source.empty() || b.source == source); }),
             list.end());
  if (list.size() == before) throw ModelError("bindings", "nothing is bound to " + path);
}

void RecordTake::apply(Project& project) const {
  for (const auto& [path, recorded] : keys) {
    if (recorded.empty()) continue;
    std::vector<Keyframe>& track = project.tracks[path].keys;
    track.erase(std::remove_if(track.begin(), track.end(),
                               [&](const Keyframe& k) { return k.t >= start - 1e-9 && k.t <= end + 1e-9; }),
                track.end());
    track.insert(track.end(), recorded.begin(), recorded.end());
    std::sort(track.begin(), track.end(), [](const Keyframe& a, const Keyframe& b) { return a.t < b.t; });
    track.erase(std::unique(track.begin(), track.end(),
                            [](const Keyframe& a, const Keyframe& b) { return std::abs(a.t - b.t) < 1e-9; }),
                track.end());
  }
}

}  // namespace gridifs
