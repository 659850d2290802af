// GUI tier: File › Render animation and File › Export points render a project whose condensation
// set is read from a mesh file beside it, and a project with median functions, and write the
// files `gridifs render` and `gridifs export-points` write, byte for byte (the four prepare their
// render in one place, core/job/prepared_render.h, and write frames in one,
// core/job/frame_output.h).
#include "gui/gui_harness.h"
#include "schema/project_time.h"

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

/// Waits for the preview's first image, or, for a project with median functions (which opens in
/// the volume preview, whose chaos-game preview never starts), for the window only.
nlohmann::json waitUntilOpen(App& app, bool chaosPreview) {
  if (chaosPreview) return app.waitForPreview();
  return app.waitFor([](const nlohmann::json& j) { return j.contains("window") && !j["modal"].get<bool>(); });
}

/// Waits until the dialog task `dialog` ("render_animation" or "export") is done or failed.
nlohmann::json waitForTask(App& app, const std::string& dialog) {
  return app.waitFor(
      [&](const nlohmann::json& j) {
        const std::string phase = j[dialog]["phase"];
        return phase == "done" || phase == "failed";
      },
      120s);
}

std::string fileBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Runs `gridifs ARGS` quietly; its exit code.
int gridifsCommand(const std::string& args) {
  return run(std::string("'") + GRIDIFS_EXE + "' " + args + " -q 2>/dev/null");
}

/// Exports the points of the project the modeller has open through File › Export points with the
/// dialog's defaults; the file it wrote (`chaosPreview` as in waitUntilOpen).
fs::path exportPointsFromDialog(App& app, const fs::path& out, bool chaosPreview = true) {
  nlohmann::json probe = waitUntilOpen(app, chaosPreview);
  clickFileMenu(app, probe, "menu.export_points");
  const std::optional<Rect> exportButton = app.waitForStableRect("export.run");
  EXPECT_TRUE(exportButton) << "the export dialog did not open";
  if (!exportButton) return {};
  // The suggested output lies beside the project.
  probe = app.probe();
  EXPECT_EQ(probe["export"]["output"], out.string());
  clickRect(*exportButton);
  probe = waitForTask(app, "export");
  EXPECT_EQ(probe["export"]["phase"], "done") << probe["export"]["message"];
  return out;
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
  probe = waitForTask(app, "render_animation");
  ASSERT_EQ(probe["render_animation"]["phase"], "done") << probe["render_animation"].dump();
  EXPECT_EQ(probe["render_animation"]["frames_done"].get<int>(), 3);
  for (int f = 0; f <= 2; ++f) {
    char name[64];
    std::snprintf(name, sizeof name, "pine_trees_%04d.png", f);
    const fs::path file = home.path / "pine_trees_frames" / name;
    ASSERT_TRUE(fs::exists(file)) << file;
    EXPECT_GT(fs::file_size(file), 0u) << file;
    std::vector<float> px;
    ASSERT_NO_FATAL_FAILURE(readLitFrame(file, 96, 72, px));
  }
  // The command line's frame 1 is the dialog's, byte for byte.
  const fs::path project = home.path / "pine_trees.gridifs";
  ASSERT_EQ(gridifsCommand("render '" + project.string() + "' -o '" + (home.path / "cli_%04d.png").string() +
                           "' --frames 1:1"),
            0);
  EXPECT_TRUE(fileBytes(home.path / "cli_0001.png") ==
              fileBytes(home.path / "pine_trees_frames" / "pine_trees_0001.png"))
      << "File › Render animation wrote another frame 1 than gridifs render --frames 1:1";
}

TEST(RenderJobGui, ExportPointsSamplesACondensationSetFromAMeshFile) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = pineTreesCopy(home);
  App app(home, {project.string()});
  const fs::path out = exportPointsFromDialog(app, home.path / "pine_trees-points.ply");
  ASSERT_TRUE(fs::exists(out));
  EXPECT_GT(fs::file_size(out), 1000u);
  ASSERT_EQ(gridifsCommand("export-points '" + project.string() + "' -o '" + (home.path / "cli.ply").string() +
                           "' --samples 1000000"),
            0);
  EXPECT_TRUE(fileBytes(out) == fileBytes(home.path / "cli.ply"))
      << "File › Export points wrote other points than gridifs export-points";
}

