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
  const Project project = projectAtTime(animated, double(frame) / fps);
  const Document document(project);
  const std::shared_ptr<const CompiledIfs> ifs = compileIfs(document.project(), document.evaluation());
  RenderJob job = RenderJob::fromProject(project, threads);
  auto report = [&](const RenderStats& s) { return !progress || progress(std::min(1.0, s.progress())); };
  const std::string description = "GridIFS animation frame " + std::to_string(frame) +
                                  " (t = " + std::to_string(project.time) + " s), " + std::to_string(job.samples) +
                                  " samples";
  switch (project.render.mode) {
    case DisplayMode::Flame: {
      // Draves & Reckase 2003, §4–8: supersampled palette colours, log-density tone mapping.
      const FlameSettings& settings = project.render.flame;
      const auto palette = std::make_shared<const Palette>(resolvePalette(settings.palette, projectFolder));
      const RenderJob flameJob = flameRenderJob(job, settings, palette);
      const RenderImage image = renderToCompletion(ifs, flameJob, DisplaySettings::fromProject(project), report);
      const FlameImage flame = developFlameSnapshot(image, settings, project.camera, job.width, job.height,
                                                    project.render.background, false, job.threads);
      writeFlameImage(flame, out, lowerExtension(out) == "exr" ? 32 : 8, false);
      return;
    }
    case DisplayMode::Shaded: {
      const ShadingSettings& shading = project.render.shading;
      const RenderJob shadedJob = shadedRenderJob(job, shading, *ifs);
      const RenderImage image = renderToCompletion(ifs, shadedJob, shadedDisplaySettings(project), report);
      ShadedImage shaded;
      developShaded(image, shading, project.camera, project.render.background, job.threads, shaded);
      writeDisplayImage(shaded.rgba, shaded.width, shaded.height, out, description);
      return;
    }
    default: {
      const RenderImage image = renderToCompletion(ifs, job, DisplaySettings::fromProject(project), report);
      writeDisplayImage(image.rgba, image.width, image.height, out, description);
      return;
    }
  }
}

}  // namespace gridifs::ui
