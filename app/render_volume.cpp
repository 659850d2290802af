#include "app/render_volume.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "app/cli.h"
#include "app/progress_bar.h"
#include "base/color_space.h"
#include "base/text_format.h"
#include "io/volume_render_io.h"
#include "render/camera.h"
#include "render/image_file.h"
#include "render/volume_raymarch.h"
#include "tone/palette.h"
#include "volume/measure_attractor.h"

namespace gridifs::cli {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// The flame palette colours the density where the functions share one colour (as in the preview).
std::vector<float> paletteOf(const Project& project, const std::filesystem::path& folder) {
  Palette palette;
  try {
    palette = resolvePalette(project.render.flame.palette, folder);
  } catch (const std::exception& e) {
    throw CliError(kBadInput, "render.flame.palette: " + std::string(e.what()));
  }
  std::vector<float> rgb;
  for (const Rgb& c : palette.colors) rgb.insert(rgb.end(), {c.r, c.g, c.b});
  return rgb;
}

void writeVolumeImage(const VolumeImage& image, const Camera& camera, const std::string& out,
                      const std::string& description) {
  const std::size_t n = std::size_t(image.width) * std::size_t(image.height);
  ImageFileLayout layout;
  layout.width = image.width;
  layout.height = image.height;
  layout.alphaChannel = 3;
  layout.description = description;
  std::vector<float> pixels;
  if (lowerExtension(out) == "exr") {
    // Scene-linear, premultiplied (OpenEXR's convention), with the depth of the opacity.
    layout.channels = {"R", "G", "B", "A", "Z"};
    layout.zChannel = 4;
    layout.stored = StoredSample::Float;
    const ExrCameraMatrices matrices = exrCameraMatrices(OrbitCamera(camera, image.width, image.height));
    layout.worldToCamera = matrices.worldToCamera;
    layout.worldToNDC = matrices.worldToNDC;
    pixels.resize(n * 5);
    for (std::size_t i = 0; i < n; ++i) {
      const float a = image.rgba[4 * i + 3];
      for (int c = 0; c < 3; ++c)
        pixels[5 * i + std::size_t(c)] = a > 0.0f ? srgbToLinear(image.rgba[4 * i + std::size_t(c)] / a) * a : 0.0f;
      pixels[5 * i + 3] = a;
      pixels[5 * i + 4] = image.depth[i] < kEmptyVolumeDepth ? image.depth[i] : kEmptyPixelDepth;
    }
  } else {
    // Premultiplied in memory; OpenImageIO stores PNG with straight alpha, as PNG requires.
    layout.channels = {"R", "G", "B", "A"};
    layout.stored = StoredSample::UInt8;
    pixels.resize(n * 4);
    for (std::size_t i = 0; i < 4 * n; ++i) pixels[i] = std::clamp(image.rgba[i], 0.0f, 1.0f);
  }
  try {
    writeImageFile(out, layout, pixels.data());
  } catch (const IoError& e) {
    throw CliError(kFailure, e.what());
  }
}

/// The options checked before the project is read.
void checkVolumeRenderOptions(const std::string& out, const RenderOverrides& overrides) {
  checkOutputPath(out, {"png", "exr"}, "a volume image");
  if (overrides.quality) throw CliError(kBadInput, "--quality applies to the chaos-game modes, not to --mode volume");
  if (overrides.device && *overrides.device == "gpu")
    throw CliError(kBadInput, "--mode volume renders on the CPU; leave out --device gpu");
}

}  // namespace

int runVolumeRender(const std::string& file, const std::string& out, const RenderOverrides& overrides,
                    std::optional<int> resolution, bool quiet) {
  checkVolumeRenderOptions(out, overrides);
  return runVolumeRenderOf(loadForVerb(file), file, out, overrides, resolution, quiet);
}

int runVolumeRenderOf(const Project& loaded, const std::string& file, const std::string& out,
                      const RenderOverrides& overrides, std::optional<int> resolution, bool quiet) {
  checkVolumeRenderOptions(out, overrides);
  const std::filesystem::path path(file);
  const Project project = projectForVerbAt(loaded, path, overrides.time);
  VolumeRenderSettings settings = project.render.volume.value_or(VolumeRenderSettings{});
  if (resolution) {
    if (*resolution < kMinVolumeResolution || *resolution > kMaxVolumeResolution)
      throw CliError(kBadInput, "--resolution must be between " + std::to_string(kMinVolumeResolution) + " and " +
                                    std::to_string(kMaxVolumeResolution) + ", not " + std::to_string(*resolution));
    settings.resolution = *resolution;
  }
  const int width = overrides.width.value_or(project.render.width),
            height = overrides.height.value_or(project.render.height);
  if (width < 1 || width > 16384 || height < 1 || height > 16384)
    throw CliError(kBadInput, "--width and --height must be between 1 and 16384");
  int threads = 0;
  if (overrides.threads) {
    if (*overrides.threads < 1 || *overrides.threads > limits::kMaxRenderThreads)
      throw CliError(kBadInput, "--threads must be between 1 and " + std::to_string(limits::kMaxRenderThreads));
    threads = *overrides.threads;
  }
  // The volume exactly as `gridifs volume` computes it, at render.volume.resolution.
  VolumeJob job;
  job.settings = project.volume.value_or(VolumeSettings{});
  job.settings.resolution = settings.resolution;
  if (overrides.samples) job.settings.samples = parseSamples(*overrides.samples, limits::kMaxRenderSamples);
  if (overrides.seed) job.settings.seed = *overrides.seed;
  job.threads = threads;
  job.projectFolder = path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  VolumeLook look = volumeLookOf(project);
  look.settings = settings;
  look.palette = paletteOf(project, job.projectFolder);
  const auto start = Clock::now();
  DensityVolume volume;
  {
    ProgressBar bar("volume", quiet);
    job.progress = [&](double done) { bar.fraction(done); };
    try {
      volume = computeDensityVolume(project, job);
    } catch (const ModelError& e) {
      throw CliError(kBadInput, file + ": " + e.what());
    }
    bar.finish();
  }
  if (volume.totalMass <= 0.0)
    throw CliError(kFailure, file + ": no point of the attractor fell inside X, so the volume is empty; " + out +
                                 " was not written");
  const double volumeSeconds = secondsSince(start);
  VolumeSource source;
  source.n = settings.resolution;
  source.density = std::move(volume.density);
  source.color = std::move(volume.color);
  const auto marchStart = Clock::now();
  VolumeImage image;
  try {
    image = renderVolumeImage(source, look, project.camera, width, height, threads);
  } catch (const ModelError& e) {
    throw CliError(kBadInput, file + ": " + e.what());
  }
  const double marchSeconds = secondsSince(marchStart);
  const std::string description = "GridIFS volume render of " + file + ", " + std::to_string(settings.resolution) +
                                  "^3 voxels, " + volume_render_io::volumeDisplayName(settings.display) + " display";
  writeVolumeImage(image, project.camera, out, description);
  if (!quiet)
    std::fprintf(stderr, "volume %d^3 in %.2f s, ray march %dx%d in %.2f s\n", settings.resolution, volumeSeconds,
                 width, height, marchSeconds);
  return kSuccess;
}

}  // namespace gridifs::cli
