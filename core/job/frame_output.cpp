#include "job/frame_output.h"

#include <algorithm>

#include "base/color_space.h"
#include "base/text_format.h"
#include "render/camera.h"
#include "render/flame_render.h"
#include "render/image_file.h"
#include "render/motion_blur.h"
#include "render/shaded_image.h"

namespace gridifs {

std::int64_t timeSampleShare(std::int64_t samples, std::int64_t i, std::int64_t count) {
  return samples / count + (i < samples % count ? 1 : 0);
}

std::vector<TimeSample> prepareTimeSamples(const Project& project, const RenderJobOptions& options, int blur,
                                           double shutter) {
  blur = std::max(1, blur);
  std::vector<TimeSample> samples;
  samples.reserve(std::size_t(blur));
  const double time = options.time.value_or(project.time);
  for (int i = 0; i < blur; ++i) {
    RenderJobOptions at = options;
    // Draves & Reckase 2003, §9: the times spread over the shutter, each drawn with its own
    // camera and tracks, so that a moving camera blurs as a moving object does.
    if (blur > 1) at.time = time + shutter * ((i + 0.5) / blur - 0.5);
    TimeSample sample{prepareRender(project, at), at.time.value_or(project.time)};
    sample.render.job.samples = timeSampleShare(sample.render.job.samples, i, blur);
    sample.render.job.seed += std::uint64_t(i);
    samples.push_back(std::move(sample));
  }
  return samples;
}

RenderImage mergeTimeSamples(const std::vector<Accumulation>& samples, const DisplaySettings& display,
                             double motionFade) {
  const std::vector<double> weights = motionBlurWeights(int(samples.size()), motionFade);
  TimeSampleSum sum;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    RenderImage sample;
    toRenderImage(samples[i], display, sample);
    sample.stats.budget = sample.stats.samples;
    addTimeSample(sum, std::move(sample), weights[i]);
  }
  return finishTimeSamples(std::move(sum));
}

RenderImage renderTimeSamples(const std::vector<TimeSample>& samples, double motionFade,
                              const std::function<bool(double)>& progress) {
  std::vector<Accumulation> sums;
  const double count = double(samples.size());
  for (const TimeSample& sample : samples) {
    const double before = double(sums.size());
    sums.push_back(accumulateToCompletion(sample.render.ifs, sample.render.job, [&](const RenderStats& s) {
      return !progress || progress(std::min(1.0, (before + s.progress()) / count));
    }));
  }
  return mergeTimeSamples(sums, samples.front().render.display, motionFade);
}

int frameBitDepth(const FrameOutput& out) {
  if (out.bitDepth != 0) return out.bitDepth;
  return lowerExtension(out.file) == "exr" ? 32 : 8;
}

namespace {

std::string frameDescription(const char* what, const FrameOutput& out, const RenderJob& job) {
  return std::string(what) + (out.source.empty() ? std::string("untitled") : out.source) + ", " +
         std::to_string(job.samples) + " samples, seed " + std::to_string(job.seed);
}

/// PNG and TIFF: 8-bit RGB, the first three channels of an RGBA8 picture over the background.
void writeRgb8(const FrameOutput& out, int width, int height, const std::vector<std::uint8_t>& rgba,
               const std::string& description) {
  const std::size_t n = std::size_t(width) * std::size_t(height);
  std::vector<std::uint8_t> rgb(n * 3);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = rgba[i * 4 + c];
  ImageFileLayout layout;
  layout.width = width;
  layout.height = height;
  layout.channels = {"R", "G", "B"};
  layout.description = description;
  writeImageFile(out.file, layout, rgb.data());
}

/// The compositing layout of an EXR: R G B A Z, then `extra`, then P, with the camera's matrices.
ImageFileLayout exrLayout(int width, int height, const OrbitCamera& camera, std::vector<std::string> extra) {
  ImageFileLayout layout;
  layout.width = width;
  layout.height = height;
  layout.channels = {"R", "G", "B", "A", "Z"};
  layout.channels.insert(layout.channels.end(), extra.begin(), extra.end());
  for (const char* p : {"P.x", "P.y", "P.z"}) layout.channels.push_back(p);
  layout.alphaChannel = 3;
  layout.zChannel = 4;
  layout.stored = StoredSample::Float;
  const ExrCameraMatrices matrices = exrCameraMatrices(camera);
  layout.worldToCamera = matrices.worldToCamera;
  layout.worldToNDC = matrices.worldToNDC;
  return layout;
}

/// P: the world position pixel `i`'s centre sees at its depth (the last three channels of `px`).
void writeWorldPosition(const OrbitCamera& camera, int width, std::size_t i, float depth, float* px) {
  const glm::dvec3 p = pixelWorldPosition(camera, int(i % std::size_t(width)), int(i / std::size_t(width)), depth);
  for (int c = 0; c < 3; ++c) px[c] = float(p[c]);
}

void writeZBuffer(const RenderImage& image, const RenderJob& output, const FrameOutput& out) {
  const std::size_t n = std::size_t(image.width) * std::size_t(image.height);
  const std::string description = frameDescription("GridIFS render of ", out, output);
  if (lowerExtension(out.file) != "exr") return writeRgb8(out, image.width, image.height, image.rgba, description);
  const OrbitCamera camera(output.camera, image.width, image.height);
  ImageFileLayout layout = exrLayout(image.width, image.height, camera, {});
  layout.description = description;
  const std::size_t k = layout.channels.size();
  std::vector<float> pixels(n * k, 0.0f);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* rgba = &image.rgba[i * 4];
    float* px = &pixels[i * k];
    const bool hit = rgba[3] != 0;
    for (int c = 0; c < 3; ++c) px[c] = hit ? srgbToLinear(rgba[c] / 255.0f) : 0.0f;
    px[3] = hit ? 1.0f : 0.0f;
    px[4] = hit ? image.depth[i] : kEmptyPixelDepth;
    if (hit) writeWorldPosition(camera, image.width, i, image.depth[i], px + 5);
  }
  writeImageFile(out.file, layout, pixels.data());
}

