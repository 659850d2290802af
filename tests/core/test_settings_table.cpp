// The settings tables: every field of every group is read, written and validated from its entry,
// the defaults are valid, and the panels' slider ranges stay inside what validation accepts.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>

#include "io/project_io.h"
#include "io/settings_json.h"
#include "model_error_text.h"
#include "schema/settings_tables.h"

using namespace gridifs;

namespace {

struct Group {
  const char* path;  // where the group stands in the project file
  const SettingTable* table;
  std::function<void*(Project&)> locate;
  /// Validation in memory (the animation is validated when it is read, not with the project).
  std::function<void(const Project&)> validate = [](const Project& p) { validateProject(p); };
};

std::vector<Group> groups() {
  return {
      {"camera", &cameraTable(), [](Project& p) -> void* { return &p.camera; }},
      {"camera.stereo", &stereoTable(),
       [](Project& p) -> void* { return &p.camera.stereo.emplace(p.camera.stereo.value_or(StereoSettings{})); }},
      {"render", &renderSettingsTable(), [](Project& p) -> void* { return &p.render; }},
      {"render.flame", &flameSettingsTable(), [](Project& p) -> void* { return &p.render.flame; }},
      {"render.shading", &shadingSettingsTable(), [](Project& p) -> void* { return &p.render.shading; }},
      {"render.shading.lights[0]", &shadingLightTable(),
       [](Project& p) -> void* { return &p.render.shading.lights.at(0); }},
      {"render.shading.ao", &ambientOcclusionTable(), [](Project& p) -> void* { return &p.render.shading.ao; }},
      {"render.shading.fog", &fogTable(), [](Project& p) -> void* { return &p.render.shading.fog; }},
      {"render.shading.dof", &depthOfFieldTable(), [](Project& p) -> void* { return &p.render.shading.dof; }},
      {"animation", &animationSettingsTable(),
       [](Project& p) -> void* { return &p.animation.emplace(p.animation.value_or(AnimationSettings{})); },
       [](const Project& p) { validateSettings(animationSettingsTable(), *p.animation, "animation"); }},
      {"volume", &volumeSettingsTable(),
       [](Project& p) -> void* { return &p.volume.emplace(p.volume.value_or(VolumeSettings{})); }},
  };
}

/// A valid project with one function (built out of line: GCC 12 warns about the inlined default
/// light list otherwise).
Project oneFunction() { return defaultNewProject(); }

/// The message reading a project with `block` set to `text` gives ("" when it reads).
std::string readingMessage(const char* block, const char* text) {
  nlohmann::json root = nlohmann::json::parse(serializeProject(oneFunction()));
  root[block] = nlohmann::json::parse(text);
  return test_support::modelErrorText([&] { parseProject(root.dump()); });
}

bool isNumber(const SettingSpec& s) {
  return s.type == SettingType::Number || s.type == SettingType::Integer || s.type == SettingType::Count ||
         s.type == SettingType::OptionalNumber;
}

/// The JSON object at `path` ("render.shading.lights[0]") inside `root`.
nlohmann::json& at(nlohmann::json& root, const std::string& path) {
  nlohmann::json* node = &root;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t dot = path.find('.', start);
    std::string part = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    const std::size_t bracket = part.find('[');
    if (bracket == std::string::npos) {
      node = &(*node)[part];
    } else {
      node = &(*node)[part.substr(0, bracket)][std::stoul(part.substr(bracket + 1))];
    }
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return *node;
}

}  // namespace

TEST(SettingsTable, KeysAreUniqueAndNumbersHaveSaneRanges) {
  for (const Group& g : groups()) {
    SCOPED_TRACE(g.path);
    std::set<std::string> keys;
    for (const SettingSpec& s : g.table->fields) {
      EXPECT_TRUE(keys.insert(s.key).second) << s.key;
      EXPECT_EQ(&g.table->field(s.key), &s);
      if (isNumber(s) || s.type == SettingType::Vector) {
        EXPECT_LT(s.min, s.max) << s.key;
      }
      // A slider never offers a value that validation would refuse.
      if (s.sliderMin < s.sliderMax) {
        EXPECT_GE(s.sliderMin, s.min) << s.key;
        EXPECT_LE(s.sliderMax, s.max) << s.key;
        EXPECT_NE(std::string(s.label), "") << s.key;
        EXPECT_NE(std::string(s.tooltip), "") << s.key;
      }
    }
  }
  EXPECT_THROW(flameSettingsTable().field("no_such_field"), std::logic_error);
}

