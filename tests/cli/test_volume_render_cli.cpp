// gridifs render --mode volume through the real executable: the cloud creature's volume (median
// sets, Sokolov & Gentil) lit and as an X-ray, PNG with alpha and EXR with depth; bad
// render.volume values, an absurd resolution and wrong options → exit 2, one sentence, nothing
// written.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "io/project_io.h"
#include "tests/cli/image_file_read.h"
#include "tests/cli/run_command.h"

namespace gridifs {
namespace {

using namespace test_support;
namespace fs = std::filesystem;

using Image = ImageFile;

/// The file's own values: PNG keeps straight alpha, which OpenImageIO would otherwise premultiply.
Image readImage(const fs::path& file) { return readImageFile(file, true); }

/// The cloud creature beside its mesh sets, with `render` merged into its render block.
fs::path cloudCopy(const ScratchDir& dir, const std::string& volumeJson = "") {
  const fs::path assets = fs::path(GRIDIFS_ASSETS) / "volumes";
  for (const char* mesh : {"creature_sketch.obj", "creature_balls.obj"})
    fs::copy_file(assets / mesh, dir.path / mesh, fs::copy_options::overwrite_existing);
  std::string text = slurp(assets / "cloud_creature.gridifs");
  if (!volumeJson.empty()) {
    const std::size_t at = text.find("\"render\": {");
    text.insert(at + 11, "\"volume\": " + volumeJson + ", ");
  }
  const fs::path file = dir.path / "cloud.gridifs";
  std::ofstream(file) << text;
  return file;
}

const std::string kSmall = " --resolution 32 --width 96 --height 72 -q";

TEST(VolumeRenderCli, LitPngHasAlphaAndXrayIsGrey) {
  ScratchDir dir("volume-render-cli");
  const fs::path lit = dir.path / "lit.png", xray = dir.path / "xray.png";
  CommandResult r =
      runGridifs("render " + quote(cloudCopy(dir).string()) + " --mode volume -o " + quote(lit.string()) + kSmall);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Image a = readImage(lit);
  ASSERT_EQ(a.channels, 4);
  EXPECT_EQ(a.width, 96);
  float alphaMin = 1.0f, alphaMax = 0.0f;
  for (std::size_t p = 0; p < a.pixels.size() / 4; ++p) {
    alphaMin = std::min(alphaMin, a.pixels[4 * p + 3]);
    alphaMax = std::max(alphaMax, a.pixels[4 * p + 3]);
  }
  EXPECT_EQ(alphaMin, 0.0f) << "the corners are transparent";
  EXPECT_GT(alphaMax, 0.9f) << "the cloud is opaque somewhere";

  const fs::path xrayProject = cloudCopy(dir, R"({"display": "xray", "density_scale": 6})");
  r = runGridifs("render " + quote(xrayProject.string()) + " --mode volume -o " + quote(xray.string()) + kSmall);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Image x = readImage(xray);
  ASSERT_EQ(x.channels, 4);
  int seen = 0;
  for (std::size_t p = 0; p < x.pixels.size() / 4; ++p) {
    if (x.pixels[4 * p + 3] < 0.05f) continue;
    ++seen;
    // Straight alpha in the PNG: grey white where anything is seen.
    EXPECT_NEAR(x.pixels[4 * p], x.pixels[4 * p + 2], 1.5f / 255.0f);
    EXPECT_NEAR(x.pixels[4 * p], 1.0f, 2.0f / 255.0f);
  }
  EXPECT_GT(seen, 100);
}

TEST(VolumeRenderCli, ExrCarriesDepthAndTheSameSettingsGiveTheSameImage) {
  ScratchDir dir("volume-render-cli");
  const fs::path project = cloudCopy(dir, R"({"transfer": [{"density": 0, "color": [0.2, 0.3, 0.8], "opacity": 0},
      {"density": 0.3, "color": [1, 0.8, 0.6], "opacity": 0.6}, {"density": 1, "color": [1, 1, 1], "opacity": 1}]})");
  const fs::path a = dir.path / "a.exr", b = dir.path / "b.exr";
  ASSERT_EQ(
      runGridifs("render " + quote(project.string()) + " --mode volume -o " + quote(a.string()) + kSmall).exitCode, 0);
  ASSERT_EQ(
      runGridifs("render " + quote(project.string()) + " --mode volume --threads 1 -o " + quote(b.string()) + kSmall)
          .exitCode,
      0);
  const Image ia = readImage(a), ib = readImage(b);
  ASSERT_EQ(ia.names, (std::vector<std::string>{"R", "G", "B", "A", "Z"}));
  EXPECT_EQ(ia.pixels, ib.pixels);
  const Project p = loadProject(project);
  int hits = 0;
  for (std::size_t i = 0; i < ia.pixels.size() / 5; ++i) {
    const float alpha = ia.pixels[5 * i + 3], z = ia.pixels[5 * i + 4];
    if (alpha == 0.0f) {
      EXPECT_EQ(z, 1e10f);
      continue;
    }
    ++hits;
    // Inside the cube X seen from the camera's distance.
    EXPECT_GT(z, p.camera.distance - 1.8);
    EXPECT_LT(z, p.camera.distance + 1.8);
  }
  EXPECT_GT(hits, 100);
}

TEST(VolumeRenderCli, BadInputExitsTwoNamingTheProblemAndWritesNothing) {
  ScratchDir dir("volume-render-cli");
  const fs::path out = dir.path / "out.png";
  const auto expectRefused = [&](const fs::path& project, const std::string& options, const std::string& needle) {
    const CommandResult r =
        runGridifs("render " + quote(project.string()) + " --mode volume -o " + quote(out.string()) + " -q" + options);
    EXPECT_EQ(r.exitCode, 2) << options << ": " << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(out));
  };
  expectRefused(cloudCopy(dir, R"({"display": "glow"})"), "", "render.volume.display");
  expectRefused(cloudCopy(dir, R"({"resolution": 4096})"), "", "render.volume.resolution");
  expectRefused(cloudCopy(dir, R"({"transfer": [{"density": 0.5, "opacity": 1}, {"density": 0.1, "opacity": 1}]})"), "",
                "render.volume.transfer[1].density");
  expectRefused(cloudCopy(dir, R"({"transfer": [{"density": 0, "color": [1, 0], "opacity": 1}]})"), "",
                "render.volume.transfer[0].color");
  expectRefused(cloudCopy(dir), " --resolution 100000", "--resolution");
  expectRefused(cloudCopy(dir), " --resolution 64 --frames 0:3", "--frames");
  const fs::path tif = dir.path / "out.tif";
  const CommandResult r =
      runGridifs("render " + quote(cloudCopy(dir).string()) + " --mode volume -o " + quote(tif.string()));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_FALSE(fs::exists(tif));
}

}  // namespace
}  // namespace gridifs
