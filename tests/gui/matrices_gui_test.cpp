// The Matrices window (key M): a transition preset and a free-form preset, each one undo step,
// saved and read back; the preview renders the free-form IFS.
#include "gui_harness.h"

using namespace gridifs::gui_test;

namespace {

/// Waits for the preview, then opens the Matrices window (key M).
void openMatricesWindow(const App& app) {
  app.waitForPreview();
  pressKeys("m");
}

}  // namespace

TEST(MatricesGui, TransitionAndFreeFormPresetsAreUndoableEdits) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs");
  App app(home, {project.string()});
  openMatricesWindow(app);
  const std::optional<Rect> noRepeats = app.waitForStableRect("matrices.transitions.No repeats");
  ASSERT_TRUE(noRepeats) << "the Matrices window did not open";
  clickRect(*noRepeats);
  nlohmann::json probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Transitions: No repeats"; });
  EXPECT_EQ(probe["undo"], "Transitions: No repeats");
  pressKeys("ctrl+s");
  app.waitFor([](const nlohmann::json& j) { return !j["dirty"].get<bool>(); });
  gridifs::Project saved = gridifs::loadProject(project);
  ASSERT_EQ(saved.transitions.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(saved.transitions[i][i], 0.0);

  // The default preset (a cubic Bézier curve) replaces the functions; the preview renders it.
  const std::optional<Rect> apply = app.waitForStableRect("matrices.apply_preset");
  ASSERT_TRUE(apply);
  const std::uint64_t restarts = app.probe()["preview"]["restarts"];
  clickRect(*apply);
  probe = app.waitForPreview(restarts);
  EXPECT_EQ(probe["undo"], "Preset: Cubic Bezier curve");
  EXPECT_EQ(probe["functions"].get<std::size_t>(), 2u);
  EXPECT_TRUE(probe["preview"]["done"].get<bool>());
  run("import -window root '" + (home.path / "matrices.png").string() + "'");
  if (const char* keep = std::getenv("GRIDIFS_GUI_SHOTS"))  // for a person to look at
    fs::copy_file(home.path / "matrices.png", fs::path(keep) / "matrices.png", fs::copy_options::overwrite_existing);
  pressKeys("ctrl+s");
  app.waitFor([](const nlohmann::json& j) { return !j["dirty"].get<bool>(); });
  saved = gridifs::loadProject(project);
  ASSERT_TRUE(saved.space);
  EXPECT_EQ(saved.space->control_points.size(), 4u);
  EXPECT_EQ(saved.functions[0].kind, gridifs::FunctionKind::Matrix);

  // Undo goes back to the grid IFS with its transitions.
  pressKeys("ctrl+z");
  probe = app.waitFor([](const nlohmann::json& j) { return j["functions"].get<std::size_t>() == 4; });
  EXPECT_EQ(probe["undo"], "Transitions: No repeats");
  pressKeys("ctrl+q");  // unsaved (undone) edits: answer "Don't save"
  const std::optional<Rect> discard = app.waitForStableRect("unsaved.discard");
  ASSERT_TRUE(discard);
  clickRect(*discard);
  EXPECT_EQ(app.waitExit(), 0);
}

TEST(MatricesGui, MapsAGridIfsOntoAControlNetAndAddsAPoint) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs");
  App app(home, {project.string()});
  openMatricesWindow(app);
  const std::optional<Rect> map = app.waitForStableRect("matrices.map_onto_net");
  ASSERT_TRUE(map) << "the Matrices window has no control-net button for a grid project";
  std::uint64_t restarts = app.probe()["preview"]["restarts"];
  clickRect(*map);
  nlohmann::json probe = app.waitForPreview(restarts);
  EXPECT_EQ(probe["undo"], "Map onto a control net");
  EXPECT_EQ(probe["functions"].get<std::size_t>(), 4u);
  const std::optional<Rect> add = app.waitForStableRect("matrices.add_point");
  ASSERT_TRUE(add);
  clickRect(*add);
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Add control point"; });
  EXPECT_EQ(probe["undo"], "Add control point");
  run("import -window root '" + (home.path / "control_net.png").string() + "'");
  if (const char* keep = std::getenv("GRIDIFS_GUI_SHOTS"))  // for a person to look at
    fs::copy_file(home.path / "control_net.png", fs::path(keep) / "control_net.png",
                  fs::copy_options::overwrite_existing);
  pressKeys("ctrl+s");
  app.waitFor([](const nlohmann::json& j) { return !j["dirty"].get<bool>(); });
  const gridifs::Project saved = gridifs::loadProject(project);
  ASSERT_TRUE(saved.space);
  EXPECT_EQ(saved.space->control_points.size(), 11u);  // a quadratic tetrahedron's 10, and one
  EXPECT_EQ(saved.functions[0].matrix.size(), 11u);
  // One undo step each: back to the net, then to the grid IFS.
  pressKeys("ctrl+z");
  app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Map onto a control net"; });
  pressKeys("ctrl+z");
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] != "Map onto a control net"; });
  pressKeys("ctrl+q");
  const std::optional<Rect> discard = app.waitForStableRect("unsaved.discard");
  ASSERT_TRUE(discard);
  clickRect(*discard);
  EXPECT_EQ(app.waitExit(), 0);
}
