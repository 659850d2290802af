#include "io/animation_json.h"

#include <cmath>

#include "anim/track_path.h"
#include "base/errors.h"
#include "io/settings_json.h"
#include "schema/settings_tables.h"

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
      if (!TrackPath::parse(path)) throw ModelError(at, "is not a parameter path like functions[0].ops[1].k");
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

}  // namespace gridifs
