// Set functions in the modeller: a median function added from the Functions panel, its set made a
// box and sized in the set editor, saved (the file holds the box), undone back to the original
// file byte for byte; a mesh path that cannot be read shows the voxelizer's sentence in the set
// editor, and the modeller goes on; the key buttons beside a set's numbers key them.
#include "gui_harness.h"

using namespace gridifs::gui_test;

namespace {

/// Opens the Add set popup and picks `kind` ("median" or "condensation").
void addSetFunction(App& app, const std::string& kind) {
  const std::optional<Rect> add = app.waitForStableRect("functions.add_set");
  ASSERT_TRUE(add) << "the Functions panel has no button for set functions";
  clickRect(*add);
  const std::optional<Rect> item = app.waitForStableRect("functions.add_set." + kind);
  ASSERT_TRUE(item) << "the set function menu did not open";
  clickRect(*item);
}

/// Waits for the preview, adds a `kind` set function and waits for its undo step ("Add `kind`
/// function"); returns the last probe.
nlohmann::json addSetFunctionAndWait(App& app, const std::string& kind) {
  app.waitForPreview();
  addSetFunction(app, kind);
  const std::string undo = "Add " + kind + " function";
  return app.waitFor([&](const nlohmann::json& j) { return j["undo"] == undo; });
}

/// Picks `shape` in the set editor's Set combo.
void chooseShape(App& app, const std::string& shape) {
  const std::optional<Rect> combo = app.waitForStableRect("set.shape");
  ASSERT_TRUE(combo) << "no set editor for the active function";
  clickRect(*combo);
  const std::optional<Rect> item = app.waitForStableRect("set.shape." + shape);
  ASSERT_TRUE(item) << "the Set combo did not open";
  clickRect(*item);
}

/// Types `text` into a field (Ctrl+click turns a drag field into a text field) and presses Enter;
/// retried while the edit named `undo` has not arrived (a key can fall between frames).
void typeInto(App& app, int x, int y, bool ctrlClick, const std::string& text, const std::string& undo) {
  for (int attempt = 0; attempt < 3; ++attempt) {
    focusWindow();
    if (ctrlClick)
      xdotool("mousemove " + std::to_string(x) + " " + std::to_string(y) +
              " sleep 0.1 keydown ctrl sleep 0.1 click 1 sleep 0.1 keyup ctrl");
    else
      clickAt(x, y);
    std::this_thread::sleep_for(300ms);
    xdotool("keydown ctrl+a sleep 0.15 keyup ctrl+a");
    std::this_thread::sleep_for(200ms);
    xdotool("type --delay 15 '" + text + "'");
    std::this_thread::sleep_for(200ms);
    xdotool("keydown Return sleep 0.15 keyup Return");
    const nlohmann::json probe = app.waitFor([&](const nlohmann::json& j) { return j["undo"] == undo; }, 5s);
    if (probe["undo"] == undo) return;
  }
  FAIL() << "the typed value did not arrive as \"" << undo << "\"";
}

}  // namespace

TEST(CondensationSetGui, AddAMedianFunctionMakeItABoxSaveAndUndoBackToTheOriginalFile) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs");
  const std::string original = fileText(project);
  const std::size_t before = gridifs::loadProject(project).functions.size();
  App app(home, {project.string()});
  nlohmann::json probe = addSetFunctionAndWait(app, "median");
  ASSERT_EQ(probe["undo"], "Add median function");
  EXPECT_EQ(probe["active_function"], int(before));
  EXPECT_EQ(probe["set_message"], "") << "the default set is not usable";

  chooseShape(app, "box");
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Set shape: box"; });
  ASSERT_EQ(probe["undo"], "Set shape: box");

  // The box's x edge length, typed into the first of the Size fields.
  const std::optional<Rect> size = app.waitForStableRect("set.size");
  ASSERT_TRUE(size) << "no Size fields for a box";
  typeInto(app, size->x + size->w / 6, size->y + size->h / 2, true, "0.8", "Box size");
  keepShot(home, "condensation_set_box.png");

  pressKeys("ctrl+s");
  probe = app.waitFor([](const nlohmann::json& j) { return !j["dirty"].get<bool>(); });
  ASSERT_FALSE(probe["dirty"].get<bool>());
  const gridifs::Project saved = gridifs::loadProject(project);
  ASSERT_EQ(saved.functions.size(), before + 1);
  const gridifs::Function& median = saved.functions.back();
  EXPECT_EQ(median.kind, gridifs::FunctionKind::Median);
  EXPECT_EQ(median.set.shape, gridifs::SetShape::Box);
  EXPECT_NEAR(median.set.size.x, 0.8, 1e-9);
  EXPECT_NEAR(median.set.size.y, 0.6, 1e-9) << "a new set's box is as wide as its ball";
  EXPECT_EQ(median.set.center, gridifs::Vec3(0.0));
  const std::string text = fileText(project);
  EXPECT_NE(text.find("\"median\""), std::string::npos);
  EXPECT_NE(text.find("\"box\""), std::string::npos);

  // Three undo steps (size, shape, add) and the file is the original, byte for byte.
  for (const char* expected : {"Set shape: box", "Add median function", ""}) {
    pressKeys("ctrl+z");
    probe = app.waitFor([&](const nlohmann::json& j) { return j["undo"] == expected; });
    EXPECT_EQ(probe["undo"], expected);
  }
  pressKeys("ctrl+s");
  probe = app.waitFor([](const nlohmann::json& j) { return !j["dirty"].get<bool>(); });
  EXPECT_EQ(fileText(project), original);
  pressKeys("ctrl+q");
  EXPECT_EQ(app.waitExit(), 0);
}

