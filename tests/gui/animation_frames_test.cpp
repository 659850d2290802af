// The numbered file names of File › Render animation (ui/animation_frames.h): checked without a
// window, like the window placement rules.
#include "ui/animation_frames.h"

#include <gtest/gtest.h>

#include "base/text_format.h"

using gridifs::frameFileName;
using gridifs::ui::checkFramePattern;

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
