// Keyframe tracks reach their parameters through typed accessors (schema/project_parameter.h).
// The project file is the contract: a path names exactly the numbers the file holds, and the
// project at a moment is what writing every keyed value into the file and reading it back
// gives. These tests hold the accessors to a reference that does just that, through the JSON,
// for every number of every example project and of projects that use every kind of field.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>

#include "anim/track_path.h"
#include "base/errors.h"
#include "io/project_io.h"
#include "schema/project_parameter.h"
#include "schema/project_time.h"
#include "tests/core/json_track_route.h"

namespace gridifs {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// The reference: tracks written into the project's JSON and read back (json_track_route.h).
namespace trackRoute = json_track_route;

// ---- helpers ---------------------------------------------------------------------------------

/// What a call gave: a project or an error's text.
struct Outcome {
  std::optional<Project> project;
  std::string error;
};

Outcome outcome(const std::function<Project()>& f) {
  try {
    return {f(), ""};
  } catch (const ModelError& e) {
    return {std::nullopt, e.what()};
  }
}

void expectSame(const Outcome& expected, const Outcome& actual, const std::string& context) {
  EXPECT_EQ(actual.error, expected.error) << context;
  ASSERT_EQ(actual.project.has_value(), expected.project.has_value()) << context;
  if (expected.project) {
    EXPECT_TRUE(*actual.project == *expected.project) << context;
    EXPECT_EQ(serializeProject(*actual.project), serializeProject(*expected.project)) << context;
  }
}

/// Every value of the project's JSON by its path, in document order ("camera.target[1]").
void collect(const json& j, const std::string& path, std::vector<std::pair<std::string, const json*>>& out) {
  out.push_back({path, &j});
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) collect(*it, path.empty() ? it.key() : path + "." + it.key(), out);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) collect(j[i], path + "[" + std::to_string(i) + "]", out);
  }
}

ParameterLookup lookup(const Project& project, const std::string& path) {
  const auto parsed = TrackPath::parse(path);
  return parsed ? findParameter(project, *parsed).lookup : ParameterLookup::Missing;
}

// A grid function with every operation, a center point, a selection and a muted operation; a
// function with flame variations and a post map, a final function with a post matrix, transitions, a volume with a
// field, a timeline with a shutter, flame and shading settings that are written only when changed.
const char* const kEveryGridField = R"({
  "format": "gridifs", "version": 1, "time": 0.5,
  "animation": {"fps": 24, "start": 0, "end": 4, "loop": true, "shutter": 0.25},
  "render": {"mode": "shaded", "flame": {"density_unit": 2.0},
             "shading": {"lights": [{"direction": [1, 1, 1], "color": [1, 0.9, 0.8], "intensity": 1.5}],
                         "dof": {"aperture": 0.1, "focus": 3.0}}},
  "functions": [
    {"name": "a", "sampling_error": 0.01, "placement": {"scale": [0.5, 0.5, 0.5]}, "ops": [
      {"type": "translate", "offset": [0.1, 0, 0]},
      {"type": "rotate", "angles": [0, 0, 30]},
      {"type": "scale", "factors": [1, 1, 0.8]},
      {"type": "taper", "axis": "z", "profile": "sine", "k": 0.3, "omega": 3.14159, "center": [0.1, 0.2, 0.3],
       "selection": [{"i": [0, 2], "j": [0, 5], "k": [1, 5], "op": "or"}]},
      {"type": "twist", "axis": "z", "profile": "linear", "k": 1.2, "omega": 1.0, "center": "selection"},
      {"type": "bend", "axis": "z", "toward": "y", "k": 0.8},
      {"type": "magnet", "point": [0.2, 0, 0], "dmax": 0.8, "strength": 0.5, "falloff": 2, "muted": true},
      {"type": "morph", "pairs": [[[0, 0, 0], [0.1, 0.2, 0]]], "strength": 1.0},
      {"type": "calculator", "x": "x + v1*t", "y": "y", "z": "z",
       "vars": {"v1": {"value": 0.2, "min": -1, "max": 1}}, "seed": 7},
      {"type": "nodes", "moves": [[1, 2, 3, [0.0, 0.1, 0.0]]]},
      {"type": "field", "amplitude": [0.1, 0.1, 0.1], "octaves": 3, "seed": 3, "wind": [0.2, 0, 0],
       "period": [0, 0, 0, 4]}
    ]},
    {"name": "b", "weight": 2, "placement": {"translate": [0.5, 0, 0], "scale": [0.5, 0.5, 0.5]},
     "variations": {"julian": 0.3, "linear": 0.7}, "variation_params": {"julian_dist": 1, "julian_power": 3},
     "post": {"rotate": [0, 0, 15], "scale": [1, 1, 1], "translate": [0.1, 0, 0]}}
  ],
  "final": {"name": "final", "placement": {"scale": [0.9, 0.9, 0.9]}, "variations": {"spherical": 1},
            "post": {"matrix": [[1, 0.1, 0, 0], [0, 1, 0, 0.2], [0, 0, 1, 0]]}},
  "transitions": [[1, 1], [1, 0.5]],
  "volume": {"resolution": 32, "field": {"strength": 0.5, "scale": 0.5, "seed": 2, "wind": [0.1, 0, 0]}}
})";

