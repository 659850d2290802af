// The preview on the GPU compute renderer (--device gpu; Mesa's llvmpipe under Xvfb): the probe
// names the device, points stream in and the preview shows the attractor; an edit restarts it.
#include <gtest/gtest.h>

#include "gui/gui_harness.h"

namespace gridifs::gui_test {
namespace {

TEST(PreviewDeviceGui, GpuPreviewStreamsTheAttractor) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "twisted_functions.gridifs");
  const fs::path shot = home.path / "shot.png";
  App app(home, {project.string(), "--device", "gpu", "--screenshot", shot.string(), "--frames", "10", "--wait-points",
                 "1000000"});
  ASSERT_EQ(app.waitExit(60s), 0);
  const nlohmann::json probe = app.probe();
  const nlohmann::json& preview = probe["preview"];
  EXPECT_EQ(preview["device"].get<std::string>().rfind("gpu", 0), 0u) << preview.dump();
  EXPECT_GE(preview["samples"].get<std::int64_t>(), 1'000'000);
  EXPECT_GT(preview["hit_pixels"].get<std::int64_t>(), 2000);
}

TEST(PreviewDeviceGui, CpuPreviewWhenAsked) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "twisted_functions.gridifs");
  App app(home, {project.string(), "--device", "cpu", "--screenshot", (home.path / "s.png").string(), "--frames", "5",
                 "--wait-points", "100000"});
  ASSERT_EQ(app.waitExit(60s), 0);
  EXPECT_EQ(app.probe()["preview"]["device"].get<std::string>(), "cpu");
}

}  // namespace
}  // namespace gridifs::gui_test
