// OSC into the running modeller, as a controller app sends it: real UDP datagrams to
// 127.0.0.1:--osc-port. A bound address moves its parameter (no undo step), /gridifs/set sets any
// parameter as one undo step, and malformed or out-of-range messages are counted, shown and never
// applied. The preview restarts on the new value.
#include <gtest/gtest.h>

#include <cmath>

#include "io/project_io.h"
#include "live/live_drive.h"
#include "tests/gui/gui_harness.h"
#include "tests/support/osc_packet.h"

using namespace gridifs::gui_test;
using gridifs::test_support::OscPacket;
using gridifs::test_support::sendUdp;

/// The default example, small, with the camera's yaw bound to OSC /knob1 (-180 to 180), in `home`.
fs::path knobBoundCopy(const TempFolder& home) {
  const fs::path project = exampleCopy(home, "default.gridifs", 300'000);
  gridifs::Project p = gridifs::loadProject(project);
  p.bindings.push_back(gridifs::Binding{"camera.yaw", "osc:/knob1", -180.0, 180.0, 0.0});
  gridifs::saveProject(p, project);
  return project;
}

TEST(LiveGui, OscMovesBoundParametersAndSetsAnyWithinItsRange) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = knobBoundCopy(home);
  const int port = gridifs::test_support::freeUdpPort();
  App app(home, {project.string(), "--osc-port", std::to_string(port)});
  nlohmann::json probe = app.waitForPreview();
  ASSERT_EQ(probe["live"]["osc_port"], port) << probe["status"];
  const std::uint64_t restarts = probe["preview"]["restarts"].get<std::uint64_t>();
  const auto revision = probe["revision"].get<std::uint64_t>();

  // A knob at three quarters: yaw = -180 + 0.75 · 360, no undo step, and the preview restarts.
  ASSERT_TRUE(sendUdp(port, OscPacket("/knob1").f(0.75f).bytes()));
  probe = app.waitFor([](const nlohmann::json& j) { return j["camera"]["yaw"] == 90.0; });
  EXPECT_EQ(probe["camera"]["yaw"], 90.0);
  EXPECT_NE(probe["undo"], "Set camera.yaw");
  probe = app.waitForPreview(restarts);
  EXPECT_GT(probe["preview"]["restarts"].get<std::uint64_t>(), restarts);
  EXPECT_GT(probe["revision"].get<std::uint64_t>(), revision);
  std::printf("OSC message to the preview's restart: %.2f ms\n", probe["live"]["latency_ms"].get<double>());

  // /gridifs/set: any parameter, as one undo step.
  ASSERT_TRUE(sendUdp(port, OscPacket("/gridifs/set").s("functions[0].weight").f(2.5f).bytes()));
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Set functions[0].weight"; });
  EXPECT_EQ(probe["undo"], "Set functions[0].weight");

  // Refused and counted, never applied: out of 0..1, out of the parameter's range, an address
  // nothing listens to, and a datagram that is not OSC.
  ASSERT_TRUE(sendUdp(port, OscPacket("/knob1").f(1.5f).bytes()));
  ASSERT_TRUE(sendUdp(port, OscPacket("/gridifs/set").s("functions[0].weight").f(-3.0f).bytes()));
  ASSERT_TRUE(sendUdp(port, OscPacket("/nobody").f(0.5f).bytes()));
  ASSERT_TRUE(sendUdp(port, std::vector<char>{'j', 'u', 'n', 'k'}));
  probe = app.waitFor([](const nlohmann::json& j) { return j["live"]["refused"] == 3 && j["live"]["malformed"] == 1; });
  EXPECT_EQ(probe["live"]["refused"], 3);
  EXPECT_EQ(probe["live"]["malformed"], 1);
  EXPECT_EQ(probe["live"]["received"], 6);
  EXPECT_EQ(probe["camera"]["yaw"], 90.0);

  saveAndWait(app);
  const gridifs::Project saved = gridifs::loadProject(project);
  EXPECT_EQ(saved.camera.yaw, 90.0);
  EXPECT_EQ(saved.functions[0].weight, 2.5);
  ASSERT_EQ(saved.bindings.size(), 1u);
  EXPECT_EQ(saved.bindings[0].source, "osc:/knob1");
}

TEST(LiveGui, SoundBoundNumbersFollowThePlayheadWithoutUndoSteps) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path example = fs::path(GRIDIFS_ASSETS) / "live";
  const fs::path project = home.path / "dancing_twist.gridifs";
  {
    gridifs::Project p = gridifs::loadProject(example / "dancing_twist.gridifs");
    p.render.samples = 200'000;
    gridifs::saveProject(p, project);
    fs::copy_file(example / "beat.wav", home.path / "beat.wav");
  }
  const gridifs::Project loaded = gridifs::loadProject(project);
  const gridifs::LiveDrive drive = gridifs::LiveDrive::forProject(loaded, home.path);
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();
  const std::string undo = probe["undo"];
  // Scrub to about a third of the timeline: the yaw (bound to the chord's band) is the binding's
  // value at the frame the playhead landed on.
  const Rect scrub = rectOf(probe, "timeline.scrub");
  clickAt(scrub.x + scrub.w / 3, scrub.y + scrub.h / 2);
  probe = app.waitFor([](const nlohmann::json& j) { return j["timeline"]["time"].get<double>() > 1.0; });
  const double t = probe["timeline"]["time"];
  ASSERT_GT(t, 1.0);
  const auto v = drive.valueAt(loaded, 4, t);
  ASSERT_TRUE(v);
  ASSERT_EQ(loaded.bindings[4].path, "camera.yaw");
  const double expected = 10.0 + *v * 60.0;
  probe = app.waitFor(
      [&](const nlohmann::json& j) { return std::abs(j["camera"]["yaw"].get<double>() - expected) < 1e-9; });
  EXPECT_NEAR(probe["camera"]["yaw"].get<double>(), expected, 1e-9) << "at t = " << t;
  EXPECT_NE(probe["camera"]["yaw"].get<double>(), loaded.camera.yaw);
  EXPECT_EQ(probe["undo"], undo) << "following the sound is no edit";
}

