// One path from a project to a render (job/prepared_render.h): condensation sets read from files
// beside the project, the project at a time, the display mode's job, and errors that name the
// JSON path of their cause.
#include <gtest/gtest.h>

#include <filesystem>

#include "io/project_io.h"
#include "job/prepared_render.h"

using namespace gridifs;
namespace fs = std::filesystem;

namespace {

const fs::path kVolumes = fs::path(GRIDIFS_ASSETS) / "volumes";

Project pineTrees() {
  Project p = loadProject(kVolumes / "pine_trees.gridifs");
  p.render.width = 64;
  p.render.height = 48;
  p.render.samples = 10'000;
  return p;
}

}  // namespace

TEST(PreparedRender, SetsReadFromFilesAreSampledBesideTheProject) {
  RenderJobOptions options;
  options.folder = kVolumes;
  options.setResolution = 32;
  const PreparedRender r = prepareRender(pineTrees(), options);
  ASSERT_TRUE(r.ifs);
  EXPECT_EQ(r.ifs->functions.size(), r.project.functions.size());
  EXPECT_EQ(r.output.width, 64);
  EXPECT_EQ(r.output.samples, 10'000);
}

TEST(PreparedRender, EachDisplayModeGetsItsJob) {
  RenderJobOptions options;
  options.folder = kVolumes;
  options.setResolution = 32;
  Project p = pineTrees();
  p.render.mode = DisplayMode::Flame;
  p.render.flame.supersample = 2;
  const PreparedRender flame = prepareRender(p, options);
  ASSERT_TRUE(flame.palette);
  EXPECT_GE(flame.job.width, 2 * 64) << "supersampled";
  EXPECT_EQ(flame.device, "auto");
  p.render.mode = DisplayMode::Shaded;
  const PreparedRender shaded = prepareRender(p, options);
  EXPECT_FALSE(shaded.palette);
  EXPECT_EQ(shaded.device, "cpu") << "shadow maps and depth of field are CPU chaos-game effects";
  p.render.mode = DisplayMode::ZBuffer;
  const PreparedRender zbuffer = prepareRender(p, options);
  EXPECT_EQ(zbuffer.job.width, 64);
  EXPECT_EQ(zbuffer.job.height, 48);
}

TEST(PreparedRender, TheProjectIsTakenAtTheAskedTime) {
  Project p = pineTrees();
  p.tracks["camera.yaw"].keys = {{0.0, 10.0}, {2.0, 50.0}};
  RenderJobOptions options;
  options.folder = kVolumes;
  options.setResolution = 32;
  options.time = 1.0;
  const PreparedRender r = prepareRender(p, options);
  EXPECT_DOUBLE_EQ(r.project.time, 1.0);
  EXPECT_NEAR(r.project.camera.yaw, 30.0, 1e-9);
}

TEST(PreparedRender, ErrorsNameTheJsonPath) {
  RenderJobOptions options;
  options.setResolution = 32;
  // A set file that is not beside the project.
  options.folder = fs::temp_directory_path();
  try {
    prepareRender(pineTrees(), options);
    FAIL() << "a missing mesh was sampled";
  } catch (const RenderJobError& e) {
    EXPECT_EQ(e.path().rfind("functions[1]", 0), 0u) << e.path();
    EXPECT_NE(std::string(e.what()).find("pine_tree.obj"), std::string::npos) << e.what();
  }
  options.folder = kVolumes;
  Project p = pineTrees();
  p.render.mode = DisplayMode::Flame;
  p.render.flame.palette = "file:no_such_palette.json";
  try {
    prepareRender(p, options);
    FAIL() << "a missing palette was read";
  } catch (const RenderJobError& e) {
    EXPECT_EQ(e.path(), "render.flame.palette");
  }
  // The preview keeps rendering with the default palette.
  options.preview = true;
  EXPECT_TRUE(prepareRender(p, options).palette);
  options.preview = false;
  p = pineTrees();
  options.samples = 0;
  try {
    prepareRender(p, options);
    FAIL() << "0 samples were accepted";
  } catch (const RenderJobError& e) {
    EXPECT_EQ(e.path(), "render.samples");
  }
}
