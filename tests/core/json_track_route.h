#pragma once
// The way keyframe tracks reached their parameters before the typed accessors: the project
// serialised to JSON, patched through a JSON pointer per track, and parsed back. Kept verbatim as
// the reference the accessors are tested against (test_project_time.cpp) and measured against
// (bench_tracks.cpp); the product no longer uses it.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "anim/track_path.h"
#include "base/errors.h"
#include "io/project_io.h"
#include "schema/project_time.h"
#include "schema/wind_drift.h"

namespace gridifs::json_track_route {

using json = nlohmann::json;

inline std::string trackPath(const std::string& path) { return "tracks[\"" + path + "\"]"; }

inline std::optional<json::json_pointer> pointerFor(const std::string& path) {
  if (path.empty() || path.size() > 256) return std::nullopt;
  std::string pointer;
  std::size_t i = 0;
  while (i < path.size()) {
    std::size_t end = i;
    while (end < path.size() && path[end] != '.' && path[end] != '[') ++end;
    if (end == i) return std::nullopt;
    pointer += "/" + path.substr(i, end - i);
    i = end;
    while (i < path.size() && path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos || close == i + 1) return std::nullopt;
      const std::string index = path.substr(i + 1, close - i - 1);
      if (index.find_first_not_of("0123456789") != std::string::npos || index.size() > 6) return std::nullopt;
      pointer += "/" + index;
      i = close + 1;
    }
    if (i < path.size()) {
      if (path[i] != '.') return std::nullopt;
      ++i;
      if (i == path.size()) return std::nullopt;
    }
  }
  return json::json_pointer(pointer);
}

inline json::json_pointer resolve(const json& document, const std::string& path) {
  const auto pointer = pointerFor(path);
  if (!pointer) throw ModelError(trackPath(path), "is not a parameter path like functions[0].ops[1].k");
  if (!document.contains(*pointer))
    throw ModelError(trackPath(path), "names no parameter of this project (was it deleted?)");
  if (!document.at(*pointer).is_number())
    throw ModelError(trackPath(path), "names a parameter that is not a number, so it cannot be keyframed");
  return *pointer;
}

inline void checkTrackPaths(const Project& project) {
  const json document = json::parse(serializeProject(project));
  for (const auto& [path, track] : project.tracks) resolve(document, path);
}

inline Project projectAtTime(const Project& project, double t) {
  if (!std::isfinite(t)) throw ModelError("time", "expected a finite number");
  // Without tracks there is no route to compare: the project at t is the one under test's.
  if (project.tracks.empty()) return gridifs::projectAtTime(project, t);
  json document = json::parse(serializeProject(project));
  for (const auto& [path, track] : project.tracks) document[resolve(document, path)] = track.valueAt(t);
  document["time"] = t;
  try {
    // parseProject checks the track paths with the accessors under test: read the file without
    // them and check them here, through the JSON, as parseProject does last.
    json withoutTracks = document;
    withoutTracks.erase("tracks");
    Project at = parseProject(withoutTracks.dump());
    at.tracks = project.tracks;
    json_track_route::checkTrackPaths(at);
    applyWindDrift(at);
    return at;
  } catch (const ModelError& e) {
    std::ostringstream when;
    when << e.message() << " (at time " << t << ", from its keyframe track)";
    throw ModelError(e.path(), when.str());
  }
}

inline Project keyEditedParameters(const Project& before, Project next) {
  if (next.tracks.empty()) {
    applyWindDrift(next);
    return next;
  }
  const json was = json::parse(serializeProject(before));
  const json now = json::parse(serializeProject(next));
  for (auto& [path, track] : next.tracks) {
    const json::json_pointer pointer = resolve(now, path);
    if (!was.contains(pointer) || !was.at(pointer).is_number()) continue;
    const double value = now.at(pointer).get<double>();
    if (value == was.at(pointer).get<double>()) continue;
    Keyframe key{next.time, value, KeyInterpolation::Linear};
    for (const Keyframe& k : track.keys)
      if (std::abs(k.t - next.time) <= 1e-9) key.interp = k.interp;
    track.setKey(key);
  }
  return json_track_route::projectAtTime(next, next.time);
}

}  // namespace gridifs::json_track_route
