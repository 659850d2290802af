// GUI tier for the volume preview mode: the measure attractor of two median sets (Sokolov &
// Gentil, §3.4) ray-marched in the preview, switched on through the real toolbar with xdotool;
// the picture is checked where the sets project and far from them, an edit and its undo restart
// the computation, and a set that cannot be voxelized is told inline. The harness is
// gui/gui_harness.h.
#include "gui/gui_harness.h"
#include "render/camera.h"

using namespace gridifs::gui_test;

namespace {

/// A copy of an example from assets/volumes in the test's home (its mesh files stay behind).
fs::path volumeExample(const TempFolder& home, const std::string& name) {
  const gridifs::Project p = gridifs::loadProject(fs::path(GRIDIFS_ASSETS) / "volumes" / name);
  const fs::path file = home.path / name;
  gridifs::saveProject(p, file);
  return file;
}

/// Mean RGB of the 7×7 pixels around (x, y) of a grab of `r`.
std::array<double, 3> meanAround(const std::vector<float>& px, const Rect& r, int x, int y) {
  std::array<double, 3> sum{0.0, 0.0, 0.0};
  int count = 0;
  for (int dy = -3; dy <= 3; ++dy)
    for (int dx = -3; dx <= 3; ++dx) {
      const int u = std::clamp(x + dx, 0, r.w - 1), v = std::clamp(y + dy, 0, r.h - 1);
      const std::size_t i = (std::size_t(v) * std::size_t(r.w) + std::size_t(u)) * 3;
      for (int c = 0; c < 3; ++c) sum[std::size_t(c)] += px[i + std::size_t(c)];
      ++count;
    }
  for (double& s : sum) s /= count;
  return sum;
}

double brightness(const std::array<double, 3>& c) { return c[0] + c[1] + c[2]; }

bool volumeFinished(const nlohmann::json& j, std::uint64_t afterRestarts) {
  const auto& m = j["preview_modes"];
  // Finished means the picture too: the ray march of the finished volume is on screen.
  return m["mode"] == "volume" && m["volume_finished"].get<bool>() && m["volume_picture_final"].get<bool>() &&
         m["volume_restarts"].get<std::uint64_t>() > afterRestarts && !j["modal"].get<bool>();
}

}  // namespace

