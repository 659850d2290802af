// GUI tier for the shaded display: the Shaded mode in the preview toolbar, the Shading panel
// (a slider drag is one undo step and re-develops without restarting the chaos game) and the key
// light's gizmo (Alt+drag on the preview). The harness is gui/gui_harness.h.
#include "gui/gui_harness.h"

using namespace gridifs::gui_test;

TEST(ShadedPreviewGui, ShadedModeLightsTheAttractorAndItsSlidersNeedNoRestart) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs", 1'000'000);
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();
  ASSERT_TRUE(probe["preview"]["done"].get<bool>());
  const Rect image = rectOf(probe, "preview.image");
  const auto zbuffer = grabScreen(home, image);

  clickRect(rectOf(probe, "preview.mode.shaded"));
  probe = app.waitFor(
      [](const nlohmann::json& j) {
        return j["preview_modes"]["mode"] == "shaded" && j["preview_modes"]["shaded_develops"].get<int>() >= 1 &&
               j["preview"]["done"].get<bool>() && j["rects"].contains("shading.Ambient");
      },
      90s);
  ASSERT_EQ(probe["preview_modes"]["mode"], "shaded");
  EXPECT_EQ(probe["undo"], "Shaded display");
  EXPECT_EQ(probe["preview_modes"]["shaded_error"], "");
  std::this_thread::sleep_for(500ms);
  probe = app.probe();
  const auto shaded = grabScreen(home, image);
  EXPECT_GT(litFraction(shaded), 0.02) << "the shaded picture looks empty";
  EXPECT_GT(meanAbsDifference(zbuffer, shaded), 2.0) << "the shaded picture is the z-buffer picture";
  const std::uint64_t restarts = probe["preview"]["restarts"];

  // Ambient: one drag, one undo step, a new develop of the same buffers.
  const std::optional<Rect> ambient = app.waitForStableRect("shading.Ambient");
  ASSERT_TRUE(ambient);
  const int develops = probe["preview_modes"]["shaded_develops"];
  const int y = ambient->y + ambient->h / 2;
  dragFrom(ambient->x + ambient->w / 5, y, ambient->x + ambient->w * 9 / 10, y, 8);
  probe = app.waitFor([&](const nlohmann::json& j) {
    return j["undo"] == "Ambient" && j["preview_modes"]["shaded_develops"].get<int>() > develops;
  });
  EXPECT_EQ(probe["undo"], "Ambient");
  EXPECT_EQ(probe["preview"]["restarts"].get<std::uint64_t>(), restarts)
      << "the ambient slider restarted the chaos game";
  std::this_thread::sleep_for(400ms);
  const auto brighter = grabScreen(home, image);
  EXPECT_GT(meanAbsDifference(shaded, brighter), 1.0) << "the ambient drag did not change the picture";

  // Alt+drag on the preview turns the key light (it casts shadows: its depth buffer is re-rendered,
  // the camera's buffers are kept).
  const int cx = image.x + image.w / 2, cy = image.y + image.h / 2;
  focusWindow();
  std::string cmd = "mousemove " + std::to_string(cx) + " " + std::to_string(cy) +
                    " sleep 0.15 keydown alt sleep 0.1 mousedown 1 sleep 0.15";
  for (int s = 1; s <= 8; ++s)
    cmd += " mousemove " + std::to_string(cx + 12 * s) + " " + std::to_string(cy) + " sleep 0.05";
  cmd += " sleep 0.2 mouseup 1 sleep 0.1 keyup alt";
  xdotool(cmd);
  probe = app.waitFor(
      [](const nlohmann::json& j) { return j["undo"] == "Move key light" && j["preview"]["done"].get<bool>(); });
  EXPECT_EQ(probe["undo"], "Move key light");
  EXPECT_GT(probe["preview"]["restarts"].get<std::uint64_t>(), restarts);
  EXPECT_TRUE(probe["preview"]["kept_camera"].get<bool>()) << "moving the light rendered the camera's buffers again";
  std::this_thread::sleep_for(400ms);
  EXPECT_GT(meanAbsDifference(brighter, grabScreen(home, image)), 0.5) << "moving the light changed nothing";
}
