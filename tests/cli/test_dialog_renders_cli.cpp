// File › Render animation… writes what `gridifs render` writes: both go through core's frame step
// (job/frame_output.h), so for every display mode and output format the dialog's frame
// (renderAnimationFrame, what its worker thread runs) equals the command line's file byte for byte,
// the EXR's compositing channels and camera matrices included. A project with median functions and
// an animated camera with motion blur (Draves & Reckase 2003, §9) are among the scenes.
#include <gtest/gtest.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>
#include <filesystem>
#include <string>

#include "cli/run_command.h"
#include "io/project_io.h"
#include "job/animation_frames.h"

namespace {

namespace fs = std::filesystem;
using gridifs::test_support::quote;
using gridifs::test_support::runGridifs;
using gridifs::test_support::slurp;

struct DialogScene {
  std::string asset;  // under assets/
  std::string mode;   // zbuffer, flame or shaded
  std::string extension;
  long frame = 0;
  int motionBlur = 1;
};

std::string sceneName(const DialogScene& s) {
  std::string name = fs::path(s.asset).stem().string() + "_" + s.mode + "_" + s.extension;
  if (s.motionBlur > 1) name += "_blur" + std::to_string(s.motionBlur);
  return name;
}

class DialogRendersTheCommandLinesFile : public ::testing::TestWithParam<DialogScene> {};

TEST_P(DialogRendersTheCommandLinesFile, ByteForByte) {
  const DialogScene& scene = GetParam();
  const fs::path asset = fs::path(GRIDIFS_ASSETS) / scene.asset;
  const fs::path dir =
      fs::temp_directory_path() / ("gridifs-dialog-cli-" + std::to_string(::getpid()) + "-" + sceneName(scene));
  fs::remove_all(dir);
  fs::create_directories(dir);
  // What the dialog does to the document's project: its size, samples (quality off), motion blur.
  gridifs::Project project = gridifs::loadProject(asset);
  project.render.width = 64;
  project.render.height = 48;
  project.render.samples = 60000;
  project.render.quality.reset();
  ASSERT_TRUE(gridifs::parseDisplayMode(scene.mode, project.render.mode));
  gridifs::AnimationSettings animation = project.animation.value_or(gridifs::AnimationSettings{});
  animation.motion_blur = scene.motionBlur;
  project.animation = animation;
  const fs::path dialog = dir / ("dialog." + scene.extension);
  gridifs::renderAnimationFrame(project, scene.frame, dialog, 2, asset.parent_path(), asset.filename().string(), {});

  const std::string frames = std::to_string(scene.frame) + ":" + std::to_string(scene.frame);
  const auto cli = runGridifs("render " + quote(asset.string()) + " -o " +
                              quote((dir / ("cli_%d." + scene.extension)).string()) + " --frames " + frames +
                              " --mode " + scene.mode + " --width 64 --height 48 --samples 60000 --motion-blur " +
                              std::to_string(scene.motionBlur) + " --threads 2 -q");
  ASSERT_EQ(cli.exitCode, 0) << cli.err;
  const std::string cliBytes = slurp(dir / ("cli_" + std::to_string(scene.frame) + "." + scene.extension));
  const std::string dialogBytes = slurp(dialog);
  ASSERT_GT(dialogBytes.size(), 100u);
  EXPECT_TRUE(dialogBytes == cliBytes) << sceneName(scene) << ": the dialog's file (" << dialogBytes.size()
                                       << " bytes) differs from the command line's (" << cliBytes.size() << " bytes)";

  // The EXR carries what a compositor needs, from either path: alpha and depth in every mode.
  if (scene.extension == "exr") {
    auto in = OIIO::ImageInput::open(dialog.string());
    ASSERT_TRUE(in);
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(spec.alpha_channel, 3);
    EXPECT_TRUE(spec.find_attribute("worldToCamera")) << "no camera matrices";
    const int channels = scene.mode == "shaded" ? 13 : scene.mode == "zbuffer" ? 8 : 4;
    EXPECT_EQ(spec.nchannels, channels);
    EXPECT_EQ(spec.z_channel, scene.mode == "flame" ? -1 : 4);
  }
  fs::remove_all(dir);
}

std::vector<DialogScene> dialogScenes() {
  std::vector<DialogScene> scenes;
  for (const char* mode : {"zbuffer", "flame", "shaded"})
    for (const char* extension : {"png", "exr", "tif"}) scenes.push_back({"default.gridifs", mode, extension});
  // Median functions: the points of the project's density volume (Sokolov & Gentil), from the
  // obj files beside it.
  scenes.push_back({"volumes/rotated_median.gridifs", "zbuffer", "exr"});
  scenes.push_back({"volumes/rotated_median.gridifs", "flame", "png"});
  // An animated camera (camera.yaw's track is kept): each time sample sees through its own camera.
  scenes.push_back({"animation/breathing_twist.gridifs", "flame", "exr", 12, 3});
  scenes.push_back({"animation/breathing_twist.gridifs", "zbuffer", "exr", 12, 3});
  return scenes;
}

INSTANTIATE_TEST_SUITE_P(EveryModeAndFormat, DialogRendersTheCommandLinesFile, ::testing::ValuesIn(dialogScenes()),
                         [](const ::testing::TestParamInfo<DialogScene>& info) { return sceneName(info.param); });

}  // namespace
