#include "ui/animation_frames.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <memory>
#include <vector>

#include "base/color_space.h"
#include "base/errors.h"
#include "base/text_format.h"
#include "edit/document.h"
#include "flame/palette.h"
#include "job/prepared_render.h"
#include "model/project_time.h"
#include "render/compiled_ifs.h"
#include "render/flame_render.h"
#include "render/image_file.h"
#include "render/shaded_image.h"

namespace gridifs::ui {
namespace {

/// Writes 8-bit display colour (4 per pixel, over the background) as RGB, or linear float RGB
/// for EXR.
void writeDisplayImage(const std::vector<std::uint8_t>& rgba, int width, int height, const std::filesystem::path& out,
                       const std::string& description) {
  const std::size_t n = std::size_t(width) * std::size_t(height);
  ImageFileLayout layout;
  layout.width = width;
  layout.height = height;
  layout.channels = {"R", "G", "B"};
  layout.description = description;
  if (lowerExtension(out) == "exr") {
    layout.stored = StoredSample::Float;
    std::vector<float> pixels(n * 3);
    for (std::size_t i = 0; i < n * 3; ++i) pixels[i] = srgbToLinear(float(rgba[i / 3 * 4 + i % 3]) / 255.0f);
    writeImageFile(out, layout, pixels.data());
  } else {
    std::vector<std::uint8_t> pixels(n * 3);
    for (std::size_t i = 0; i < n * 3; ++i) pixels[i] = rgba[i / 3 * 4 + i % 3];
    writeImageFile(out, layout, pixels.data());
  }
}

}  // namespace

std::optional<std::string> checkFramePattern(const std::string& pattern) {
  if (pattern.empty()) return "the output name is empty";
  if (const auto problem = framePatternProblem(pattern)) return "the output name " + *problem;
  const std::string ext = lowerExtension(std::filesystem::path(pattern));
  if (ext != "png" && ext != "tif" && ext != "tiff" && ext != "exr") return "frames are written as .png, .tif or .exr";
  return std::nullopt;
}

void renderAnimationFrame(const Project& animated, long frame, const std::filesystem::path& out, int threads,
                          const std::filesystem::path& projectFolder, const std::function<bool(double)>& progress) {
  const double fps = animated.animation.value_or(AnimationSettings{}).fps;
  // The same preparation as `gridifs render --time`: condensation sets read from files beside
  // the project, the palette and the lights of the display mode (job/prepared_render.h).
  RenderJobOptions options;
  options.time = double(frame) / fps;
  options.threads = threads;
  options.folder = projectFolder;
  const PreparedRender render = prepareRender(animated, options);
  const Project& project = render.project;
  const RenderJob& job = render.output;
  auto report = [&](const RenderStats& s) { return !progress || progress(std::min(1.0, s.progress())); };
  const std::string description = "GridIFS animation frame " + std::to_string(frame) +
                                  " (t = " + std::to_string(project.time) + " s), " + std::to_string(job.samples) +
                                  " samples";
  const RenderImage image = renderToCompletion(render.ifs, render.job, render.display, report);
  switch (project.render.mode) {
    case DisplayMode::Flame: {
      // Draves & Reckase 2003, §4–8: supersampled palette colours, log-density tone mapping.
      const FlameImage flame = developFlameSnapshot(image, project.render.flame, project.camera, job.width, job.height,
                                                    project.render.background, false, job.threads);
      writeFlameImage(flame, out, lowerExtension(out) == "exr" ? 32 : 8, false);
      return;
    }
    case DisplayMode::Shaded: {
      ShadedImage shaded;
      developShaded(image, project.render.shading, project.camera, project.render.background, job.threads, shaded);
      writeDisplayImage(shaded.rgba, shaded.width, shaded.height, out, description);
      return;
    }
    default:
      writeDisplayImage(image.rgba, image.width, image.height, out, description);
      return;
  }
}

}  // namespace gridifs::ui