// Condensation and median functions with every kind of set.
const char* const kEverySet = R"({
  "format": "gridifs", "version": 1,
  "functions": [
    {"name": "A", "kind": "median", "weight": 2, "rotate": 10, "set": {"primitive": "sphere", "center": [-0.45, 0, 0], "radius": 0.35}},
    {"name": "B", "kind": "median", "set": {"primitive": "box", "center": [0.45, 0, 0], "size": [0.5, 0.5, 0.5]}},
    {"name": "C", "kind": "condensation", "set": {"primitive": "torus", "center": [0, 0.3, 0], "major": 0.4, "minor": 0.1, "axis": [0, 1, 0]}},
    {"name": "D", "kind": "condensation", "set": {"mesh": "tree.obj", "fill": "surface", "placement": {"translate": [0.6, 0, 0], "scale": [0.3, 0.3, 0.3]}}},
    {"name": "E", "kind": "condensation", "set": {"vdb": "cloud.vdb", "grid": "density", "threshold": 0.25}}
  ],
  "volume": {"iterations": 40, "skip": 5}
})";

std::vector<std::pair<std::string, Project>> projects() {
  std::vector<std::pair<std::string, Project>> all;
  all.emplace_back("every grid field", parseProject(kEveryGridField));
  all.emplace_back("every set", parseProject(kEverySet));
  for (const auto& entry : fs::recursive_directory_iterator(GRIDIFS_ASSETS))
    if (entry.path().extension() == ".gridifs")
      all.emplace_back(entry.path().filename().string(), loadProject(entry.path()));
  return all;
}

// The imported flame holds 57000 numbers, most of them node moves: the reference's JSON takes
// long to write and read, and the projects above have node moves too.
constexpr std::size_t kMaxNumbers = 5000;

KeyframeTrack ramp(double from, double to) {
  KeyframeTrack track;
  track.keys = {{0.0, from, KeyInterpolation::Linear}, {1.0, to, KeyInterpolation::Linear}};
  return track;
}

/// The sound and the bindings drive numbers; like tracks, they are no numbers to key or bind.
bool drivesNumbers(const std::string& path) { return path.rfind("audio", 0) == 0 || path.rfind("bindings", 0) == 0; }

// ---- tests -----------------------------------------------------------------------------------

