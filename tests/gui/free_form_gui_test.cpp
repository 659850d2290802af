// A free-form IFS in the modeller: its control points are dragged in the grid views like nodes
// (one undo step, the preview follows), and File › Combine… joins a second project into it.
#include <glm/geometric.hpp>

#include "gui_harness.h"

using namespace gridifs::gui_test;

TEST(FreeFormGui, DraggingAControlPointIsOneUndoStepAndIsSaved) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "fractal_bezier_curve.gridifs");
  const gridifs::Project original = gridifs::loadProject(project);
  ASSERT_TRUE(original.space);
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();
  const std::optional<Rect> point = app.waitForStableRect("control_point.Top.1");
  ASSERT_TRUE(point) << "the Top view shows no control point 1";
  const int x = point->x + point->w / 2, y = point->y + point->h / 2;
  const std::uint64_t restarts = app.probe()["preview"]["restarts"];
  dragFrom(x, y, x + 40, y - 30);
  probe = app.waitForPreview(restarts);  // the preview restarted on the moved point
  EXPECT_EQ(probe["undo"], "Move control point");
  keepShot(home, "control_point_drag.png");

  pressKeys("ctrl+s");
  app.waitFor([](const nlohmann::json& j) { return !j["dirty"].get<bool>(); });
  gridifs::Project saved = gridifs::loadProject(project);
  ASSERT_TRUE(saved.space);
  const gridifs::Vec3 before = original.space->control_points[1], after = saved.space->control_points[1];
  EXPECT_GT(glm::length(after - before), 0.05) << "the saved file has the point where it was";
  EXPECT_NEAR(after.z, before.z, 1e-9) << "a drag in the Top view stays in its plane";
  for (std::size_t j : {0u, 2u, 3u}) EXPECT_EQ(saved.space->control_points[j], original.space->control_points[j]);

  // One undo step: Ctrl+Z puts the point back and leaves nothing more to undo.
  pressKeys("ctrl+z");
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "" && j["dirty"].get<bool>(); });
  EXPECT_EQ(probe["undo"], "");
  pressKeys("ctrl+s");
  app.waitFor([](const nlohmann::json& j) { return !j["dirty"].get<bool>(); });
  saved = gridifs::loadProject(project);
  ASSERT_TRUE(saved.space);
  EXPECT_EQ(saved.space->control_points, original.space->control_points);
  pressKeys("ctrl+q");
  EXPECT_EQ(app.waitExit(), 0);
}

TEST(FreeFormGui, CombineDialogExplainsWhatItCannotDoAndCombinesAsOneUndoStep) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "fractal_bezier_curve.gridifs");
  gridifs::saveProject(gridifs::loadProject(project), home.path / "second.gridifs");
  exampleCopy(home, "sierpinski_tetrahedron.gridifs");  // a grid IFS: no operation joins it to a curve
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();
  const int wx = probe["window"]["x"], wy = probe["window"]["y"];
  clickAt(wx + 18, wy + 9);  // File
  const std::optional<Rect> menuItem = app.waitForStableRect("menu.combine");
  ASSERT_TRUE(menuItem) << "the File menu did not open";
  clickRect(*menuItem);
  const std::optional<Rect> field = app.waitForStableRect("combine.path");
  ASSERT_TRUE(field) << "the Combine dialog did not open";

  // The second project's path is typed (relative: from the open project's folder). On a busy
  // machine a click or the first keys can fall between frames: the text is checked and retyped.
  auto typePath = [&](const std::string& text) {
    for (int attempt = 0; attempt < 3; ++attempt) {
      // The dialog grows and shrinks with its messages and stays centred: find the field again.
      const std::optional<Rect> at = app.waitForStableRect("combine.path");
      ASSERT_TRUE(at);
      clickRect(*at);
      focusWindow();
      xdotool("keydown ctrl+a sleep 0.15 keyup ctrl+a");
      std::this_thread::sleep_for(200ms);
      xdotool("type --delay 15 '" + text + "'");
      probe = app.waitFor([&](const nlohmann::json& j) { return j["combine"]["path"] == text; }, 5s);
      if (probe["combine"]["path"] == text) break;
    }
    ASSERT_EQ(probe["combine"]["path"], text) << "the typed path did not arrive";
  };

  typePath("missing.gridifs");
  probe = app.waitFor([](const nlohmann::json& j) { return !j["combine"]["load_error"].get<std::string>().empty(); });
  EXPECT_NE(probe["combine"]["load_error"].get<std::string>().find("There is no file"), std::string::npos)
      << probe["combine"]["load_error"];
  clickRect(*app.waitForStableRect("combine.run"));  // disabled: nothing happens
  probe = app.probe();
  EXPECT_EQ(probe["undo"], "");
  EXPECT_TRUE(probe["combine"]["open"].get<bool>());

  // A grid IFS: every operation is greyed out, each with its reason.
  typePath("sierpinski_tetrahedron.gridifs");
  probe = app.waitFor([](const nlohmann::json& j) { return j["combine"]["loaded"].get<bool>(); });
  for (const char* op : {"union", "concat", "product", "shuffle"})
    EXPECT_NE(probe["combine"]["reasons"][op].get<std::string>().find("same kind"), std::string::npos) << op;

  // A second curve on the same control points: every operation is possible (concatenation too, as
  // both act on the same barycentric space).
  typePath("second.gridifs");
  probe = app.waitFor([](const nlohmann::json& j) {
    return j["combine"]["loaded"].get<bool>() && j["combine"]["reasons"]["union"] == "";
  });
  EXPECT_EQ(probe["combine"]["reasons"]["product"], "");
  EXPECT_EQ(probe["combine"]["reasons"]["shuffle"], "");
  EXPECT_EQ(probe["combine"]["reasons"]["concat"], "");
  clickRect(*app.waitForStableRect("combine.op.product"));
  probe = app.waitFor([](const nlohmann::json& j) { return j["combine"]["op"] == "product"; });
  ASSERT_EQ(probe["combine"]["op"], "product");
  keepShot(home, "combine_dialog.png");
  const std::uint64_t restarts = probe["preview"]["restarts"];
  clickRect(*app.waitForStableRect("combine.run"));
  probe = app.waitForPreview(restarts);
  EXPECT_EQ(probe["undo"], "Combine (product)");
  EXPECT_EQ(probe["functions"].get<std::size_t>(), 4u);  // every pair of the two curves' halves
  EXPECT_FALSE(probe["combine"]["open"].get<bool>());
  keepShot(home, "combined.png");

  // One undo step back to the open project.
  pressKeys("ctrl+z");
  probe = app.waitFor([](const nlohmann::json& j) { return j["functions"].get<std::size_t>() == 2; });
  EXPECT_EQ(probe["functions"].get<std::size_t>(), 2u);
  EXPECT_EQ(probe["undo"], "");
  EXPECT_FALSE(probe["dirty"].get<bool>());
  pressKeys("ctrl+q");
  EXPECT_EQ(app.waitExit(), 0);
}
