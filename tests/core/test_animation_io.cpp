// Time, the timeline and keyframe tracks in the project file, and the project at a moment of
// its animation.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/errors.h"
#include "io/project_io.h"
#include "schema/project_time.h"

using namespace gridifs;
namespace fs = std::filesystem;

namespace {

std::string readText(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

Project sierpinski() { return loadProject(fs::path(GRIDIFS_ASSETS) / "sierpinski_tetrahedron.gridifs"); }

std::string animationErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(AnimationIo, ProjectsWithoutAnimationSaveUnchanged) {
  for (const auto& entry : fs::directory_iterator(GRIDIFS_ASSETS)) {
    if (entry.path().extension() != ".gridifs") continue;
    const Project p = loadProject(entry.path());
    EXPECT_TRUE(p.tracks.empty());
    EXPECT_FALSE(p.animation.has_value());
    const std::string text = serializeProject(p);
    EXPECT_EQ(text.find("\"tracks\""), std::string::npos) << entry.path();
    EXPECT_EQ(text.find("\"animation\""), std::string::npos) << entry.path();
    EXPECT_EQ(text.find("\"time\""), std::string::npos) << entry.path();
  }
}

TEST(AnimationIo, TimeTimelineAndTracksRoundTrip) {
  Project p = sierpinski();
  p.time = 1.25;
  p.animation = AnimationSettings{30.0, 0.0, 2.0, false};
  p.tracks["camera.yaw"].keys = {{0.0, 10.0, KeyInterpolation::Smooth}, {2.0, 50.0, KeyInterpolation::Linear}};
  p.tracks["functions[1].weight"].keys = {{0.5, 2.0, KeyInterpolation::Step}};
  const std::string text = serializeProject(p);
  const Project back = parseProject(text);
  EXPECT_EQ(back, p);
  EXPECT_EQ(serializeProject(back), text);
}

TEST(AnimationIo, TracksSetTheirParametersAtATime) {
  Project p = sierpinski();
  p.tracks["camera.yaw"].keys = {{0.0, 10.0}, {2.0, 50.0}};
  p.tracks["functions[1].weight"].keys = {{0.0, 1.0, KeyInterpolation::Step}, {1.0, 3.0}};
  p.tracks["render.flame.brightness"].keys = {{0.0, 2.0}, {4.0, 6.0}};
  const Project at = projectAtTime(p, 1.5);
  EXPECT_DOUBLE_EQ(at.camera.yaw, 40.0);
  EXPECT_DOUBLE_EQ(at.functions[1].weight, 3.0);
  EXPECT_DOUBLE_EQ(at.render.flame.brightness, 3.5);  // 2 + (6 - 2) · 1.5 / 4
  EXPECT_DOUBLE_EQ(at.time, 1.5);
  EXPECT_EQ(at.tracks, p.tracks);  // still animated
  const Project early = projectAtTime(p, 0.5);
  EXPECT_DOUBLE_EQ(early.functions[1].weight, 1.0);  // a step key holds until the next key
  // Without tracks only the time changes.
  Project still = sierpinski();
  Project moved = projectAtTime(still, 3.0);
  EXPECT_EQ(moved.time, 3.0);
  moved.time = still.time;
  EXPECT_EQ(moved, still);
}

TEST(AnimationIo, BadTracksAreErrorsWithTheirPath) {
  const std::string base = readText(fs::path(GRIDIFS_ASSETS) / "sierpinski_tetrahedron.gridifs");
  auto withTracks = [&](const std::string& tracks) {
    std::string text = base;
    text.insert(text.rfind('}'), ",\n  \"tracks\": " + tracks + "\n");
    return text;
  };
  EXPECT_EQ(animationErrorOf([&] { parseProject(withTracks(R"({"functions[9].weight": [{"t": 0, "v": 1}]})")); }),
            "tracks[\"functions[9].weight\"]: names no parameter of this project (was it deleted?)");
  EXPECT_EQ(animationErrorOf([&] { parseProject(withTracks(R"({"functions[0].name": [{"t": 0, "v": 1}]})")); }),
            "tracks[\"functions[0].name\"]: names a parameter that is not a number, so it cannot be keyframed");
  EXPECT_EQ(animationErrorOf([&] { parseProject(withTracks(R"({"camera..yaw": [{"t": 0, "v": 1}]})")); }),
            "tracks[\"camera..yaw\"]: is not a parameter path like functions[0].ops[1].k");
  EXPECT_EQ(
      animationErrorOf([&] { parseProject(withTracks(R"({"camera.yaw": [{"t": 1, "v": 1}, {"t": 0, "v": 2}]})")); }),
      "tracks[\"camera.yaw\"][1].t: keys must be in increasing time order");
  EXPECT_EQ(
      animationErrorOf([&] { parseProject(withTracks(R"({"camera.yaw": [{"t": 1, "v": 1, "interp": "cubic"}]})")); }),
      "tracks[\"camera.yaw\"][0].interp: expected \"step\", \"linear\" or \"smooth\"");
  EXPECT_EQ(animationErrorOf([&] { parseProject(withTracks(R"({"camera.yaw": [{"v": 1}]})")); }),
            "tracks[\"camera.yaw\"][0].t: the key has no time");
  // A key value the parameter does not accept is reported when the time reaches it.
  Project p = sierpinski();
  p.tracks["camera.pitch"].keys = {{0.0, 0.0}, {1.0, 500.0}};
  EXPECT_NO_THROW(projectAtTime(p, 0.0));
  const std::string late = animationErrorOf([&] { projectAtTime(p, 1.0); });
  EXPECT_NE(late.find("camera.pitch"), std::string::npos) << late;
  EXPECT_NE(late.find("at time 1"), std::string::npos) << late;
}

TEST(AnimationIo, BadTimelineIsAnError) {
  const std::string base = readText(fs::path(GRIDIFS_ASSETS) / "sierpinski_tetrahedron.gridifs");
  std::string text = base;
  text.insert(text.rfind('}'), ",\n  \"animation\": {\"fps\": 0}\n");
  EXPECT_EQ(animationErrorOf([&] { parseProject(text); }), "animation.fps: frames per second must be in (0, 1000]");
}

TEST(AnimationIo, EditingAnAnimatedParameterKeysItAtTheCurrentTime) {
  Project p = sierpinski();
  p.tracks["camera.yaw"].keys = {{0.0, 10.0, KeyInterpolation::Smooth}, {2.0, 50.0}};
  p = projectAtTime(p, 1.0);
  Project edited = p;
  edited.camera.yaw = 100.0;
  edited.camera.pitch = p.camera.pitch + 5.0;  // not animated: stays as edited, no track
  const Project keyed = keyEditedParameters(p, edited);
  ASSERT_EQ(keyed.tracks.at("camera.yaw").keys.size(), 3u);
  EXPECT_EQ(keyed.tracks.at("camera.yaw").keys[1], (Keyframe{1.0, 100.0, KeyInterpolation::Linear}));
  EXPECT_DOUBLE_EQ(keyed.camera.yaw, 100.0);
  EXPECT_DOUBLE_EQ(keyed.camera.pitch, p.camera.pitch + 5.0);
  EXPECT_EQ(keyed.tracks.count("camera.pitch"), 0u);
  // A key already at that time is updated and keeps its interpolation.
  Project atStart = projectAtTime(keyed, 0.0);
  Project again = atStart;
  again.camera.yaw = -20.0;
  const Project updated = keyEditedParameters(atStart, again);
  EXPECT_EQ(updated.tracks.at("camera.yaw").keys.front(), (Keyframe{0.0, -20.0, KeyInterpolation::Smooth}));
  // Moving the time alone sets every animated parameter from its track.
  Project later = updated;
  later.time = 2.0;
  EXPECT_DOUBLE_EQ(keyEditedParameters(updated, later).camera.yaw, 50.0);
  EXPECT_EQ(keyEditedParameters(updated, later).tracks, updated.tracks);
}
