// GUI tier for the flame controls: the Tone popup's new controls and density plot, the palette
// editor (one undo step per gesture, saved beside the project), and the motion blur fields of
// File › Render animation…. The harness is gui/gui_harness.h.
#include "gui/gui_harness.h"

using namespace gridifs::gui_test;

namespace {

/// Starts the modeller on a copy of an example and switches the preview to the flame display.
nlohmann::json openFlame(App& app) {
  nlohmann::json probe = app.waitForPreview();
  clickRect(rectOf(probe, "preview.mode.flame"));
  return app.waitFor([](const nlohmann::json& j) {
    return j["preview_modes"]["mode"] == "flame" && j["preview_modes"]["flame_developed"].get<int>() >= 1;
  });
}

}  // namespace

TEST(FlameControlsGui, TonePopupShowsTheNewControlsAndTheDensityPlot) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs", 1'000'000);
  App app(home, {project.string()});
  nlohmann::json probe = openFlame(app);
  clickRect(rectOf(probe, "flame.tone"));
  for (const char* item : {"flame.Hue", "flame.density_display", "flame.density_plot", "flame.Supersample",
                           "flame.Filter radius", "flame.quality"})
    EXPECT_TRUE(app.waitForStableRect(item)) << item << " is not in the tone popup";
  const std::optional<Rect> plot = app.waitForStableRect("flame.density_plot");
  ASSERT_TRUE(plot);
  std::this_thread::sleep_for(600ms);  // a develop with the popup open fills the plot
  const auto px = grabScreen(home, *plot);
  EXPECT_GT(litFraction(px), 0.02) << "the density plot is empty";
  if (const char* shot = std::getenv("GRIDIFS_GUI_SCREENSHOT"))  // for a person to look at
    run(std::string("import -window root '") + shot + "'");
  // A hue drag is one undo step.
  const std::optional<Rect> hue = app.waitForStableRect("flame.Hue");
  ASSERT_TRUE(hue);
  const int y = hue->y + hue->h / 2;
  dragFrom(hue->x + hue->w / 10, y, hue->x + hue->w / 2, y, 8);
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Hue"; });
  EXPECT_EQ(probe["undo"], "Hue");
}

TEST(FlameControlsGui, PaletteEditorEditsAreUndoableAndSaveBesideTheProject) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs", 200'000);
  App app(home, {project.string()});
  nlohmann::json probe = openFlame(app);
  clickRect(rectOf(probe, "flame.gradient"));
  std::optional<Rect> start = app.waitForStableRect("palette_editor.from_current");
  ASSERT_TRUE(start) << "the palette editor did not open";
  clickRect(*start);
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Gradient from current palette"; });
  ASSERT_EQ(probe["undo"], "Gradient from current palette");
  std::optional<Rect> add = app.waitForStableRect("palette_editor.add");
  ASSERT_TRUE(add);
  clickRect(*add);
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Add palette key"; });
  EXPECT_EQ(probe["undo"], "Add palette key");
  std::optional<Rect> del = app.waitForStableRect("palette_editor.delete");
  ASSERT_TRUE(del);
  clickRect(*del);
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Delete palette key"; });
  EXPECT_EQ(probe["undo"], "Delete palette key");
  if (const char* shot = std::getenv("GRIDIFS_GUI_SCREENSHOT_EDITOR")) {
    std::this_thread::sleep_for(1500ms);  // the restarted preview develops with the new palette
    run(std::string("import -window root '") + shot + "'");
  }
  std::optional<Rect> save = app.waitForStableRect("palette_editor.save");
  ASSERT_TRUE(save);
  clickRect(*save);
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Save palette gradient"; });
  EXPECT_EQ(probe["undo"], "Save palette gradient");
  EXPECT_TRUE(fs::exists(project.parent_path() / "gradient.palette.json"));
}

TEST(FlameControlsGui, RenderAnimationOffersMotionBlurAndFade) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs", 200'000);
  App app(home, {project.string()});
  openRenderAnimation(app);
  EXPECT_TRUE(app.waitForStableRect("animation.motion_blur")) << "no motion blur field";
  EXPECT_TRUE(app.waitForStableRect("animation.motion_fade")) << "no motion fade slider";
}