TEST(ProjectParameter, PathsNameExactlyTheNumbersTheFileHolds) {
  for (const auto& [name, project] : projects()) {
    const json document = json::parse(serializeProject(project));
    std::vector<std::pair<std::string, const json*>> values;
    collect(document, "", values);
    for (const auto& [path, value] : values) {
      // Tracks are no parameters, nor is the construction tree (the functions are its value), nor
      // are the states' indices (structure, not quantities).
      if (path.empty() || path.rfind("tracks", 0) == 0 || path.rfind("construction", 0) == 0 || drivesNumbers(path))
        continue;
      if (path.rfind("states", 0) == 0) {
        EXPECT_EQ(findParameter(project, *TrackPath::parse(path)).lookup, ParameterLookup::NotANumber) << path;
        continue;
      }
      const auto parsed = TrackPath::parse(path);
      ASSERT_TRUE(parsed) << name << ": " << path;
      const FoundParameter found = findParameter(project, *parsed);
      if (!value->is_number()) {
        EXPECT_EQ(found.lookup, ParameterLookup::NotANumber) << name << ": " << path;
        continue;
      }
      ASSERT_EQ(found.lookup, ParameterLookup::Number) << name << ": " << path;
      EXPECT_EQ(found.parameter.get(project), value->get<double>()) << name << ": " << path;
      EXPECT_EQ(found.parameter.path(), path) << name;
      // Nothing lies inside a number, nor past the end of a list.
      EXPECT_EQ(lookup(project, path + ".x"), ParameterLookup::Missing) << name << ": " << path;
      EXPECT_EQ(lookup(project, path + "[0]"), ParameterLookup::Missing) << name << ": " << path;
    }
  }
}

TEST(ProjectParameter, SpellingsAJsonPointerReadsStillResolve) {
  const Project p = parseProject(kEveryGridField);
  EXPECT_EQ(lookup(p, "camera/yaw"), ParameterLookup::Number);
  EXPECT_EQ(lookup(p, "functions.0.weight"), ParameterLookup::Number);
  EXPECT_EQ(lookup(p, "functions[00].weight"), ParameterLookup::Missing);  // a leading zero
  EXPECT_EQ(lookup(p, "functions[2].weight"), ParameterLookup::Missing);
  EXPECT_EQ(lookup(p, "functions[0].ops[6].muted"), ParameterLookup::NotANumber);
  EXPECT_EQ(lookup(p, "functions[0].ops[5].muted"), ParameterLookup::Missing);  // written only when muted
  EXPECT_EQ(lookup(p, "functions[0].ops[4].center"), ParameterLookup::NotANumber);
  EXPECT_EQ(lookup(p, "functions[0].ops[4].center[0]"), ParameterLookup::Missing);
  EXPECT_EQ(lookup(p, "functions[1].sampling_error"), ParameterLookup::Missing);
  EXPECT_EQ(lookup(p, "render.flame.density_unit"), ParameterLookup::Number);
  EXPECT_EQ(lookup(parseProject(kEverySet), "functions[0].placement.scale[0]"), ParameterLookup::Missing);
  EXPECT_FALSE(TrackPath::parse("camera.~2yaw"));
  EXPECT_FALSE(TrackPath::parse("camera..yaw"));
  EXPECT_FALSE(TrackPath::parse("camera.yaw."));
  EXPECT_FALSE(TrackPath::parse("functions[x].weight"));
}

