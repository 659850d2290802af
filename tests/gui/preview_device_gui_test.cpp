// The preview on the GPU compute renderer (--device gpu; Mesa's llvmpipe under Xvfb): the probe
// names the device, points stream in and the preview shows the attractor, the picture the CPU
// preview shows (sampling noise aside); an edit restarts it.
#include <gtest/gtest.h>

#include "gpu/correlation.h"
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

/// The preview image's pixels (grey levels) in a --screenshot of the modeller on `device` after a
/// million points of `project`, whose camera is turned by `yaw` degrees.
std::vector<float> previewPicture(const std::string& device, double yaw = 0.0) {
  TempFolder home;
  const fs::path project = exampleCopy(home, "twisted_functions.gridifs");
  if (yaw != 0.0) {
    Project p = loadProject(project);
    p.camera.yaw += yaw;
    saveProject(p, project);
  }
  const fs::path shot = home.path / "shot.png";
  App app(home, {project.string(), "--device", device, "--screenshot", shot.string(), "--frames", "10", "--wait-points",
                 "1000000"});
  EXPECT_EQ(app.waitExit(60s), 0);
  const nlohmann::json probe = app.probe();
  const auto& r = probe["rects"]["preview.image"];
  const int x = int(r[0].get<double>()), y = int(r[1].get<double>()), w = int(r[2].get<double>()),
            h = int(r[3].get<double>());
  OIIO::ImageBuf buf(shot.string());
  std::vector<float> rgb(std::size_t(w) * std::size_t(h) * 3);
  EXPECT_TRUE(buf.get_pixels(OIIO::ROI(x, x + w, y, y + h, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, rgb.data()));
  std::vector<float> grey(std::size_t(w) * std::size_t(h));
  for (std::size_t i = 0; i < grey.size(); ++i) grey[i] = rgb[i * 3] + rgb[i * 3 + 1] + rgb[i * 3 + 2];
  return grey;
}

// The GPU's preview is the CPU's picture: the same prepared render (core/job/preview_plan.h) on
// either renderer gives images that agree but for sampling noise, and a turned camera does not.
TEST(PreviewDeviceGui, GpuPreviewIsTheCpusPicture) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  const std::vector<float> gpu = previewPicture("gpu");
  const std::vector<float> cpu = previewPicture("cpu");
  const std::vector<float> turned = previewPicture("cpu", 25.0);
  ASSERT_EQ(gpu.size(), cpu.size());
  ASSERT_EQ(turned.size(), cpu.size());
  ASSERT_GT(gpu.size(), 10000u);
  const double same = test::correlation(gpu, cpu), other = test::correlation(turned, cpu);
  std::printf("preview correlation: gpu vs cpu %.4f, turned camera vs cpu %.4f\n", same, other);
  EXPECT_GT(same, 0.9);
  EXPECT_LT(other, same - 0.1) << "the comparison cannot tell another picture apart";
}

}  // namespace
}  // namespace gridifs::gui_test
