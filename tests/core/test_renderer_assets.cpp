// Every example project renders: a non-empty image with the attractor inside the frame.
#include <gtest/gtest.h>

#include <filesystem>

#include "io/project_io.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"

namespace gridifs {
namespace {

std::vector<std::filesystem::path> examples() {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(GRIDIFS_ASSETS, ec))
    if (entry.path().extension() == ".gridifs") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(RendererAssets, EveryExampleRendersInsideTheFrame) {
  const auto files = examples();
  if (files.empty()) GTEST_SKIP() << "no examples in " << GRIDIFS_ASSETS;
  for (const auto& file : files) {
    SCOPED_TRACE(file.filename().string());
    const Project project = loadProject(file);
    RenderJob job = RenderJob::fromProject(project, 2);
    // The project's aspect ratio at a small size.
    job.width = 160;
    job.height = std::max(1, int(160.0 * project.render.height / project.render.width));
    job.samples = 200'000;
    const RenderImage image = renderToCompletion(compileIfs(project), job, DisplaySettings::fromProject(project));
    EXPECT_EQ(image.stats.samples, job.samples);
    EXPECT_LT(image.stats.badFraction(), 0.01);
    EXPECT_GT(image.hitPixels, 200) << "the image is (nearly) empty";
    // Inside the frame: almost every point past the skip lands in the image...
    EXPECT_GT(double(image.stats.plotted) / double(image.stats.samples), 0.95);
    // ...and the picture does not run off the border: only a small part of the border is lit.
    int border = 0;
    for (int x = 0; x < image.width; ++x)
      border += image.density[x] > 0 || image.density[std::size_t(image.height - 1) * image.width + x] > 0;
    for (int y = 0; y < image.height; ++y)
      border += image.density[std::size_t(y) * image.width] > 0 ||
                image.density[std::size_t(y) * image.width + image.width - 1] > 0;
    EXPECT_LT(border, (image.width + image.height) / 10);
  }
}

}  // namespace
}  // namespace gridifs
