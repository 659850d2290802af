#include "job/animation_frames.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <memory>
#include <vector>

#include "base/text_format.h"
#include "job/frame_output.h"
#include "render/motion_blur.h"

namespace gridifs {

std::optional<std::string> checkFramePattern(const std::string& pattern) {
  if (pattern.empty()) return "the output name is empty";
  if (const auto problem = framePatternProblem(pattern)) return "the output name " + *problem;
  const std::string ext = lowerExtension(std::filesystem::path(pattern));
  if (ext != "png" && ext != "tif" && ext != "tiff" && ext != "exr") return "frames are written as .png, .tif or .exr";
  return std::nullopt;
}

void renderAnimationFrame(const Project& animated, long frame, const std::filesystem::path& out, int threads,
                          const std::filesystem::path& projectFolder, const std::string& source,
                          const std::function<bool(double)>& progress) {
  const AnimationSettings animation = animated.animation.value_or(AnimationSettings{});
  // `gridifs render --time f/fps` in every step (job/frame_output.h): condensation sets read from
  // files beside the project, the palette and lights of the display mode, the time samples of
  // motion blur (Draves & Reckase 2003, §9), and every output the mode writes.
  RenderJobOptions options;
  options.time = double(frame) / animation.fps;
  options.threads = threads;
  options.folder = projectFolder;
  // The shaded display's shadow maps and depth of field are one chaos game: no time samples.
  const bool shaded = animated.render.mode == DisplayMode::Shaded;
  const int blur = shaded ? 1 : std::clamp(animation.motion_blur, 1, kMaxMotionBlurSamples);
  const std::vector<TimeSample> samples =
      prepareTimeSamples(animated, options, blur, animation.shutter / animation.fps);
  const RenderImage image = renderTimeSamples(samples, animation.motion_fade, progress);
  const PreparedRender& first = samples.front().render;
  FrameOutput output;
  output.file = out;
  output.source = source;
  writeFrame(image, first.project, first.output, first.job, output);
}

}  // namespace gridifs