TEST(SettingsTable, DefaultsAreValidAndEveryFieldIsWritten) {
  Project p = oneFunction();
  p.render.shading.dof.focus = 2.0;   // an unset optional is not written
  p.render.flame.density_unit = 2.0;  // the default is omitted
  p.render.flame.hue = 0.1;           // likewise the flame controls' fields
  p.render.flame.palette_keys = "0:#000000 1:#ffffff";
  p.render.flame.density_display = "linear";
  p.render.quality = 50.0;
  p.animation = AnimationSettings{};
  p.animation->shutter = 0.25;  // the default is omitted
  p.animation->motion_blur = 2;
  p.animation->motion_fade = 1.0;
  p.volume = VolumeSettings{};
  p.camera.projection = CameraProjection::Fisheye;  // "projection" is written for panoramic cameras
  p.camera.stereo = StereoSettings{};
  p.camera.roll = 10.0;
  EXPECT_NO_THROW(validateProject(p));
  p.render.mode = DisplayMode::Shaded;  // writes render.shading
  nlohmann::json root = nlohmann::json::parse(serializeProject(p));
  const auto flatOnly = [](const SettingSpec& s) {
    return std::string(s.key).rfind("shift_", 0) == 0 || std::string(s.key) == "lens_blur";
  };
  for (const Group& g : groups()) {
    SCOPED_TRACE(g.path);
    const nlohmann::json& object = at(root, g.path);
    for (const SettingSpec& s : g.table->fields) {
      if (g.table == &cameraTable() && flatOnly(s)) continue;
      EXPECT_TRUE(object.contains(s.key)) << s.key;
    }
  }
  // A panoramic camera has no lens shift or lens blur: a flat one writes them.
  p.camera.projection = CameraProjection::Perspective;
  p.camera.shift_x = 0.1;
  p.camera.shift_y = -0.1;
  p.camera.lens_blur = 0.5;
  EXPECT_NO_THROW(validateProject(p));
  root = nlohmann::json::parse(serializeProject(p));
  EXPECT_TRUE(root["camera"].contains("shift_x"));
  EXPECT_TRUE(root["camera"].contains("shift_y"));
  EXPECT_TRUE(root["camera"].contains("lens_blur"));
}

TEST(SettingsTable, EveryNumberOutsideItsRangeIsRefusedWithItsPath) {
  for (const Group& g : groups()) {
    for (const SettingSpec& s : g.table->fields) {
      if (!isNumber(s) || s.min <= -limits::kMaxCoordinate) continue;
      const std::string path = std::string(g.path) + "." + s.key;
      SCOPED_TRACE(path);
      // In memory: validation names the field.
      Project p = oneFunction();
      s.setNumber(g.locate(p), s.min - 1.0);
      try {
        g.validate(p);
        ADD_FAILURE() << "no error";
      } catch (const ModelError& e) {
        EXPECT_EQ(e.path(), path) << e.what();
      }
      // In a file: reading names it too.
      p = oneFunction();
      p.render.mode = DisplayMode::Shaded;
      g.locate(p);
      nlohmann::json root = nlohmann::json::parse(serializeProject(p));
      at(root, g.path)[s.key] = s.max + 1.0;
      try {
        parseProject(root.dump());
        ADD_FAILURE() << "no error";
      } catch (const ModelError& e) {
        EXPECT_EQ(e.path(), path) << e.what();
      }
    }
  }
}

TEST(SettingsTable, MessagesNameTheMeaningWhereTheTableHasANoun) {
  Project p = oneFunction();
  p.render.shading.fog.density = -1.0;
  EXPECT_EQ(test_support::modelErrorText([&] { validateProject(p); }),
            "render.shading.fog.density: the fog density must not be negative, found -1");
  p = oneFunction();
  p.render.shading.ao.directions = 40;
  EXPECT_EQ(test_support::modelErrorText([&] { validateProject(p); }),
            "render.shading.ao.directions: expected between 1 and 32 occlusion directions, found 40");
  p = oneFunction();
  p.render.shading.lights[0].color = Vec3(0.5, 1.5, 0.5);
  EXPECT_EQ(test_support::modelErrorText([&] { validateProject(p); }),
            "render.shading.lights[0].color[1]: expected a colour component between 0 and 1, found 1.5");
  p = oneFunction();
  p.render.flame.gamma = 0.0;
  EXPECT_EQ(test_support::modelErrorText([&] { validateProject(p); }),
            "render.flame.gamma: expected a number between 0.05 and 100, found 0");
}