void writeShaded(const RenderImage& image, const Project& project, const RenderJob& rendered, const FrameOutput& out) {
  ShadedImage shaded;
  developShaded(image, project.render.shading, project.camera, project.render.background, rendered.threads, shaded);
  const std::size_t n = std::size_t(shaded.width) * std::size_t(shaded.height);
  const std::string description = frameDescription("GridIFS shaded render of ", out, rendered);
  if (lowerExtension(out.file) != "exr") return writeRgb8(out, shaded.width, shaded.height, shaded.rgba, description);
  const OrbitCamera camera(project.camera, shaded.width, shaded.height);
  ImageFileLayout layout = exrLayout(shaded.width, shaded.height, camera, {"N.x", "N.y", "N.z", "AO", "shadow"});
  layout.description = description;
  const std::size_t k = layout.channels.size();
  std::vector<float> pixels(n * k, 0.0f);
  for (std::size_t i = 0; i < n; ++i) {
    float* px = &pixels[i * k];
    for (std::size_t c = 0; c < 4; ++c) px[c] = shaded.linear[i * 4 + c];
    const bool hit = shaded.rgba[i * 4 + 3] != 0;
    px[4] = hit ? image.depth[i] : kEmptyPixelDepth;
    for (std::size_t c = 0; c < 3; ++c) px[5 + c] = shaded.normals[i * 3 + c];
    px[8] = shaded.occlusion[i];
    px[9] = shaded.shadow[i];
    if (hit) writeWorldPosition(camera, shaded.width, i, image.depth[i], px + 10);
  }
  writeImageFile(out.file, layout, pixels.data());
}

void writeFlame(const RenderImage& image, const Project& project, const RenderJob& output, const RenderJob& rendered,
                const FrameOutput& out) {
  // Draves & Reckase 2003, §4–8: the supersampled histogram tone mapped and filtered down to the
  // output's pixels; an EXR keeps its coverage as alpha for compositing.
  const bool alpha = lowerExtension(out.file) == "exr" || out.transparent;
  const FlameImage flame = developFlameSnapshot(image, project.render.flame, project.camera, output.width,
                                                output.height, project.render.background, alpha, rendered.threads);
  writeFlameImage(flame, out.file, frameBitDepth(out), alpha, &project.camera);
}

}  // namespace

void writeFrame(const RenderImage& image, const Project& project, const RenderJob& output, const RenderJob& rendered,
                const FrameOutput& out) {
  switch (project.render.mode) {
    case DisplayMode::Flame:
      writeFlame(image, project, output, rendered, out);
      return;
    case DisplayMode::Shaded:
      writeShaded(image, project, rendered, out);
      return;
    default:
      writeZBuffer(image, output, out);
      return;
  }
}

}  // namespace gridifs