TEST(VolumePreviewGui, TwoSetsFillWhereTheyProjectAndRestartOnEdits) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path file = volumeExample(home, "two_sets.gridifs");
  const gridifs::Project project = gridifs::loadProject(file);
  App app(home, {file.string()});
  const std::optional<Rect> button = app.waitForStableRect("preview.mode.volume");
  ASSERT_TRUE(button) << "no Volume mode in the preview toolbar";
  clickRect(*button);
  nlohmann::json probe = app.waitFor([](const nlohmann::json& j) { return volumeFinished(j, 0); }, 120s);
  ASSERT_TRUE(volumeFinished(probe, 0)) << probe["preview_modes"].dump();
  const auto& m = probe["preview_modes"];
  EXPECT_EQ(m["volume_error"], "");
  EXPECT_EQ(m["volume_done"], m["volume_total"]);
  EXPECT_EQ(m["volume_total"].get<int>(), project.volume->iterations);
  EXPECT_GE(m["volume_uploads"].get<int>(), 1);
  EXPECT_FALSE(probe["rects"].contains("preview.message"));

  // Where the two sets' centres project: the sphere A (orange) and the box B (blue) are lit; the
  // image's corners show the background.
  const Rect image = rectOf(probe, "preview.image");
  const gridifs::OrbitCamera camera(project.camera, image.w, image.h);
  const auto a = camera.project(glm::dvec3(-0.45, 0.0, 0.0)), b = camera.project(glm::dvec3(0.45, 0.0, 0.0));
  ASSERT_TRUE(a.inFront && b.inFront);
  const auto px = grabSettled(home, image);
  const auto atA = meanAround(px, image, int(a.x), int(a.y)), atB = meanAround(px, image, int(b.x), int(b.y));
  const double background = project.render.background.x + project.render.background.y + project.render.background.z;
  EXPECT_GT(brightness(atA), background + 0.3) << "the sphere's centre is dark";
  EXPECT_GT(brightness(atB), background + 0.3) << "the box's centre is dark";
  // The colour volume holds each voxel's mean structural colour, a blend along the morph: the
  // sphere's side is the more orange (red over blue), the box's the more blue.
  EXPECT_GT(atA[0] - atA[2], atB[0] - atB[2] + 0.05) << "the colours of the sets are not told apart";
  for (const auto& corner : {meanAround(px, image, 4, 4), meanAround(px, image, image.w - 5, image.h - 5),
                             meanAround(px, image, image.w - 5, 4)})
    EXPECT_NEAR(brightness(corner), background, 0.03) << "a corner far from the sets is not the background";

  // Muting B is an edit of the functions: the computation starts again, and without B the box's
  // side of the picture goes dark (one median function keeps its own set, the sphere).
  std::uint64_t restarts = m["volume_restarts"];
  clickRect(rectOf(probe, "functions.mute.1"));
  probe = app.waitFor([&](const nlohmann::json& j) { return volumeFinished(j, restarts); }, 120s);
  ASSERT_TRUE(volumeFinished(probe, restarts)) << "muting a function did not restart the volume";
  EXPECT_EQ(probe["undo"], "Mute function");
  std::this_thread::sleep_for(300ms);
  const auto muted = grabSettled(home, image);
  EXPECT_LT(brightness(meanAround(muted, image, int(b.x), int(b.y))), background + 0.15)
      << "the box is still drawn after muting it";
  EXPECT_GT(brightness(meanAround(muted, image, int(a.x), int(a.y))), background + 0.3);

  // Ctrl+Z brings B back: another restart, the box lit again.
  restarts = probe["preview_modes"]["volume_restarts"];
  pressKeys("ctrl+z");
  probe = app.waitFor([&](const nlohmann::json& j) { return volumeFinished(j, restarts); }, 120s);
  ASSERT_TRUE(volumeFinished(probe, restarts)) << "undo did not restart the volume";
  std::this_thread::sleep_for(300ms);
  const auto undone = grabSettled(home, image);
  EXPECT_GT(brightness(meanAround(undone, image, int(b.x), int(b.y))), background + 0.3) << "the box did not come back";
  EXPECT_LT(meanAbsDifference(px, undone), 2.0) << describeDifference(px, undone, image);
}

// A set whose mesh file is missing cannot be voxelized: the preview says so over the image, the
// modeller keeps running, and switching back to the z-buffer works.
TEST(VolumePreviewGui, ASetThatCannotBeVoxelizedIsToldInline) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path file = volumeExample(home, "comma_to_letter.gridifs");  // comma.obj and letter_l.obj stay behind
  App app(home, {file.string()});
  const std::optional<Rect> button = app.waitForStableRect("preview.mode.volume");
  ASSERT_TRUE(button);
  clickRect(*button);
  nlohmann::json probe = app.waitFor(
      [](const nlohmann::json& j) {
        return j["preview_modes"]["volume_error"] != "" && j["rects"].contains("preview.message");
      },
      60s);
  const std::string error = probe["preview_modes"]["volume_error"];
  EXPECT_NE(error.find(".obj"), std::string::npos) << error;
  EXPECT_TRUE(probe["rects"].contains("preview.message"));
  EXPECT_FALSE(probe["preview_modes"]["volume_computing"].get<bool>());
  clickRect(rectOf(probe, "preview.mode.zbuffer"));
  probe = app.waitFor([](const nlohmann::json& j) { return j["preview_modes"]["mode"] == "zbuffer"; }, 10s);
  EXPECT_EQ(probe["preview_modes"]["mode"], "zbuffer");
  EXPECT_FALSE(probe["rects"].contains("preview.message"));
}