// Median functions map sets, not points (Sokolov & Gentil, §3.2): the dialog exports the points
// of the project's density volume, as the command line does, instead of refusing the project.
TEST(RenderJobGui, ExportPointsOfAMedianProjectAreTheCommandLines) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  gridifs::Project p = gridifs::loadProject(fs::path(GRIDIFS_ASSETS) / "volumes" / "two_sets.gridifs");
  gridifs::VolumeSettings volume = p.volume.value_or(gridifs::VolumeSettings{});
  volume.resolution = 48;  // a small density volume: this test is about the path, not the volume
  volume.iterations = 200;
  p.volume = volume;
  const fs::path project = home.path / "median.gridifs";
  gridifs::saveProject(p, project);
  App app(home, {project.string()});
  const fs::path out = exportPointsFromDialog(app, home.path / "median-points.ply", false);
  ASSERT_TRUE(fs::exists(out));
  ASSERT_EQ(gridifsCommand("export-points '" + project.string() + "' -o '" + (home.path / "cli.ply").string() +
                           "' --samples 1000000"),
            0);
  EXPECT_GT(fs::file_size(out), 1000u);
  EXPECT_TRUE(fileBytes(out) == fileBytes(home.path / "cli.ply"))
      << "File › Export points wrote other points than gridifs export-points";
}

namespace {

/// Renders frames 0 and 1 of `project` through File › Render animation… as EXR (the output pattern
/// typed into the dialog) and checks each against `gridifs render --frames 0:1`, byte for byte.
void renderExrFramesLikeTheCommandLine(const TempFolder& home, const fs::path& project, bool chaosPreview) {
  App app(home, {project.string()});
  nlohmann::json probe = waitUntilOpen(app, chaosPreview);
  clickFileMenu(app, probe, "menu.render_animation");
  const std::optional<Rect> output = app.waitForStableRect("animation.output");
  ASSERT_TRUE(output) << "the dialog did not open";
  const std::string pattern = (home.path / "dialog_%04d.exr").string();
  for (int attempt = 0; attempt < 3 && app.probe()["render_animation"]["output"] != pattern; ++attempt) {
    focusWindow();
    clickRect(*output);
    std::this_thread::sleep_for(300ms);
    xdotool("keydown ctrl+a sleep 0.15 keyup ctrl+a");
    std::this_thread::sleep_for(200ms);
    xdotool("type --delay 15 '" + pattern + "'");
    app.waitFor([&](const nlohmann::json& j) { return j["render_animation"]["output"] == pattern; }, 5s);
  }
  ASSERT_EQ(app.probe()["render_animation"]["output"], pattern);
  const std::optional<Rect> render = app.waitForStableRect("animation.render");
  ASSERT_TRUE(render);
  clickRect(*render);
  probe = waitForTask(app, "render_animation");
  ASSERT_EQ(probe["render_animation"]["phase"], "done") << probe["render_animation"].dump();
  ASSERT_EQ(gridifsCommand("render '" + project.string() + "' -o '" + (home.path / "cli_%04d.exr").string() +
                           "' --frames 0:1"),
            0);
  for (const char* frame : {"0000", "0001"}) {
    const fs::path dialog = home.path / ("dialog_" + std::string(frame) + ".exr");
    ASSERT_TRUE(fs::exists(dialog)) << dialog;
    EXPECT_TRUE(fileBytes(dialog) == fileBytes(home.path / ("cli_" + std::string(frame) + ".exr")))
        << "File › Render animation wrote another " << dialog.filename() << " than gridifs render";
  }
}

}  // namespace

// A project with median functions (Sokolov & Gentil, §3.2) to EXR: the points of its density
// volume, with alpha, depth and position, as the command line writes them.
TEST(RenderJobGui, RenderAnimationOfAMedianProjectToExrIsTheCommandLines) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  gridifs::Project p = gridifs::loadProject(fs::path(GRIDIFS_ASSETS) / "volumes" / "two_sets.gridifs");
  gridifs::VolumeSettings volume = p.volume.value_or(gridifs::VolumeSettings{});
  volume.resolution = 48;
  volume.iterations = 200;
  p.volume = volume;
  p.render.width = 96;
  p.render.height = 72;
  p.render.samples = 40'000;
  p.render.quality.reset();
  p.animation = gridifs::AnimationSettings{4.0, 0.0, 0.25, true};
  const fs::path project = home.path / "median.gridifs";
  gridifs::saveProject(p, project);
  renderExrFramesLikeTheCommandLine(home, project, false);
}

// An animated flame with motion blur (Draves & Reckase 2003, §9) whose camera turns: each time
// sample sees through its own camera, in the dialog as on the command line.
TEST(RenderJobGui, RenderAnimationOfAnAnimatedFlameToExrIsTheCommandLines) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  gridifs::Project p = gridifs::loadProject(fs::path(GRIDIFS_ASSETS) / "animation" / "breathing_twist.gridifs");
  p.render.mode = gridifs::DisplayMode::Flame;
  p.render.width = 96;
  p.render.height = 72;
  p.render.samples = 60'000;
  p.render.quality.reset();
  p.animation = gridifs::AnimationSettings{4.0, 0.0, 0.25, true};
  p.animation->motion_blur = 3;
  p.animation->motion_fade = 1.0;
  ASSERT_TRUE(p.tracks.count("camera.yaw")) << "the camera should turn";
  const fs::path project = home.path / "twist.gridifs";
  gridifs::saveProject(p, project);
  renderExrFramesLikeTheCommandLine(home, project, true);
}
