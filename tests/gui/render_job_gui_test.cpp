// GUI tier: File › Render animation and File › Export points render a project whose condensation
// set is read from a mesh file beside it, as `gridifs render` and `gridifs export-points` do (the
// three prepare their render in one place: core/job/prepared_render.h).
#include "gui/gui_harness.h"
#include "model/project_time.h"

using namespace gridifs::gui_test;

namespace {

/// assets/volumes/pine_trees.gridifs (a condensation set read from pine_tree.obj) and its mesh,
/// small, animated over frames 0..2 with the camera turning.
fs::path pineTreesCopy(const TempFolder& home) {
  const fs::path assets = fs::path(GRIDIFS_ASSETS) / "volumes";
  gridifs::Project p = gridifs::loadProject(assets / "pine_trees.gridifs");
  p.render.width = 96;
  p.render.height = 72;
  p.render.samples = 40'000;
  p.animation = gridifs::AnimationSettings{4.0, 0.0, 0.5, true};
  p.tracks["camera.yaw"].keys = {{0.0, p.camera.yaw}, {0.5, p.camera.yaw + 20.0}};
  const fs::path file = home.path / "pine_trees.gridifs";
  gridifs::saveProject(p, file);
  fs::copy_file(assets / "pine_tree.obj", home.path / "pine_tree.obj");
  return file;
}

}  // namespace

TEST(RenderJobGui, RenderAnimationRendersACondensationSetFromAMeshFile) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  App app(home, {pineTreesCopy(home).string()});
  nlohmann::json probe = openRenderAnimation(app);
  const std::optional<Rect> render = app.waitForStableRect("animation.render");
  ASSERT_TRUE(render) << "the dialog did not open";
  clickRect(*render);
  probe = app.waitFor(
      [](const nlohmann::json& j) {
        const std::string phase = j["render_animation"]["phase"];
        return phase == "done" || phase == "failed";
      },
      120s);
  ASSERT_EQ(probe["render_animation"]["phase"], "done") << probe["render_animation"].dump();
  EXPECT_EQ(probe["render_animation"]["frames_done"].get<int>(), 3);
  for (int f = 0; f <= 2; ++f) {
    char name[64];
    std::snprintf(name, sizeof name, "pine_trees_%04d.png", f);
    const fs::path file = home.path / "pine_trees_frames" / name;
    ASSERT_TRUE(fs::exists(file)) << file;
    EXPECT_GT(fs::file_size(file), 0u) << file;
    OIIO::ImageBuf image(file.string());
    ASSERT_TRUE(image.init_spec(file.string(), 0, 0)) << image.geterror();
    EXPECT_EQ(image.spec().width, 96);
    EXPECT_EQ(image.spec().height, 72);
    std::vector<float> px(96 * 72 * 3);
    image.get_pixels(OIIO::ROI(0, 96, 0, 72, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, px.data());
    EXPECT_GT(litFraction(px), 0.01) << name << " is empty";
  }
}

TEST(RenderJobGui, ExportPointsSamplesACondensationSetFromAMeshFile) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  App app(home, {pineTreesCopy(home).string()});
  nlohmann::json probe = app.waitForPreview();
  clickFileMenu(app, probe, "menu.export_points");
  const std::optional<Rect> exportButton = app.waitForStableRect("export.run");
  ASSERT_TRUE(exportButton) << "the export dialog did not open";
  // The suggested output lies beside the project.
  const fs::path out = home.path / "pine_trees-points.ply";
  probe = app.probe();
  ASSERT_EQ(probe["export"]["output"], out.string());
  clickRect(*exportButton);
  probe = app.waitFor(
      [](const nlohmann::json& j) {
        const std::string phase = j["export"]["phase"];
        return phase == "done" || phase == "failed";
      },
      120s);
  ASSERT_EQ(probe["export"]["phase"], "done") << probe["export"]["message"];
  ASSERT_TRUE(fs::exists(out)) << probe["export"]["message"];
  EXPECT_GT(fs::file_size(out), 1000u);
}
