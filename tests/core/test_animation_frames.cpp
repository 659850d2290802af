// The numbered file names of File › Render animation (core/job/animation_frames.h): checked without a
// window, like the window placement rules.
#include "job/animation_frames.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "base/text_format.h"
#include "io/project_io.h"

using gridifs::checkFramePattern;
using gridifs::frameFileName;

TEST(AnimationFrames, PatternsNeedOneFrameNumberAndAnImageExtension) {
  EXPECT_FALSE(checkFramePattern("frames/shot_%04d.png"));
  EXPECT_FALSE(checkFramePattern("shot_%d.tif"));
  EXPECT_FALSE(checkFramePattern("100%%_%03d.EXR"));
  EXPECT_TRUE(checkFramePattern(""));
  EXPECT_TRUE(checkFramePattern("shot.png"));            // no frame number
  EXPECT_TRUE(checkFramePattern("shot_%04d_%04d.png"));  // two
  EXPECT_TRUE(checkFramePattern("shot_%s.png"));         // not an integer
  EXPECT_TRUE(checkFramePattern("shot_%0100d.png"));     // an absurd width
  EXPECT_TRUE(checkFramePattern("shot_%04d.jpg"));       // not a frame format
  EXPECT_NE(checkFramePattern("shot.png")->find("%04d"), std::string::npos);
}

TEST(AnimationFrames, FrameNumbersAreFormattedIntoThePattern) {
  EXPECT_EQ(frameFileName("frames/shot_%04d.png", 7), "frames/shot_0007.png");
  EXPECT_EQ(frameFileName("shot_%d.tif", 123456), "shot_123456.tif");
  EXPECT_EQ(frameFileName("100%%_%03d.exr", -2), "100%_-02.exr");
}

// File › Render animation… with motion blur and a fade renders the frame the command line does
// (`gridifs render --frames F:F --motion-blur N --motion-fade F`): the same time samples, seeds
// and weights (Draves & Reckase 2003, §9, directional motion blur).
TEST(AnimationFrames, MotionBlurredFrameIsTheCommandLinesFrame) {
  namespace fs = std::filesystem;
  gridifs::Project p = gridifs::loadProject(std::string(GRIDIFS_ASSETS) + "/animation/breathing_twist.gridifs");
  p.render.width = 64;
  p.render.height = 48;
  p.render.samples = 200000;
  p.render.mode = gridifs::DisplayMode::Flame;
  gridifs::AnimationSettings a = p.animation.value_or(gridifs::AnimationSettings{});
  a.motion_blur = 3;
  a.motion_fade = 2.0;
  a.shutter = 1.0;
  p.animation = a;
  const fs::path dir = fs::temp_directory_path() / ("gridifs-frames-blur-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  gridifs::saveProject(p, dir / "blur.gridifs");
  gridifs::renderAnimationFrame(p, 12, dir / "dialog.png", 2, dir, "blur.gridifs", {});
  const std::string cli = std::string(GRIDIFS_EXE) + " render '" + (dir / "blur.gridifs").string() + "' -o '" +
                          (dir / "cli_%02d.png").string() + "' --frames 12:12 --threads 2 -q 2>/dev/null";
  ASSERT_EQ(std::system(cli.c_str()), 0);
  auto slurp = [](const fs::path& f) {
    std::ifstream in(f, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  ASSERT_FALSE(slurp(dir / "dialog.png").empty());
  EXPECT_EQ(slurp(dir / "dialog.png"), slurp(dir / "cli_12.png"));
  fs::remove_all(dir);
}
