#include "job/animation_frames.h"

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
#include "render/motion_blur.h"
#include "render/shaded_image.h"

namespace gridifs {
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
  const AnimationSettings animation = animated.animation.value_or(AnimationSettings{});
  // The same preparation as `gridifs render --time`: condensation sets read from files beside
  // the project, the palette and the lights of the display mode (job/prepared_render.h).
  RenderJobOptions options;
  options.time = double(frame) / animation.fps;
  options.threads = threads;
  options.folder = projectFolder;
  const PreparedRender render = prepareRender(animated, options);
  const Project& project = render.project;
  const RenderJob& job = render.output;
  const std::string description = "GridIFS animation frame " + std::to_string(frame) +
                                  " (t = " + std::to_string(project.time) + " s), " + std::to_string(job.samples) +
                                  " samples";
  // Draves & Reckase 2003, §9, motion blur as `gridifs render --motion-blur N --motion-fade F`:
  // the frame's samples shared among N times spread over the shutter, each with its own seed,
  // summed into one histogram; with a fade the earlier times are drawn dimmer.
  const int blur = project.render.mode == DisplayMode::Shaded ? 1 : std::clamp(animation.motion_blur, 1, 256);
  const std::vector<double> weights = motionBlurWeights(blur, animation.motion_fade);
  const double shutter = animation.shutter / animation.fps;
  TimeSampleSum sum;
  for (int i = 0; i < blur; ++i) {
    auto report = [&](const RenderStats& s) { return !progress || progress(std::min(1.0, (i + s.progress()) / blur)); };
    if (blur == 1) {
      addTimeSample(sum, renderToCompletion(render.ifs, render.job, render.display, report), 1.0);
      break;
    }
    RenderJobOptions at = options;
    at.time = *options.time + shutter * ((i + 0.5) / blur - 0.5);
    at.samples = job.samples / blur + (i < job.samples % blur ? 1 : 0);
    at.seed = job.seed + std::uint64_t(i);
    const PreparedRender sample = prepareRender(animated, at);
    addTimeSample(sum, renderToCompletion(sample.ifs, sample.job, sample.display, report), weights[std::size_t(i)]);
  }
  const RenderImage image = finishTimeSamples(std::move(sum));
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

}  // namespace gridifs