TEST(CondensationSetGui, AMeshThatCannotBeReadIsToldInTheSetEditor) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs");
  {
    // A small closed mesh beside the project: a cube of edge 0.5.
    std::ofstream cube(home.path / "cube.obj");
    for (int k = 0; k < 8; ++k)
      cube << "v " << (k & 1 ? 0.25 : -0.25) << ' ' << (k & 2 ? 0.25 : -0.25) << ' ' << (k & 4 ? 0.25 : -0.25) << "\n";
    cube << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  }
  App app(home, {project.string()});
  nlohmann::json probe = addSetFunctionAndWait(app, "condensation");
  ASSERT_EQ(probe["undo"], "Add condensation function");

  // A mesh set starts with its file: the browser opens, and the mesh chosen there is the set.
  chooseShape(app, "mesh");
  const std::optional<Rect> name = app.waitForStableRect("browser.fileName");
  ASSERT_TRUE(name) << "choosing a mesh set opened no file browser";
  typeInto(app, name->x + name->w / 2, name->y + name->h / 2, false, "cube.obj", "Set shape: mesh");
  probe = app.waitFor([](const nlohmann::json& j) { return j["rects"].contains("set.path"); });
  EXPECT_EQ(probe["set_message"], "") << "the cube beside the project cannot be used";
  EXPECT_EQ(gridifs::loadProject(project).functions.size() + 1, probe["functions"].get<std::size_t>());

  // A file that is not there: the voxelizer's sentence, naming it, in the set editor.
  const std::optional<Rect> field = app.waitForStableRect("set.path");
  ASSERT_TRUE(field) << "no File field for a mesh set";
  typeInto(app, field->x + field->w / 2, field->y + field->h / 2, false, "no_such_mesh.obj", "Set mesh file");
  probe = app.waitFor([](const nlohmann::json& j) {
    return j["set_message"].get<std::string>().find("no_such_mesh.obj") != std::string::npos;
  });
  const std::string message = probe["set_message"];
  EXPECT_NE(message.find("no_such_mesh.obj"), std::string::npos) << message;
  ASSERT_TRUE(app.waitForStableRect("set.message")) << "the message is not shown in the set editor";
  keepShot(home, "condensation_set_bad_mesh.png");

  // The modeller goes on: undo brings back the cube, and the message goes.
  pressKeys("ctrl+z");
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Set shape: mesh" && j["set_message"] == ""; });
  EXPECT_EQ(probe["undo"], "Set shape: mesh");
  EXPECT_EQ(probe["set_message"], "");
  EXPECT_EQ(::waitpid(app.pid(), nullptr, WNOHANG), 0) << "the modeller stopped";
}

TEST(CondensationSetGui, KeyButtonsBesideTheSetsNumbersKeyThemAndUndoRemovesTheKey) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs");
  const std::size_t before = gridifs::loadProject(project).functions.size();
  App app(home, {project.string()});
  nlohmann::json probe = addSetFunctionAndWait(app, "median");
  ASSERT_EQ(probe["undo"], "Add median function");

  // The new median's sphere radius and its rotation each have a key button.
  const std::string fn = "functions[" + std::to_string(before) + "]";
  auto keys = [](const nlohmann::json& j, const std::string& path) -> std::size_t {
    const auto& tracks = j["timeline"]["tracks"];
    return tracks.contains(path) ? tracks[path].size() : 0;
  };
  ASSERT_TRUE(app.waitForStableRect("key." + fn + ".rotate")) << "no key button beside the median's rotation";
  const std::optional<Rect> radius = app.waitForStableRect("key." + fn + ".set.radius");
  ASSERT_TRUE(radius) << "no key button beside the sphere's radius";
  clickRect(*radius);
  probe = app.waitFor([&](const nlohmann::json& j) { return keys(j, fn + ".set.radius") == 1; });
  ASSERT_EQ(keys(probe, fn + ".set.radius"), 1u) << probe["timeline"]["tracks"].dump();
  EXPECT_EQ(probe["undo"], "Set key");

  pressKeys("ctrl+z");
  probe = app.waitFor([&](const nlohmann::json& j) { return keys(j, fn + ".set.radius") == 0; });
  EXPECT_EQ(keys(probe, fn + ".set.radius"), 0u);
  EXPECT_EQ(probe["undo"], "Add median function");
  EXPECT_EQ(::waitpid(app.pid(), nullptr, WNOHANG), 0) << "the modeller stopped";
}
