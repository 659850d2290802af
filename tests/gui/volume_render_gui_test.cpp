// GUI tier for the volume image: a project of median sets only (the cloud creature, Sokolov &
// Gentil) opens in the Volume mode with no "Preview stopped" message, and the preview shows the
// same picture as `gridifs render --mode volume` from the same settings (the one ray march of
// render/volume_raymarch.h): the screen under Xvfb against the command line's PNG, scaled up the
// way the preview scales its picture, while a different density scale is told apart.
#include "gui/gui_harness.h"

using namespace gridifs::gui_test;

namespace {

/// The cloud creature and its mesh sets in the test's home; `volume` is merged into its render block.
fs::path cloudCopy(const TempFolder& home, const std::string& volume = "") {
  const fs::path assets = fs::path(GRIDIFS_ASSETS) / "volumes";
  for (const char* mesh : {"creature_sketch.obj", "creature_balls.obj"})
    fs::copy_file(assets / mesh, home.path / mesh, fs::copy_options::overwrite_existing);
  std::string text = fileText(assets / "cloud_creature.gridifs");
  if (!volume.empty()) text.insert(text.find("\"render\": {") + 11, "\"volume\": " + volume + ", ");
  const fs::path file = home.path / "cloud.gridifs";
  std::ofstream(file) << text;
  return file;
}

/// The PNG (straight alpha in the file, premultiplied as OpenImageIO reads it) over `background`, sampled at the
/// centres of a w × h grid the way a linearly filtered texture is drawn (texel centres at (i + 0.5) / width).
std::vector<float> composedAndScaled(const fs::path& png, const gridifs::Vec3& background, int w, int h) {
  OIIO::ImageBuf buf(png.string());
  const OIIO::ImageSpec& spec = buf.spec();
  const int iw = spec.width, ih = spec.height;
  std::vector<float> src(std::size_t(iw) * ih * 4);
  buf.get_pixels(OIIO::ROI(0, iw, 0, ih, 0, 1, 0, 4), OIIO::TypeDesc::FLOAT, src.data());
  std::vector<float> rgb(std::size_t(iw) * ih * 3);
  for (std::size_t p = 0; p < std::size_t(iw) * ih; ++p)
    for (int c = 0; c < 3; ++c) {
      const float a = src[4 * p + 3];
      // The preview's 8-bit picture of the same premultiplied colour.
      rgb[3 * p + c] =
          std::round(std::clamp(src[4 * p + c] + float(background[c]) * (1.0f - a), 0.0f, 1.0f) * 255.0f) / 255.0f;
    }
  std::vector<float> out(std::size_t(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float u = std::clamp((x + 0.5f) * iw / w - 0.5f, 0.0f, float(iw - 1)),
                  v = std::clamp((y + 0.5f) * ih / h - 0.5f, 0.0f, float(ih - 1));
      const int x0 = int(u), y0 = int(v), x1 = std::min(x0 + 1, iw - 1), y1 = std::min(y0 + 1, ih - 1);
      const float fx = u - x0, fy = v - y0;
      for (int c = 0; c < 3; ++c) {
        const auto at = [&](int i, int j) { return rgb[3 * (std::size_t(j) * iw + i) + c]; };
        out[3 * (std::size_t(y) * w + x) + c] =
            (at(x0, y0) * (1 - fx) + at(x1, y0) * fx) * (1 - fy) + (at(x0, y1) * (1 - fx) + at(x1, y1) * fx) * fy;
      }
    }
  return out;
}

bool pictureFinal(const nlohmann::json& j) {
  const auto& m = j["preview_modes"];
  return m["mode"] == "volume" && m["volume_picture_final"].get<bool>() && !j["modal"].get<bool>();
}

}  // namespace

TEST(VolumeRenderGui, SetsOnlyProjectOpensInVolumeModeAndMatchesTheCommandLine) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path file = cloudCopy(home, R"({"density_scale": 16, "transfer": [
      {"density": 0, "color": [0.3, 0.4, 0.9], "opacity": 0}, {"density": 0.25, "color": [1, 0.85, 0.7], "opacity": 0.7},
      {"density": 1, "color": [1, 1, 1], "opacity": 1}]})");
  const gridifs::Project project = gridifs::loadProject(file);
  App app(home, {file.string()});
  nlohmann::json probe = app.waitFor(pictureFinal, 180s);
  ASSERT_TRUE(pictureFinal(probe)) << probe["preview_modes"].dump();
  EXPECT_EQ(probe["preview_modes"]["mode"], "volume") << "a project of median sets opens in the Volume mode";
  EXPECT_EQ(probe["preview_modes"]["volume_error"], "");
  EXPECT_FALSE(probe["rects"].contains("preview.message")) << "the preview shows a message";
  EXPECT_FALSE(probe["dirty"].get<bool>()) << "opening in the Volume mode changed the project";

  const Rect image = rectOf(probe, "preview.image");
  const auto& m = probe["preview_modes"];
  const int n = m["volume_resolution"].get<int>(), w = m["volume_image_width"].get<int>(),
            h = m["volume_image_height"].get<int>();
  const auto screen = grabSettled(home, image);
  const auto cli = [&](const std::string& name, const std::string& extra) {
    const fs::path out = home.path / name;
    const std::string command = std::string(GRIDIFS_EXE) + " render '" + file.string() + "' --mode volume -q -o '" +
                                out.string() + "' --resolution " + std::to_string(n) + " --width " + std::to_string(w) +
                                " --height " + std::to_string(h) + extra;
    EXPECT_EQ(run(command), 0) << command;
    return composedAndScaled(out, project.render.background, image.w, image.h);
  };
  const double same = meanAbsDifference(screen, cli("same.png", ""));
  RecordProperty("preview_vs_cli_mean_abs_difference", std::to_string(same));
  EXPECT_LT(same, 1.0) << "the preview and the command line differ (mean difference in 8-bit levels)";
  // A picture of other settings is told apart: the comparison can fail.
  fs::path thinner = home.path / "thin.gridifs";
  std::string text = fileText(file);
  text.replace(text.find("\"density_scale\": 16"), 19, "\"density_scale\": 2");
  std::ofstream(thinner) << text;
  const fs::path out = home.path / "thin.png";
  ASSERT_EQ(
      run(std::string(GRIDIFS_EXE) + " render '" + thinner.string() + "' --mode volume -q -o '" + out.string() +
          "' --resolution " + std::to_string(n) + " --width " + std::to_string(w) + " --height " + std::to_string(h)),
      0);
  const double other = meanAbsDifference(screen, composedAndScaled(out, project.render.background, image.w, image.h));
  // (Most of the picture is background, so the mean difference of a thinner cloud is a few levels.)
  EXPECT_GT(other, 5.0 * same);
  EXPECT_GT(other, 1.0);
}

TEST(VolumeRenderGui, TheChosenModeIsSavedAndReopened) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path file = cloudCopy(home);
  {
    App app(home, {file.string()});
    const std::optional<Rect> mesh = app.waitForStableRect("preview.mode.mesh");
    ASSERT_TRUE(mesh);
    clickRect(*mesh);
    nlohmann::json probe = app.waitFor([](const nlohmann::json& j) { return j["preview_modes"]["mode"] == "mesh"; });
    ASSERT_EQ(probe["preview_modes"]["mode"], "mesh");
    saveAndWait(app);
  }
  EXPECT_EQ(gridifs::loadProject(file).preview_mode, gridifs::StoredPreviewMode::Mesh);
  App again(home, {file.string()});
  const nlohmann::json probe =
      again.waitFor([](const nlohmann::json& j) { return j["preview_modes"]["mode"] == "mesh"; });
  EXPECT_EQ(probe["preview_modes"]["mode"], "mesh");
}