// The animation and volume blocks had readers of their own before the tables; their files are told
// what they were always told.
TEST(SettingsTable, AnimationAndVolumeKeepTheirWords) {
  EXPECT_EQ(readingMessage("animation", "[]"), "animation: expected an object with fps, start, end and loop");
  EXPECT_EQ(readingMessage("animation", R"({"fps": "x"})"), "animation.fps: expected a number");
  EXPECT_EQ(readingMessage("animation", R"({"loop": 1})"), "animation.loop: expected true or false");
  EXPECT_EQ(readingMessage("animation", R"({"fps": 0})"), "animation.fps: frames per second must be in (0, 1000]");
  EXPECT_EQ(readingMessage("animation", R"({"fps": 1000})"), "");
  EXPECT_EQ(readingMessage("animation", R"({"start": 5, "end": 1})"),
            "animation.end: the animation must not end before it starts");
  EXPECT_EQ(readingMessage("animation", R"({"shutter": 1.5})"),
            "animation.shutter: the shutter must be a fraction of the frame interval between 0 and 1");
  EXPECT_EQ(readingMessage("animation", R"({"start": 2e6, "end": 1e300})"), "");  // any finite time
  // Read in table order (the shutter before the loop); written with the shutter, only written
  // when changed, last.
  EXPECT_EQ(readingMessage("animation", R"({"loop": 1, "shutter": "x"})"), "animation.shutter: expected a number");
  AnimationSettings blurred;
  blurred.shutter = 0.25;
  EXPECT_EQ(writeSettings(animationSettingsTable(), blurred).dump(),
            R"({"fps":24.0,"start":0.0,"end":4.0,"loop":true,"shutter":0.25})");
  EXPECT_EQ(readingMessage("volume", "[]"), "volume: expected an object");
  EXPECT_EQ(readingMessage("volume", R"({"seed": "x"})"),
            "volume.seed: expected an integer between 0 and 9223372036854775807");
  EXPECT_EQ(readingMessage("volume", R"({"resolution": 16.5})"),
            "volume.resolution: expected an integer between 16 and 512");
  EXPECT_EQ(readingMessage("volume", R"({"samples": true})"),
            "volume.samples: expected an integer between 1 and 100000000000");
  EXPECT_EQ(readingMessage("volume", R"({"iterations": 300, "skip": 300})"),
            "volume.skip: expected fewer skipped iterations than iterations");

  // In memory, validation keeps its words too.
  Project p = oneFunction();
  p.volume = VolumeSettings{};
  p.volume->samples = 0;
  EXPECT_EQ(test_support::modelErrorText([&] { validateProject(p); }),
            "volume.samples: expected between 1 and 1e11 samples");
  p.volume = VolumeSettings{};
  p.volume->skip = -1;
  EXPECT_EQ(test_support::modelErrorText([&] { validateProject(p); }),
            "volume.skip: expected fewer skipped iterations than iterations");
  AnimationSettings a;
  a.start = std::nan("");
  EXPECT_EQ(test_support::modelErrorText([&] { validateSettings(animationSettingsTable(), a, "animation"); }),
            "animation.start: the start time must be a finite number");

  // A seed spelled as a float of 2^63 reads as that seed.
  nlohmann::json root = nlohmann::json::parse(serializeProject(oneFunction()));
  root["volume"] = nlohmann::json::parse(R"({"seed": 9223372036854775808.0})");
  EXPECT_EQ(parseProject(root.dump()).volume->seed, std::uint64_t(1) << 63);
}

TEST(SettingsTable, ReadingStartsFromTheGivenDefaultsAndRoundTrips) {
  FlameSettings f;
  f.gamma = 2.5;
  f.supersample = 3;
  f.palette = "flam3:27";
  const nlohmann::ordered_json written = writeSettings(flameSettingsTable(), f);
  EXPECT_FALSE(written.contains("density_unit"));
  const FlameSettings back = readSettings(flameSettingsTable(), nlohmann::json::parse(written.dump()), "render.flame");
  EXPECT_EQ(back, f);
  const FlameSettings partial =
      readSettings(flameSettingsTable(), nlohmann::json::parse(R"({"vibrancy": 0.25})"), "render.flame", f);
  EXPECT_EQ(partial.gamma, 2.5);
  EXPECT_EQ(partial.vibrancy, 0.25);
}
