// The Camera window driven as an artist drives it: open it from the preview's toolbar, turn the
// stereo pair on, drag the field of view to its end and the lens blur up (one undo step each), see
// the preview render both eyes and spread the blurred points, save, and undo back to the file's
// camera.
#include <gtest/gtest.h>

#include "io/project_io.h"
#include "tests/gui/gui_harness.h"

using namespace gridifs::gui_test;

TEST(CameraGui, StereoAndFieldOfViewFromTheCameraWindowWithUndo) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "default.gridifs", 300'000);
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();
  EXPECT_EQ(probe["camera"]["projection"], "perspective");
  clickRect(rectOf(probe, "preview.camera"));
  const auto stereo = app.waitForStableRect("camera.stereo");
  ASSERT_TRUE(stereo) << "the Camera window opens";
  clickAt(stereo->x + stereo->h / 2, stereo->y + stereo->h / 2);
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Stereo on"; });
  EXPECT_TRUE(probe["camera"]["stereo"].get<bool>());
  probe = app.waitFor([](const nlohmann::json& j) {
    const auto& p = j["preview"];
    return p["done"].get<bool>() && p["image_generation"] == p["generation"] && j["undo"] == "Stereo on";
  });
  EXPECT_GT(probe["preview"]["hit_pixels"].get<std::int64_t>(), 1000) << "both eyes drawn";
  const std::uint64_t restarts = probe["preview"]["restarts"].get<std::uint64_t>();

  // The field of view's slider dragged to its right end: a flat camera stops at 170°.
  const Rect fov = rectOf(probe, "camera.fov");
  dragFrom(fov.x + fov.w / 2, fov.y + fov.h / 2, fov.x + fov.w + 40, fov.y + fov.h / 2);
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Field of view"; });
  EXPECT_DOUBLE_EQ(probe["camera"]["fov"].get<double>(), 170.0);
  probe = app.waitForPreview(restarts);
  EXPECT_GT(probe["preview"]["hit_pixels"].get<std::int64_t>(), 0) << "a smaller picture, still there";

  // The lens blur's slider dragged towards its right end: what lies off the target's plane
  // blurs, so the same points cover more pixels.
  const std::int64_t sharpPixels = probe["preview"]["hit_pixels"].get<std::int64_t>();
  const std::uint64_t sharpRestarts = probe["preview"]["restarts"].get<std::uint64_t>();
  const Rect blur = rectOf(probe, "camera.lens_blur");
  dragFrom(blur.x + blur.w / 2, blur.y + blur.h / 2, blur.x + blur.w + 40, blur.y + blur.h / 2);
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Lens blur"; });
  const double blurred = probe["camera"]["lens_blur"].get<double>();
  EXPECT_GT(blurred, 1.0);
  probe = app.waitForPreview(sharpRestarts);
  EXPECT_GT(probe["preview"]["hit_pixels"].get<std::int64_t>(), sharpPixels * 11 / 10) << "blurred points spread";

  saveAndWait(app);
  const gridifs::Project saved = gridifs::loadProject(project);
  ASSERT_TRUE(saved.camera.stereo);
  EXPECT_EQ(saved.camera.fov, 170.0);
  EXPECT_EQ(saved.camera.lens_blur, blurred);

  // Three undo steps bring the file's camera back.
  pressKeys("ctrl+z");
  pressKeys("ctrl+z");
  pressKeys("ctrl+z");
  probe = app.waitFor(
      [](const nlohmann::json& j) { return !j["camera"]["stereo"].get<bool>() && j["camera"]["fov"] == 35.0; });
  EXPECT_FALSE(probe["camera"]["stereo"].get<bool>());
  EXPECT_EQ(probe["camera"]["fov"], 35.0);
  EXPECT_EQ(probe["camera"]["lens_blur"], 0.0);
}
