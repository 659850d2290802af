// GUI tier: the timeline under the preview, key buttons beside parameters, and File › Render
// animation, in the real modeller window under Xvfb with real input (gui/gui_harness.h).
#include "gui/gui_harness.h"
#include "schema/project_time.h"

using namespace gridifs::gui_test;

namespace {

/// The default example with its camera turning a quarter turn over two seconds.
fs::path turningCopy(const TempFolder& home, double fps = 24.0, double end = 2.0, int width = 0) {
  gridifs::Project p = gridifs::loadProject(fs::path(GRIDIFS_ASSETS) / "default.gridifs");
  p.render.samples = 1'000'000;
  if (width > 0) {
    p.render.width = width;
    p.render.height = width * 3 / 4;
    p.render.samples = 40'000;
  }
  p.animation = gridifs::AnimationSettings{fps, 0.0, end, true};
  p.tracks["camera.yaw"].keys = {{0.0, p.camera.yaw}, {end, p.camera.yaw + 90.0}};
  const fs::path file = home.path / "turning.gridifs";
  gridifs::saveProject(p, file);
  return file;
}

std::size_t keyCount(const nlohmann::json& probe, const std::string& path) {
  const auto& tracks = probe["timeline"]["tracks"];
  return tracks.contains(path) ? tracks[path].size() : 0;
}

}  // namespace

TEST(TimelineGui, ScrubbingMovesTheTimeAndThePreviewFollows) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  App app(home, {turningCopy(home).string()});
  nlohmann::json probe = app.waitForPreview();
  ASSERT_TRUE(probe["preview"]["done"].get<bool>());
  EXPECT_EQ(probe["timeline"]["time"].get<double>(), 0.0);
  const Rect previewRect = rectOf(probe, "preview.image");
  const Rect scrub = rectOf(probe, "timeline.scrub");
  const auto atStart = grabSettled(home, previewRect);

  // Scrub to the middle and past: many frames in one drag, each a new time for the preview.
  const std::int64_t framesBefore = probe["frame"];
  const auto started = std::chrono::steady_clock::now();
  dragFrom(scrub.x + scrub.w / 10, scrub.y + scrub.h / 2, scrub.x + scrub.w / 2, scrub.y + scrub.h / 2, 40);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  probe = app.waitForPreview(probe["preview"]["restarts"].get<std::uint64_t>());
  const std::int64_t frames = probe["frame"].get<std::int64_t>() - framesBefore;
  std::printf("scrubbing: %lld frames in %.2f s (%.1f fps with the preview restarting)\n", (long long)frames, seconds,
              double(frames) / seconds);
  const double t = probe["timeline"]["time"];
  EXPECT_NEAR(t, 1.0, 0.15) << "the middle of a 0..2 s timeline";
  EXPECT_NEAR(t * 24.0, std::round(t * 24.0), 1e-9) << "scrubbing lands on frames";
  EXPECT_EQ(probe["undo"], "") << "scrubbing is not an undo step";
  const auto middle = grabScreen(home, previewRect);
  EXPECT_GT(meanAbsDifference(atStart, middle), 1.0) << "the preview did not follow the time";

  // Back to the first frame (Shift+Left) shows the first picture again.
  pressKeys("shift+Left");
  probe = app.waitFor([](const nlohmann::json& j) { return j["timeline"]["time"].get<double>() == 0.0; }, 10s);
  probe = app.waitForPreview(probe["preview"]["restarts"].get<std::uint64_t>() - 1);
  EXPECT_EQ(probe["timeline"]["time"].get<double>(), 0.0);
  const auto again = grabSettled(home, previewRect);
  EXPECT_LT(meanAbsDifference(atStart, again), 0.5) << describeDifference(atStart, again, previewRect);

  // Alt+A plays: the time moves on without any undo step; Alt+A again pauses.
  pressKeys("alt+a");
  probe = app.waitFor([](const nlohmann::json& j) { return j["timeline"]["time"].get<double>() > 0.2; }, 10s);
  EXPECT_TRUE(probe["timeline"]["playing"].get<bool>());
  pressKeys("alt+a");
  probe = app.waitFor([](const nlohmann::json& j) { return !j["timeline"]["playing"].get<bool>(); }, 10s);
  EXPECT_FALSE(probe["timeline"]["playing"].get<bool>());
  EXPECT_EQ(probe["undo"], "");
}

