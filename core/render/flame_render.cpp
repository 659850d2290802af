#include "render/flame_render.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/atomic_file.h"
#include "base/color_space.h"
#include "base/errors.h"
#include "base/text_format.h"
#include "render/image_file.h"

namespace gridifs {

double flamePixelsPerUnit(const Camera& camera, int outputHeight) {
  // A panoramic camera: the pixels per radian, seen at the target's distance.
  if (camera.panoramic()) return outputHeight / (camera.fov * M_PI / 360.0) / (2.0 * camera.distance);
  const double halfHeight = camera.distance * std::tan(camera.fov * M_PI / 360.0);
  return halfHeight > 0.0 ? outputHeight / (2.0 * halfHeight) : 1.0;
}

int flameGutter(const FlameSettings& settings) {
  // flam3: the DE reaches ceil(radius) output pixels, the spatial filter half its width.
  const int de = settings.estimator_radius > 0.0 ? int(std::ceil(settings.estimator_radius)) : 0;
  const int filter = int(std::ceil(1.5 * settings.filter_radius)) + 1;
  return de + filter;
}

namespace {
/// The gutter actually used for `camera` (0 when widening the view would exceed 170°, and for
/// panoramic and stereo cameras).
int usableGutter(const Camera& camera, int outputHeight, const FlameSettings& settings) {
  // A wider view would move a dome's circle and the stereo eyes' edges: no gutter there.
  if (camera.panoramic() || camera.stereo) return 0;
  const int g = flameGutter(settings);
  const double halfTan = std::tan(camera.fov * M_PI / 360.0) * double(outputHeight + 2 * g) / outputHeight;
  return std::atan(halfTan) * 360.0 / M_PI <= 170.0 ? g : 0;
}
}  // namespace

RenderJob flameRenderJob(const RenderJob& outputJob, const FlameSettings& settings,
                         std::shared_ptr<const Palette> palette, bool gutter) {
  RenderJob job = outputJob;
  const int ss = std::max(1, settings.supersample);
  const int g = gutter ? usableGutter(outputJob.camera, outputJob.height, settings) : 0;
  // The same pixels per unit on a larger image: widen the (vertical) field of view; OrbitCamera's
  // orthographic extent follows the same tan(fov/2), and the width follows the aspect ratio.
  if (g > 0) {
    const double halfTan =
        std::tan(outputJob.camera.fov * M_PI / 360.0) * double(outputJob.height + 2 * g) / outputJob.height;
    job.camera.fov = std::atan(halfTan) * 360.0 / M_PI;
    // The shift is in frame heights: the same slide is a smaller part of the taller frame.
    const double taller = double(outputJob.height + 2 * g) / outputJob.height;
    job.camera.shift_x /= taller;
    job.camera.shift_y /= taller;
  }
  // Draves & Reckase 2003, §8: supersampling = more histogram buckets for the same number of iterations.
  job.width = (outputJob.width + 2 * g) * ss;
  job.height = (outputJob.height + 2 * g) * ss;
  job.accumulateColor = true;
  job.palette = std::move(palette);  // Draves & Reckase 2003, §5: the palette color at c, per sample
  return job;
}

RenderJob flameRenderJob(const Project& project, std::shared_ptr<const Palette> palette, int threads) {
  return flameRenderJob(RenderJob::fromProject(project, threads), project.render.flame, std::move(palette));
}

FlameHistogram flameHistogramFromSnapshot(const RenderImage& snapshot, const Palette* meanCPalette) {
  const std::size_t n = std::size_t(snapshot.width) * std::size_t(snapshot.height);
  if (snapshot.colorSums.size() != n * 4 || snapshot.density.size() != n)
    throw std::invalid_argument("the renderer snapshot has no flame color sums (accumulateColor was off)");
  FlameHistogram h(snapshot.width, snapshot.height);
  for (std::size_t i = 0; i < n; ++i) {
    const float hits = float(snapshot.density[i]);
    float* b = &h.buckets[i * 4];
    b[3] = hits;
    if (hits <= 0.f) continue;
    const float* s = &snapshot.colorSums[i * 4];
    if (meanCPalette) {
      const Rgb c = meanCPalette->lookup(s[3] / hits);
      b[0] = c.r * hits, b[1] = c.g * hits, b[2] = c.b * hits;
    } else {
      b[0] = s[0], b[1] = s[1], b[2] = s[2];
    }
  }
  return h;
}

FlameImage developFlameSnapshot(const RenderImage& snapshot, const FlameSettings& settings, const Camera& camera,
                                int outputWidth, int outputHeight, const Vec3& background, bool transparent,
                                int threads, const Palette* meanCPalette) {
  const int ss = std::max(1, settings.supersample);
  // The gutter is whatever the job had (flameRenderJob with or without one, any settings).
  const int g = snapshot.width % ss == 0 ? (snapshot.width / ss - outputWidth) / 2 : -1;
  if (g < 0 || snapshot.width != (outputWidth + 2 * g) * ss || snapshot.height != (outputHeight + 2 * g) * ss)
    throw std::invalid_argument(
        "the renderer snapshot does not have the size of the flame job (output + gutter, "
        "times the supersampling)");
  const FlameHistogram histogram = flameHistogramFromSnapshot(snapshot, meanCPalette);
  const FlameImage full = developFlame(histogram, settings, background, transparent,
                                       double(std::max<std::int64_t>(1, snapshot.stats.samples)),
                                       flamePixelsPerUnit(camera, outputHeight) * settings.density_unit, threads);
  if (g == 0) return full;
  FlameImage image;
  image.width = outputWidth;
  image.height = outputHeight;
  image.rgba.resize(std::size_t(outputWidth) * std::size_t(outputHeight) * 4);
  for (int y = 0; y < outputHeight; ++y)
    std::copy_n(full.pixel(g, y + g), std::size_t(outputWidth) * 4, &image.rgba[std::size_t(y) * outputWidth * 4]);
  return image;
}

void flameImageToRgba8(const FlameImage& image, std::vector<std::uint8_t>& out) {
  out.resize(image.rgba.size());
  for (std::size_t i = 0; i < image.rgba.size(); ++i)
    out[i] = std::uint8_t(std::lround(std::clamp(image.rgba[i], 0.0f, 1.0f) * 255.0f));
}

void writeFlameImage(const FlameImage& image, const std::filesystem::path& file, int bitDepth, bool withAlpha,
                     const Camera* camera) {
  namespace fs = std::filesystem;
  const std::string ext = lowerExtension(file);
  const bool exr = ext == "exr";
  if (!exr && ext != "png" && ext != "tif" && ext != "tiff")
    throw IoError("cannot write " + file.string() + ": use a .png, .tif or .exr file name");
  ImageFileLayout layout;
  if (exr)
    layout.stored = bitDepth == 32 ? StoredSample::Float : StoredSample::Half;
  else if (bitDepth == 16)
    layout.stored = StoredSample::UInt16;
  else if (bitDepth == 8)
    layout.stored = StoredSample::UInt8;
  else
    throw IoError("cannot write " + file.string() + ": PNG and TIFF take 8 or 16 bits per channel");
  layout.width = image.width;
  layout.height = image.height;
  if (exr && camera) {
    const ExrCameraMatrices matrices = exrCameraMatrices(OrbitCamera(*camera, image.width, image.height));
    layout.worldToCamera = matrices.worldToCamera;
    layout.worldToNDC = matrices.worldToNDC;
  }
  layout.channels = withAlpha ? std::vector<std::string>{"R", "G", "B", "A"} : std::vector<std::string>{"R", "G", "B"};
  if (withAlpha) layout.alphaChannel = 3;
  std::vector<float> pixels;
  const float* data = image.rgba.data();
  if (exr) {
    // The tone-mapped colors are display (sRGB-encoded) values; EXR holds scene-linear light,
    // like the z-buffer EXR of `gridifs render`. Convert the unpremultiplied color, then
    // premultiply again so that compositing over a linear background matches the PNG.
    pixels.resize(image.rgba.size());
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
      const float a = withAlpha ? image.rgba[i + 3] : 1.0f;
      for (int c = 0; c < 3; ++c) {
        const float straight = a > 0.0f ? std::min(1.0f, image.rgba[i + c] / a) : 0.0f;
        pixels[i + c] = srgbToLinear(straight) * a;
      }
      pixels[i + 3] = a;
    }
    data = pixels.data();
  }
  if (!withAlpha) {
    std::vector<float> rgb(std::size_t(image.width) * std::size_t(image.height) * 3);
    for (std::size_t i = 0, n = rgb.size() / 3; i < n; ++i)
      for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = data[i * 4 + c];
    pixels = std::move(rgb);
    data = pixels.data();
  }
  writeImageFile(file, layout, data);
}

}  // namespace gridifs