TEST(LiveGui, ATakeTurnsLiveInputIntoKeysAsOneUndoStep) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const int port = gridifs::test_support::freeUdpPort();
  App app(home, {knobBoundCopy(home).string(), "--osc-port", std::to_string(port)});
  nlohmann::json probe = app.waitForPreview();
  focusWindow();
  clickRect(rectOf(probe, "menu.view"));
  const auto live = app.waitForStableRect("menu.live");
  ASSERT_TRUE(live) << "the View menu opens";
  clickRect(*live);
  const auto record = app.waitForStableRect("live.record");
  ASSERT_TRUE(record) << "View > Live opens";
  clickRect(*record);
  probe = app.waitFor([](const nlohmann::json& j) { return j["live"]["recording"] == true; });
  ASSERT_TRUE(probe["live"]["recording"].get<bool>());

  // A value at the start, then the playhead moved (the knob held), then a new value there.
  ASSERT_TRUE(sendUdp(port, OscPacket("/knob1").f(0.25f).bytes()));
  app.waitFor([](const nlohmann::json& j) { return j["camera"]["yaw"] == -90.0; });
  const Rect scrub = rectOf(probe, "timeline.scrub");
  clickAt(scrub.x + scrub.w / 2, scrub.y + scrub.h / 2);
  probe = app.waitFor([](const nlohmann::json& j) { return j["timeline"]["time"].get<double>() > 0.5; });
  const double t = probe["timeline"]["time"];
  ASSERT_GT(t, 0.5);
  ASSERT_TRUE(sendUdp(port, OscPacket("/knob1").f(0.75f).bytes()));
  app.waitFor([](const nlohmann::json& j) { return j["camera"]["yaw"] == 90.0; });
  clickRect(rectOf(app.probe(), "live.record"));  // Stop (the window's lines above it may have grown)
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Record take"; });
  ASSERT_EQ(probe["undo"], "Record take") << probe["live"].dump() << " " << probe["timeline"]["tracks"].dump() << " "
                                          << probe["rects"]["live.record"].dump() << " " << probe["status"];
  const auto& keys = probe["timeline"]["tracks"]["camera.yaw"];
  ASSERT_EQ(keys.size(), 2u) << keys.dump();
  EXPECT_EQ(keys[0][0], 0.0);
  EXPECT_EQ(keys[0][1], -90.0);
  EXPECT_NEAR(keys[1][0].get<double>(), t, 1e-9);
  EXPECT_EQ(keys[1][1], 90.0);

  // One undo step takes the whole take back.
  pressKeys("ctrl+z");
  probe = app.waitFor([](const nlohmann::json& j) { return !j["timeline"]["tracks"].contains("camera.yaw"); });
  EXPECT_FALSE(probe["timeline"]["tracks"].contains("camera.yaw"));
}

/// The dancing example with its sound beside it in `home`.
fs::path dancingCopy(const TempFolder& home) {
  const fs::path example = fs::path(GRIDIFS_ASSETS) / "live";
  const fs::path project = home.path / "dancing_twist.gridifs";
  gridifs::Project p = gridifs::loadProject(example / "dancing_twist.gridifs");
  p.render.samples = 100'000;
  gridifs::saveProject(p, project);
  fs::copy_file(example / "beat.wav", home.path / "beat.wav", fs::copy_options::overwrite_existing);
  return project;
}

/// Presses Play and returns how far the playhead got after about a second.
double playForASecond(App& app) {
  nlohmann::json probe = app.waitForPreview();
  clickRect(rectOf(probe, "timeline.play"));
  probe = app.waitFor([](const nlohmann::json& j) { return j["timeline"]["playing"] == true; });
  const double t0 = probe["timeline"]["time"];
  std::this_thread::sleep_for(1200ms);
  return app.probe()["timeline"]["time"].get<double>() - t0;
}

TEST(LiveGui, PlaybackSoundsWhereThereIsAnOutputAndKeepsASilentClockWhereNot) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  {
    // These machines have no sound card: SDL finds no output, and the timeline keeps its clock.
    TempFolder home;
    App app(home, {dancingCopy(home).string()});
    const double moved = playForASecond(app);
    EXPECT_GT(moved, 0.5) << "the silent clock plays";
    const std::string output = app.probe()["live"]["sound_output"];
    EXPECT_NE(output.find("silent clock"), std::string::npos) << output;
  }
  {
    // SDL's dummy driver consumes the sound in real time: its played samples drive the playhead.
    ::setenv("SDL_AUDIODRIVER", "dummy", 1);
    TempFolder home;
    App app(home, {dancingCopy(home).string()});
    const double moved = playForASecond(app);
    ::unsetenv("SDL_AUDIODRIVER");
    EXPECT_GT(moved, 0.5) << "the sound's clock plays";
    EXPECT_LT(moved, 2.5);
    EXPECT_EQ(app.probe()["live"]["sound_output"], "dummy");
  }
}