TEST(TimelineGui, KeyAtOneTimeThenEditAtAnotherMakesATrackAndUndoRemovesIt) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "default.gridifs");
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();
  const std::string path = "functions[0].ops[0].k";
  const Rect row = rectOf(probe, "ops.row.0");
  clickAt(row.x + row.w / 2, row.y + row.h / 2);
  const std::optional<Rect> key = app.waitForStableRect("key." + path);
  ASSERT_TRUE(key) << "no key button beside the twist's k";

  // A key at t = 0.
  clickRect(*key);
  probe = app.waitFor([&](const nlohmann::json& j) { return keyCount(j, path) == 1; }, 10s);
  ASSERT_EQ(keyCount(probe, path), 1u);
  EXPECT_EQ(probe["undo"], "Set key");
  EXPECT_EQ(probe["timeline"]["tracks"][path][0][0].get<double>(), 0.0);

  // To the middle of the timeline, then drag k: the edit keys it there.
  const Rect scrub = rectOf(probe, "timeline.scrub");
  clickAt(scrub.x + scrub.w / 2, scrub.y + scrub.h / 2);
  probe = app.waitFor([](const nlohmann::json& j) { return j["timeline"]["time"].get<double>() > 1.0; }, 10s);
  const double t = probe["timeline"]["time"];
  ASSERT_GT(t, 1.0);
  const Rect slider = *app.waitForStableRect("twist.k");
  dragFrom(slider.x + slider.w / 2, slider.y + slider.h / 2, slider.x + slider.w * 3 / 4, slider.y + slider.h / 2);
  probe = app.waitFor([&](const nlohmann::json& j) { return keyCount(j, path) == 2; }, 10s);
  ASSERT_EQ(keyCount(probe, path), 2u) << probe["timeline"]["tracks"].dump();
  EXPECT_EQ(probe["undo"], "twist k");
  EXPECT_DOUBLE_EQ(probe["timeline"]["tracks"][path][1][0].get<double>(), t);
  const double k0 = probe["timeline"]["tracks"][path][0][1], k1 = probe["timeline"]["tracks"][path][1][1];
  EXPECT_GT(k1, k0 + 0.3) << "the second key holds the dragged value";

  // The two keys animate k: the project saved now evaluates between them.
  pressKeys("ctrl+s");
  probe = app.waitFor([](const nlohmann::json& j) { return !j["dirty"].get<bool>(); }, 10s);
  const gridifs::Project saved = gridifs::loadProject(project);
  const double mid = std::get<gridifs::TwistOp>(gridifs::projectAtTime(saved, t / 2).functions[0].ops[0].params).k;
  EXPECT_NEAR(mid, (k0 + k1) / 2, 1e-9);

  // Undo removes the second key, then the track; the time stays where the artist put it.
  pressKeys("ctrl+z");
  probe = app.waitFor([&](const nlohmann::json& j) { return keyCount(j, path) == 1; }, 10s);
  EXPECT_EQ(keyCount(probe, path), 1u);
  EXPECT_EQ(probe["timeline"]["time"].get<double>(), t);
  pressKeys("ctrl+z");
  probe = app.waitFor([&](const nlohmann::json& j) { return keyCount(j, path) == 0; }, 10s);
  EXPECT_EQ(keyCount(probe, path), 0u);
  EXPECT_TRUE(probe["timeline"]["tracks"].empty());
}

TEST(TimelineGui, RenderAnimationWritesEveryFrame) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  // 4 fps over one second: frames 0..4.
  App app(home, {turningCopy(home, 4.0, 1.0, 96).string()});
  nlohmann::json probe = openRenderAnimation(app);
  const std::optional<Rect> render = app.waitForStableRect("animation.render");
  ASSERT_TRUE(render) << "the dialog did not open";
  clickRect(*render);
  probe = app.waitFor([](const nlohmann::json& j) { return j["render_animation"]["phase"] == "done"; }, 60s);
  ASSERT_EQ(probe["render_animation"]["phase"], "done") << probe["render_animation"].dump();
  EXPECT_EQ(probe["render_animation"]["frames_done"].get<int>(), 5);
  std::vector<std::vector<float>> frames;
  for (int f = 0; f <= 4; ++f) {
    char name[64];
    std::snprintf(name, sizeof name, "turning_%04d.png", f);
    const fs::path file = home.path / "turning_frames" / name;
    ASSERT_TRUE(fs::exists(file)) << file;
    std::vector<float> px;
    ASSERT_NO_FATAL_FAILURE(readLitFrame(file, 96, 72, px));
    frames.push_back(std::move(px));
  }
  EXPECT_FALSE(fs::exists(home.path / "turning_frames" / "turning_0005.png"));
  // The camera turns between frames.
  EXPECT_GT(meanAbsDifference(frames[0], frames[4]), 1.0);
  EXPECT_GT(meanAbsDifference(frames[0], frames[1]), 0.2);
}

TEST(TimelineGui, RenderAnimationOnASlurmClusterWritesTheJobFolderAndShowsItsStatus) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  App app(home, {turningCopy(home, 4.0, 1.0, 96).string()});
  nlohmann::json probe = openRenderAnimation(app);
  const std::optional<Rect> farm = app.waitForStableRect("animation.farm");
  ASSERT_TRUE(farm) << "the dialog did not open";
  clickAt(farm->x + 8, farm->y + farm->h / 2);  // the checkbox itself
  const std::optional<Rect> write = app.waitForStableRect("animation.farm_write");
  ASSERT_TRUE(write) << "the farm's buttons did not appear";
  clickRect(*write);
  // Frames 0..4 in the default 4 parts, beside the project: turning_farm/.
  const fs::path job = home.path / "turning_farm";
  probe = app.waitFor([](const nlohmann::json& j) { return !j["render_animation"]["farm_status"].empty(); }, 20s);
  const auto& status = probe["render_animation"]["farm_status"];
  ASSERT_FALSE(status.empty()) << probe["render_animation"].dump();
  EXPECT_EQ(status[0].get<std::string>().rfind("frame 0: 0/4 parts, not merged", 0), 0u) << status.dump();
  EXPECT_NE(status.dump().find("0 of 5 frames have every part, 0 merged"), std::string::npos) << status.dump();
  ASSERT_TRUE(fs::exists(job / "farm.json"));
  const std::string script = [&] {
    std::ifstream in(job / "render.sbatch");
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  EXPECT_NE(script.find("turning.gridifs"), std::string::npos);
  EXPECT_NE(script.find("--samples"), std::string::npos);
  EXPECT_NE(script.find("parts=4"), std::string::npos);
}
