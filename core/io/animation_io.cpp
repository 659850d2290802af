#include "io/animation_io.h"

#include <cmath>
#include <sstream>

#include "base/errors.h"
#include "io/animation_json.h"
#include "io/project_io.h"
#include "io/settings_json.h"
#include "model/settings_tables.h"

namespace gridifs {
namespace {

using json = nlohmann::json;

// Tracks are reported as tracks["functions[0].weight"], so the path inside stays readable.
std::string trackPath(const std::string& path) { return "tracks[\"" + path + "\"]"; }

double finiteNumber(const json& j, const std::string& path) {
  if (!j.is_number()) throw ModelError(path, "expected a number");
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw ModelError(path, "expected a finite number");
  return v;
}

// "functions[0].ops[1].k" → the JSON pointer /functions/0/ops/1/k; empty on a malformed path.
std::optional<json::json_pointer> pointerFor(const std::string& path) {
  if (path.empty() || path.size() > 256) return std::nullopt;
  std::string pointer;
  std::size_t i = 0;
  while (i < path.size()) {
    std::size_t end = i;
    while (end < path.size() && path[end] != '.' && path[end] != '[') ++end;
    if (end == i) return std::nullopt;  // an empty name
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
      if (i == path.size()) return std::nullopt;  // a trailing dot
    }
  }
  return json::json_pointer(pointer);
}

json::json_pointer resolve(const json& document, const std::string& path) {
  const auto pointer = pointerFor(path);
  if (!pointer) throw ModelError(trackPath(path), "is not a parameter path like functions[0].ops[1].k");
  if (!document.contains(*pointer))
    throw ModelError(trackPath(path), "names no parameter of this project (was it deleted?)");
  const json& target = document.at(*pointer);
  if (!target.is_number())
    throw ModelError(trackPath(path), "names a parameter that is not a number, so it cannot be keyframed");
  return *pointer;
}

}  // namespace

void readAnimation(const json& root, Project& project) {
  if (auto it = root.find("time"); it != root.end()) {
    project.time = finiteNumber(*it, "time");
  }
  if (auto it = root.find("animation"); it != root.end() && !it->is_null()) {
    if (!it->is_object()) throw ModelError("animation", "expected an object with fps, start, end and loop");
    project.animation = readSettings(animationSettingsTable(), *it, "animation");
  }
  if (auto it = root.find("tracks"); it != root.end() && !it->is_null()) {
    if (!it->is_object()) throw ModelError("tracks", "expected an object from parameter paths to lists of keys");
    if (it->size() > 10000) throw ModelError("tracks", "more than 10000 tracks");
    for (const auto& [path, keys] : it->items()) {
      const std::string at = trackPath(path);
      if (!pointerFor(path)) throw ModelError(at, "is not a parameter path like functions[0].ops[1].k");
      if (!keys.is_array()) throw ModelError(at, "expected a list of keys {\"t\", \"v\", \"interp\"}");
      if (keys.size() > 100000) throw ModelError(at, "more than 100000 keys");
      KeyframeTrack track;
      for (std::size_t i = 0; i < keys.size(); ++i) {
        const std::string keyPath = at + "[" + std::to_string(i) + "]";
        const json& k = keys[i];
        if (!k.is_object()) throw ModelError(keyPath, "expected a key {\"t\", \"v\", \"interp\"}");
        Keyframe key;
        const auto t = k.find("t");
        const auto v = k.find("v");
        if (t == k.end()) throw ModelError(keyPath + ".t", "the key has no time");
        if (v == k.end()) throw ModelError(keyPath + ".v", "the key has no value");
        key.t = finiteNumber(*t, keyPath + ".t");
        key.v = finiteNumber(*v, keyPath + ".v");
        if (auto interp = k.find("interp"); interp != k.end()) {
          if (!interp->is_string() || !parseKeyInterpolation(interp->get<std::string>(), key.interp))
            throw ModelError(keyPath + ".interp", "expected \"step\", \"linear\" or \"smooth\"");
        }
        track.keys.push_back(key);
      }
      try {
        track.validate();
      } catch (const ModelError& e) {
        throw ModelError(at + e.path(), e.message());
      }
      project.tracks.emplace(path, std::move(track));
    }
  }
}

void writeAnimation(const Project& project, nlohmann::ordered_json& root) {
  if (project.time != 0.0) root["time"] = project.time;
  if (project.animation) root["animation"] = writeSettings(animationSettingsTable(), *project.animation);
  if (!project.tracks.empty()) {
    nlohmann::ordered_json tracks = nlohmann::ordered_json::object();
    for (const auto& [path, track] : project.tracks) {
      nlohmann::ordered_json keys = nlohmann::ordered_json::array();
      for (const Keyframe& k : track.keys) keys.push_back({{"t", k.t}, {"v", k.v}, {"interp", toString(k.interp)}});
      tracks[path] = keys;
    }
    root["tracks"] = tracks;
  }
}

void checkTrackPaths(const Project& project) {
  if (project.tracks.empty()) return;
  const json document = json::parse(serializeProject(project));
  for (const auto& [path, track] : project.tracks) resolve(document, path);
}

Project projectAtTime(const Project& project, double t) {
  if (!std::isfinite(t)) throw ModelError("time", "expected a finite number");
  if (project.tracks.empty()) {
    Project at = project;
    at.time = t;
    return at;
  }
  json document = json::parse(serializeProject(project));
  for (const auto& [path, track] : project.tracks) document[resolve(document, path)] = track.valueAt(t);
  document["time"] = t;
  try {
    return parseProject(document.dump());
  } catch (const ModelError& e) {
    std::ostringstream when;
    when << e.message() << " (at time " << t << ", from its keyframe track)";
    throw ModelError(e.path(), when.str());
  }
}

Project keyEditedParameters(const Project& before, Project next) {
  if (next.tracks.empty()) return next;
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
  return projectAtTime(next, next.time);
}

}  // namespace gridifs
