#include "schema/project_time.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "anim/track_path.h"
#include "base/errors.h"
#include "schema/project_parameter.h"
#include "schema/settings_tables.h"
#include "schema/validation.h"
#include "schema/wind_drift.h"

namespace gridifs {
namespace {

// Tracks are reported as tracks["functions[0].weight"], so the path inside stays readable.
std::string trackPath(const std::string& path) { return "tracks[\"" + path + "\"]"; }

[[noreturn]] void noParameter(const std::string& path) {
  throw ModelError(trackPath(path), "names no parameter of this project (was it deleted?)");
}

std::optional<TrackPath> parse(const std::string& path) {
  std::optional<TrackPath> parsed = TrackPath::parse(path);
  if (!parsed) throw ModelError(trackPath(path), "is not a parameter path like functions[0].ops[1].k");
  return parsed;
}

/// The number `path` names in `project`. Throws ModelError naming the track when it names none.
ProjectParameter resolve(const Project& project, const std::string& path, const TrackPath& parsed) {
  const FoundParameter found = findParameter(project, parsed);
  switch (found.lookup) {
    case ParameterLookup::Number:
      break;
    case ParameterLookup::NotANumber:
      throw ModelError(trackPath(path), "names a parameter that is not a number, so it cannot be keyframed");
    case ParameterLookup::Missing:
      noParameter(path);
  }
  return found.parameter;
}

/// A track and the number it drives, resolved in the project it animates.
struct Keyed {
  const std::string* path;
  const KeyframeTrack* track;
  ProjectParameter parameter;
};

std::vector<Keyed> resolveTracks(const Project& project) {
  std::vector<Keyed> keyed;
  keyed.reserve(project.tracks.size());
  for (const auto& [path, track] : project.tracks)
    keyed.push_back({&path, &track, resolve(project, path, *parse(path))});
  return keyed;
}

/// Writes every track's value at t to its parameter and t to the time, then checks `project` as
/// reading a file that holds it would: each value with its reader's words (in the order reading
/// meets them), the timeline, the whole project, and whether each track still names a number.
/// Errors say the time. `keyed` was resolved in `project` (setting values leaves every number
/// where it was).
void applyTracks(Project& project, const std::vector<Keyed>& keyed, double t) {
  struct Value {
    const Keyed* keyed;
    double v;
  };
  std::vector<Value> values;
  values.reserve(keyed.size());
  for (const Keyed& k : keyed) values.push_back({&k, k.track->valueAt(t)});
  // Stable: of two tracks on one number (spelt apart, "camera.yaw" and "camera/yaw") the later
  // one, as the tracks are ordered, sets it.
  std::stable_sort(values.begin(), values.end(),
                   [](const Value& a, const Value& b) { return a.keyed->parameter.readBefore(b.keyed->parameter); });
  try {
    bool animation = false;
    for (std::size_t i = 0; i < values.size(); ++i) {
      const ProjectParameter& parameter = values[i].keyed->parameter;
      if (i + 1 < values.size() && parameter.sameNumber(values[i + 1].keyed->parameter)) continue;
      if (parameter.isTime()) continue;  // the moment sets the time
      parameter.set(project, values[i].v);
      animation |= parameter.inAnimation();
    }
    project.time = t;
    // Reading validates the timeline with its group; validateProject does not cover it.
    if (animation) validateSettings(animationSettingsTable(), *project.animation, "animation");
    validateProject(project);
    for (const Keyed& k : keyed)
      if (k.parameter.dependsOnValues() && findParameter(project, *parse(*k.path)).lookup != ParameterLookup::Number)
        noParameter(*k.path);
  } catch (const ModelError& e) {
    std::ostringstream when;
    when << e.message() << " (at time " << t << ", from its keyframe track)";
    throw ModelError(e.path(), when.str());
  }
}

}  // namespace

void checkTrackPaths(const Project& project) {
  for (const auto& [path, track] : project.tracks) resolve(project, path, *parse(path));
}

Project projectAtTime(const Project& project, double t) {
  if (!std::isfinite(t)) throw ModelError("time", "expected a finite number");
  if (project.tracks.empty()) {
    Project at = project;
    at.time = t;
    applyWindDrift(at);
    return at;
  }
  const std::vector<Keyed> keyed = resolveTracks(project);
  Project at = project;
  applyTracks(at, keyed, t);
  applyWindDrift(at);
  return at;
}

Project keyEditedParameters(const Project& before, Project next) {
  if (next.tracks.empty()) {
    applyWindDrift(next);  // a drift left from removed wind keys goes
    return next;
  }
  std::vector<Keyed> keyed;
  keyed.reserve(next.tracks.size());
  for (auto& [path, track] : next.tracks) {
    const std::optional<TrackPath> parsed = parse(path);
    const ProjectParameter now = resolve(next, path, *parsed);
    const FoundParameter was = findParameter(before, *parsed);
    keyed.push_back({&path, &track, now});
    if (was.lookup != ParameterLookup::Number) continue;
    const double value = now.get(next);
    if (value == was.parameter.get(before)) continue;
    Keyframe key{next.time, value, KeyInterpolation::Linear};
    for (const Keyframe& k : track.keys)
      if (std::abs(k.t - next.time) <= 1e-9) key.interp = k.interp;
    track.setKey(key);
  }
  if (!std::isfinite(next.time)) throw ModelError("time", "expected a finite number");
  applyTracks(next, keyed, next.time);
  applyWindDrift(next);
  return next;
}

}  // namespace gridifs
