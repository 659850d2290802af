#include "edit/key_edits.h"

#include <cmath>

namespace gridifs {
namespace {

constexpr double kSameTime = 1e-9;  // as KeyframeTrack::setKey

}  // namespace

void SetKeys::apply(Project& project) const {
  for (const KeyedNumber& n : numbers) {
    KeyframeTrack& track = project.tracks[n.path];
    Keyframe k{project.time, n.value, KeyInterpolation::Linear};
    for (const Keyframe& old : track.keys)
      if (std::abs(old.t - project.time) <= kSameTime) k.interp = old.interp;
    track.setKey(k);
  }
}

void RemoveKeys::apply(Project& project) const {
  for (const std::string& path : paths) {
    const auto it = project.tracks.find(path);
    if (it == project.tracks.end()) continue;
    it->second.removeKey(project.time, kSameTime);
    if (it->second.keys.empty()) project.tracks.erase(it);
  }
}

}  // namespace gridifs
