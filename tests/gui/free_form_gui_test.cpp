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
  if (const char* keep = std::getenv("GRIDIFS_GUI_SHOTS")) {  // for a person to look at
    run("import -window root '" + (home.path / "control_point_drag.png").string() + "'");
    fs::copy_file(home.path / "control_point_drag.png", fs::path(keep) / "control_point_drag.png",
                  fs::copy_options::overwrite_existing);
  }

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

