// SetParameter: any number of a project set by its parameter path, checked exactly as the file
// reader checks it, as one undo step; and parameterPaths, the list of those paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "anim/track_path.h"
#include "edit/document.h"
#include "edit/project_edit.h"
#include "io/parameter_paths.h"
#include "io/project_io.h"
#include "schema/project_parameter.h"

namespace gridifs {
namespace {

Project twisted() { return loadProject(std::string(GRIDIFS_ASSETS) + "/twisted_functions.gridifs"); }

/// The message parseProject gives for `project`'s file with `key` at `pointer` set to `value`.
std::string readerMessage(const Project& project, const std::string& pointer, double value) {
  nlohmann::json file = nlohmann::json::parse(serializeProject(project));
  file[nlohmann::json::json_pointer(pointer)] = value;
  try {
    parseProject(file.dump());
  } catch (const ModelError& e) {
    return e.what();
  }
  return "accepted";
}

std::string editMessage(Project project, const std::string& path, double value) {
  const Project before = project;
  try {
    applyEdit(project, SetParameter{path, value});
  } catch (const ModelError& e) {
    EXPECT_EQ(project, before) << "a refused value must leave the project as it was";
    return e.what();
  }
  return "accepted";
}

TEST(SetParameter, SetsTheNumberAtItsPath) {
  Project p = twisted();
  applyEdit(p, SetParameter{"functions[1].weight", 0.25});
  EXPECT_EQ(p.functions[1].weight, 0.25);
  applyEdit(p, SetParameter{"camera.yaw", 33.0});
  EXPECT_EQ(parameterValue(p, "camera.yaw"), 33.0);
  EXPECT_EQ(editLabel(SetParameter{"camera.yaw", 1.0}), "Set camera.yaw");
}

TEST(SetParameter, RefusesWhatTheFileReaderRefusesInItsWords) {
  const Project p = twisted();
  // A weight below 0, a size that is not a whole number, a size of 0, an angle too large.
  const struct {
    const char* path;
    const char* pointer;
    double value;
  } cases[] = {{"functions[0].weight", "/functions/0/weight", -1.0},
               {"render.width", "/render/width", 64.5},
               {"render.width", "/render/width", 0.0},
               {"functions[1].ops[0].k", "/functions/1/ops/0/k", 1e300}};
  for (const auto& c : cases) {
    const std::string reader = readerMessage(p, c.pointer, c.value);
    ASSERT_NE(reader, "accepted") << c.path;
    EXPECT_EQ(editMessage(p, c.path, c.value), reader) << c.path;
  }
}

TEST(SetParameter, NamesWhatIsWrongWithThePath) {
  const Project p = twisted();
  EXPECT_EQ(editMessage(p, "functions[9].weight", 1.0), "functions[9].weight: names nothing this project holds");
  EXPECT_EQ(editMessage(p, "functions[0].name", 1.0),
            "functions[0].name: is not a number (a string, a switch, a list or an object)");
  EXPECT_EQ(editMessage(p, "functions..weight", 1.0),
            "functions..weight: is not a parameter path like functions[0].ops[1].k");
  EXPECT_NE(editMessage(p, "version", 2.0), "accepted");
}

TEST(SetParameter, IsOneUndoStepOfTheDocument) {
  Document document(twisted());
  const Project before = document.project();
  document.apply(SetParameter{"functions[0].weight", 0.5});
  EXPECT_EQ(document.project().functions[0].weight, 0.5);
  EXPECT_EQ(document.undoLabel(), "Set functions[0].weight");
  ASSERT_TRUE(document.undo());
  EXPECT_EQ(document.project(), before);
  EXPECT_THROW(document.apply(SetParameter{"functions[0].weight", -2.0}), ModelError);
  EXPECT_EQ(document.project(), before);
  EXPECT_FALSE(document.canRedo() && document.undoLabel() == "Set functions[0].weight");
}

TEST(ParameterPaths, ListsEveryNumberOfTheFileThatIsAParameter) {
  const Project p = twisted();
  const std::vector<std::string> paths = parameterPaths(p);
  auto has = [&](const std::string& path) { return std::find(paths.begin(), paths.end(), path) != paths.end(); };
  EXPECT_TRUE(has("functions[0].weight"));
  EXPECT_TRUE(has("functions[1].ops[0].k"));
  EXPECT_TRUE(has("camera.yaw"));
  EXPECT_TRUE(has("camera.target[2]"));
  EXPECT_FALSE(has("version"));
  for (const std::string& path : paths) {
    const auto parsed = TrackPath::parse(path);
    ASSERT_TRUE(parsed) << path;
    EXPECT_EQ(findParameter(p, *parsed).lookup, ParameterLookup::Number) << path;
    // Every listed number reads back as itself through the edit.
    Project copy = p;
    applyEdit(copy, SetParameter{path, parameterValue(p, path)});
    EXPECT_EQ(copy, p) << path;
  }
}

}  // namespace
}  // namespace gridifs

namespace gridifs {
namespace {

// The numbers a file leaves out while they keep their defaults are set by an edit as a panel
// sets them: a variation's parameter, a setting written only when changed, the shading of a
// project that is not shaded, the volume render of a project without one. Keyframe tracks do not
// see them until the file holds them.
TEST(SetParameter, ReachesTheDefaultsTheFileLeavesOut) {
  Project p = twisted();
  p.functions[0].variations["julian"] = 1.0;
  const std::string power = "functions[0].variation_params.julian_power";
  EXPECT_EQ(parameterValue(p, power), 1.0);  // flam3's default
  EXPECT_EQ(findParameter(p, *TrackPath::parse(power)).lookup, ParameterLookup::Missing);
  applyEdit(p, SetParameter{power, 3.0});
  EXPECT_EQ(p.functions[0].variation_params.at("julian_power"), 3.0);
  EXPECT_EQ(findParameter(p, *TrackPath::parse(power)).lookup, ParameterLookup::Number);
  applyEdit(p, SetParameter{"functions[0].variations.julian", 0.25});
  EXPECT_EQ(p.functions[0].variations.at("julian"), 0.25);
  EXPECT_EQ(editMessage(p, "functions[0].variation_params.no_such_parameter", 1.0),
            "functions[0].variation_params.no_such_parameter: names nothing this project holds");

  EXPECT_FALSE(p.render.volume);
  EXPECT_EQ(parameterValue(p, "render.volume.density_scale"), VolumeRenderSettings{}.density_scale);
  applyEdit(p, SetParameter{"render.volume.density_scale", 5.0});
  ASSERT_TRUE(p.render.volume);
  EXPECT_EQ(p.render.volume->density_scale, 5.0);
  EXPECT_EQ(editMessage(p, "render.volume.resolution", 8.0), readerMessage(p, "/render/volume/resolution", 8.0));

  applyEdit(p, SetParameter{"render.flame.hue", 0.5});  // written only when changed
  EXPECT_EQ(p.render.flame.hue, 0.5);
  applyEdit(p, SetParameter{"render.shading.fog.density", 0.3});
  EXPECT_EQ(p.render.shading.fog.density, 0.3);
}

// The timeline's rule across its fields holds for an edit of one of them, as reading does.
TEST(SetParameter, KeepsTheTimelinesRule) {
  Project p = twisted();
  p.animation = AnimationSettings{};
  EXPECT_EQ(editMessage(p, "animation.start", 10.0), readerMessage(p, "/animation/start", 10.0));
  EXPECT_NE(editMessage(p, "animation.start", 10.0), "accepted");
  EXPECT_EQ(editMessage(p, "animation.start", 1.0), "accepted");
}

}  // namespace
}  // namespace gridifs