// Every number keyed, one at a time, to values inside and outside its range, whole and not:
// the accessors give what writing the value into the file and reading it back gives, or the
// same error.
TEST(ProjectTime, KeyingAnyNumberGivesWhatTheFileWouldHold) {
  const double candidates[] = {0.25, -1.0, 2.0, 1e7, 3.0, 0.0, 1.0, 70.0};
  std::size_t candidate = 0, compared = 0;
  for (const auto& [name, project] : projects()) {
    std::vector<std::pair<std::string, const json*>> values;
    const json document = json::parse(serializeProject(project));
    collect(document, "", values);
    std::vector<std::string> numbers;
    for (const auto& [path, value] : values)
      if (value->is_number() && path.rfind("tracks", 0) != 0 && path.rfind("states", 0) != 0 && !drivesNumbers(path))
        numbers.push_back(path);
    if (numbers.size() > kMaxNumbers) continue;
    // Some 16 numbers of each project, spread over all of it.
    const std::size_t stride = std::max<std::size_t>(1, numbers.size() / 16);
    for (std::size_t n = 0; n < numbers.size(); n += stride) {
      const std::string& path = numbers[n];
      const double from = document.at(*trackRoute::pointerFor(path)).get<double>();
      for (int pass = 0; pass < 2; ++pass) {
        Project keyed = project;
        keyed.tracks[path] = ramp(from, candidates[candidate++ % std::size(candidates)]);
        for (double t : {1.0, 0.5}) {
          const std::string context = name + ": " + path + " at " + std::to_string(t);
          expectSame(outcome([&] { return trackRoute::projectAtTime(keyed, t); }),
                     outcome([&] { return projectAtTime(keyed, t); }), context);
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, 1000u);  // numbers × 2 values × 2 times
}

TEST(ProjectTime, ManyTracksTogetherAndEdits) {
  for (const auto& [name, project] : projects()) {
    // Every number keyed at once to the value it has: nothing changes but the time.
    const json document = json::parse(serializeProject(project));
    std::vector<std::pair<std::string, const json*>> values;
    collect(document, "", values);
    Project keyed = project;
    std::vector<std::string> numbers;
    for (const auto& [path, value] : values)
      if (value->is_number() && path.rfind("tracks", 0) != 0 && path.rfind("states", 0) != 0 && path != "version" &&
          path != "time" && !drivesNumbers(path))
        numbers.push_back(path);
    if (numbers.size() > kMaxNumbers) continue;
    // Up to 200 numbers of each project, spread over all of it.
    const std::size_t stride = std::max<std::size_t>(1, numbers.size() / 200);
    std::vector<std::string> tracked;
    for (std::size_t n = 0; n < numbers.size(); n += stride) {
      const double value = document.at(*trackRoute::pointerFor(numbers[n])).get<double>();
      keyed.tracks[numbers[n]] = ramp(value, value);
      tracked.push_back(numbers[n]);
    }
    numbers = tracked;
    expectSame(outcome([&] { return trackRoute::projectAtTime(keyed, 0.75); }),
               outcome([&] { return projectAtTime(keyed, 0.75); }), name + ": all keyed");
    // An edit of a keyed number keys it; an edit of a number that is not keyed does not.
    const Project at = projectAtTime(keyed, 0.75);
    for (std::size_t n = 0; n < numbers.size(); n += std::max<std::size_t>(1, numbers.size() / 5)) {
      Project edited = at;
      const ProjectParameter parameter = findParameter(at, *TrackPath::parse(numbers[n])).parameter;
      try {
        parameter.set(edited, parameter.get(at) == 0.0 ? 0.5 : parameter.get(at) * 0.5);
      } catch (const ModelError&) {
        continue;  // not a value the file allows
      }
      expectSame(outcome([&] { return trackRoute::keyEditedParameters(at, edited); }),
                 outcome([&] { return keyEditedParameters(at, edited); }), name + ": edit " + numbers[n]);
      Project untracked = edited;
      untracked.tracks.erase(numbers[n]);
      expectSame(outcome([&] { return trackRoute::keyEditedParameters(at, untracked); }),
                 outcome([&] { return keyEditedParameters(at, untracked); }), name + ": untracked " + numbers[n]);
    }
  }
}

TEST(ProjectTime, ValuesTheFileRefusesAreErrorsWithTheReadersWords) {
  Project p = parseProject(kEveryGridField);
  auto errorAt = [&](const std::string& path, double v) {
    Project keyed = p;
    keyed.tracks[path] = ramp(v, v);
    return outcome([&] { return projectAtTime(keyed, 1.0); }).error;
  };
  EXPECT_EQ(errorAt("functions[0].ops[10].octaves", 2.5),
            "functions[0].ops[10].octaves: expected an integer (at time 1, from its keyframe track)");
  EXPECT_EQ(errorAt("functions[1].weight", -1.0),
            "functions[1].weight: expected a number between 0 and 1e+09, found -1 (at time 1, from its keyframe "
            "track)");
  EXPECT_EQ(errorAt("functions/1/color[2]", 2.0),
            "functions[1].color[2]: expected a number between 0 and 1, found 2 (at time 1, from its keyframe track)");
  EXPECT_EQ(errorAt("animation.end", -1.0),
            "animation.end: the animation must not end before it starts (at time 1, from its keyframe track)");
  EXPECT_EQ(errorAt("version", 2.0),
            "version: unsupported version 2.0 (this GridIFS reads version 1) (at time 1, from its keyframe track)");
  // A number written only while it differs from its default is gone once keyed to the default.
  EXPECT_EQ(errorAt("render.flame.density_unit", 1.0),
            "tracks[\"render.flame.density_unit\"]: names no parameter of this project (was it deleted?) (at time 1, "
            "from its keyframe track)");
}

}  // namespace
}  // namespace gridifs
