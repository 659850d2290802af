#include "ui/views/volume_preview.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "base/system_memory.h"
#include "schema/palette_reference.h"
#include "tone/palette.h"
#include "volume/measure_attractor.h"

namespace gridifs::ui {
namespace {

using Clock = std::chrono::steady_clock;

/// How often the worker publishes a partial volume: the classification and the ray march cost a
/// little each time, and a few pictures a second read as a steady fill.
constexpr double kPublishSeconds = 0.35;

/// Chaos-game projects (no median function) are binned in this many passes of a share of the
/// samples each, so that their picture fills progressively too.
constexpr int kPointPasses = 8;

/// Bytes a preview at resolution n needs at most: the worker's counts, colour sums, the published
/// frame (density, colour), its classification (albedo, opacity, shadow) and shading (4 per
/// voxel), and the voxel sets of a set iteration (the current set, its image and one voxelized
/// set per function, each at worst every voxel).
std::uint64_t volumeBytes(const Project& project, int n) {
  const std::uint64_t voxels = std::uint64_t(n) * std::uint64_t(n) * std::uint64_t(n);
  const std::uint64_t functions = project.functions.size();
  return voxels * (4 + 12 + 4 + 12 + 20 + 16 + 4 * (2 + functions)) *
         2;  // ×2: a frame in flight and one on the UI side
}

}  // namespace

VolumePreview::VolumePreview() = default;
VolumePreview::~VolumePreview() = default;

Vec3 VolumePreview::lightDirection(const Project& project) {
  const Vec3 d = volumeLookOf(project).towardLight;
  const double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  return length > 0.0 ? d / length : Vec3(0.0, 0.0, 1.0);
}

int VolumePreview::effectiveResolution(const Project& project, int requested) {
  const int cap = project.volume ? project.volume->resolution : VolumeSettings{}.resolution;
  return std::clamp(std::min(requested, cap), kMinVolumeResolution, kMaxVolumeResolution);
}

VolumeLook VolumePreview::lookOf(const Project& project) {
  VolumeLook look = volumeLookOf(project);
  // The palette colours the density where the functions share one colour (no colour volume).
  if (palette_.empty() || paletteRef_ != project.render.flame.palette) {
    paletteRef_ = project.render.flame.palette;
    Palette palette;
    try {
      palette = resolvePalette(paletteRef_, paletteFolder_);
    } catch (const std::exception&) {
      palette = builtinPalette(kDefaultPaletteRef);  // the flame controls say why
    }
    palette_.clear();
    for (const Rgb& c : palette.colors) palette_.insert(palette_.end(), {c.r, c.g, c.b});
  }
  look.palette = palette_;
  return look;
}

void VolumePreview::update(const Document& document, int threads) {
  const Project& project = document.project();
  paletteFolder_ = document.path().parent_path();
  const VolumeLook look = lookOf(project);
  const bool reclassify = !haveLook_ || !look.classifiesLike(look_);
  look_ = look;
  haveLook_ = true;
  if (reclassify) classifySource();  // the volume on screen gets its new look; a running one's frames on arrival
  const int resolution = effectiveResolution(project, view.resolution);
  // The measure depends on the functions (and their sets) and on the volume settings; the Document
  // bumps the geometry revision when a new time changes a function (keys, fields, calculators).
  // Camera, display and light changes only redraw.
  if (haveRequest_ && document.revisions().geometry == geometryRevision_ && project.volume == volumeSettings_ &&
      resolution == requestedResolution_)
    return;
  haveRequest_ = true;
  geometryRevision_ = document.revisions().geometry;
  volumeSettings_ = project.volume;
  requestedResolution_ = resolution;
  ++restarts_;
  setIteration_ = usesSetIteration(project);

  compute_.cancel();  // stale work stops at its next poll
  error_.clear();
  shownFinal_ = false;
  const std::uint64_t need = volumeBytes(project, resolution);
  if (const auto available = availableMemoryBytes(); available && need > *available / 2) {
    error_ = "A " + std::to_string(resolution) + "³ volume needs about " + describeBytes(need) +
             ", more than half of the " + describeBytes(*available) + " free: choose a lower preview resolution";
    return;
  }
  Request request;
  request.project = project;
  request.folder = document.path().parent_path();
  request.resolution = resolution;
  request.threads = threads_ = std::max(1, threads);
  compute_.submit(std::move(request));
}

void VolumePreview::suspend() {
  if (!compute_.busy()) return;
  compute_.cancel();
  haveRequest_ = false;
}

void VolumePreview::classifySource() {
  if (source_) classify_.submit({source_, look_, threads_});
}

void VolumePreview::compute(const Request& request, ComputeJob::Context& context) {
  const Project& project = request.project;
  VolumeSettings settings = project.volume.value_or(VolumeSettings{});
  settings.resolution = request.resolution;
  VolumeJob job;
  job.threads = request.threads;
  job.projectFolder = request.folder;
  job.cancel = context.stopFlag();
  const std::size_t voxels =
      std::size_t(settings.resolution) * std::size_t(settings.resolution) * std::size_t(settings.resolution);
  auto lastPublish = Clock::now();
  try {
    if (usesSetIteration(project)) {
      // Sokolov & Gentil, §3.4: P accumulates once per set iteration after the skip; each partial
      // volume is the visits so far, a picture that sharpens as the iteration runs.
      context.progress(0, settings.iterations);
      job.settings = settings;
      job.progress = [&](double f) {
        context.progress(std::int64_t(std::lround(f * settings.iterations)), settings.iterations);
      };
      job.partial = [&](const DensityVolume& partial) {
        if (std::chrono::duration<double>(Clock::now() - lastPublish).count() < kPublishSeconds) return;
        publish(request, context, partial.density, partial.color, false);
        lastPublish = Clock::now();
      };
      const DensityVolume volume = computeDensityVolume(project, job);
      if (context.stale()) return;
      std::vector<float> colorSums = volume.color;  // means back to sums: publish() divides again
      for (std::size_t v = 0; v < voxels && !colorSums.empty(); ++v)
        for (int c = 0; c < 3; ++c) colorSums[3 * v + std::size_t(c)] *= volume.density[v];
      publish(request, context, volume.density, colorSums, true);
    } else {
      // The chaos game's points binned: the samples in passes with their own seeds, each pass's
      // normalised density turned back into hit counts (P = density · max P, max P = Σ P / Σ density).
      const std::int64_t samples = std::max<std::int64_t>(settings.samples, kPointPasses);
      context.progress(0, samples);
      std::vector<float> counts(voxels, 0.0f), colorSums;
      for (int pass = 0; pass < kPointPasses && !context.stale(); ++pass) {
        job.settings = settings;
        job.settings.samples = samples / kPointPasses;
        job.settings.seed = settings.seed + std::uint64_t(pass) * 0x9E3779B97F4A7C15ull;
        const std::int64_t before = std::int64_t(pass) * job.settings.samples;
        job.progress = [&](double f) {
          context.progress(before + std::int64_t(f * double(job.settings.samples)), samples);
        };
        const DensityVolume volume = computeDensityVolume(project, job);
        if (context.stale()) return;
        double sum = 0.0;
        for (float d : volume.density) sum += d;
        const double largest = sum > 0.0 ? volume.totalMass / sum : 0.0;
        if (!volume.color.empty() && colorSums.empty()) colorSums.assign(voxels * 3, 0.0f);
        for (std::size_t v = 0; v < voxels; ++v) {
          const float hits = float(volume.density[v] * largest);
          counts[v] += hits;
          if (!volume.color.empty())
            for (int c = 0; c < 3; ++c)
              colorSums[3 * v + std::size_t(c)] += volume.color[3 * v + std::size_t(c)] * hits;
        }
        publish(request, context, counts, colorSums, pass + 1 == kPointPasses);
      }
      context.progress(samples, samples);
    }
  } catch (const std::exception& e) {
    if (context.stale()) return;
    auto frame = std::make_shared<Frame>();
    frame->error = e.what();
    context.publish(std::move(frame));
  }
}

void VolumePreview::publish(const Request& request, ComputeJob::Context& context, const std::vector<float>& counts,
                            const std::vector<float>& colorSums, bool final) {
  if (context.stale()) return;  // spare the copy of a volume nobody will see
  auto frame = std::make_shared<Frame>();
  frame->volume.n = request.resolution;
  frame->final = final;
  frame->volume.density = counts;
  float largest = 0.0f;
  for (float c : counts) largest = std::max(largest, c);
  if (!colorSums.empty()) {
    frame->volume.color.resize(colorSums.size());
    for (std::size_t v = 0; v < counts.size(); ++v)
      for (int c = 0; c < 3; ++c)
        frame->volume.color[3 * v + std::size_t(c)] =
            counts[v] > 0.0f ? colorSums[3 * v + std::size_t(c)] / counts[v] : 0.0f;
  }
  if (largest > 0.0f)
    for (float& d : frame->volume.density) d /= largest;
  context.publish(std::move(frame));
}

void VolumePreview::classify(const ClassifyInput& input, ClassifyJob::Context& context) {
  auto volume = std::make_shared<ClassifiedVolume>(classifyVolume(input.source->volume, input.look, input.threads));
  context.publish({input.source, input.look, std::move(volume)});
}

void VolumePreview::march(const ImageInput& input, ImageJob::Context& context) {
  Picture picture;
  picture.input = input;
  try {
    const ShadedVolume shaded = shadeVolume(*input.classified.volume, input.look, input.threads);
    if (context.stale()) return;
    const VolumeImage image = marchVolume(shaded, input.look, input.camera, input.width, input.height, input.threads);
    picture.rgba = image.composited(input.look.background);
  } catch (const std::exception&) {
    // A degenerate camera (validated elsewhere) shows the background only.
    picture.rgba.assign(std::size_t(input.width) * std::size_t(input.height) * 4, 255);
    for (std::size_t p = 0; p < picture.rgba.size() / 4; ++p)
      for (int c = 0; c < 3; ++c)
        picture.rgba[4 * p + std::size_t(c)] =
            std::uint8_t(std::lround(std::clamp(input.look.background[c], 0.0, 1.0) * 255.0));
  }
  context.publish(std::move(picture));
}

bool VolumePreview::upload() {
  if (auto computed = compute_.poll()) {
    const FramePtr& frame = computed->value;
    if (!frame->error.empty()) {
      error_ = frame->error;
      return true;
    }
    source_ = frame;
    shownResolution_ = frame->volume.n;
    shownFinal_ = frame->final;
    error_.clear();
    ++uploads_;
    classifySource();
  }
  if (auto classified = classify_.poll()) {
    // Kept only when it is the newest volume in the newest look (an older one is moot).
    if (classified->value.source == source_ && classified->value.look.classifiesLike(look_))
      classified_ = std::move(classified->value);
  }
  bool changed = false;
  if (auto picture = image_.poll()) {
    Picture& p = picture->value;
    texture_.upload(p.input.width, p.input.height, p.rgba.data());
    // Scaled up to the view: linear filtering, as a texture of the volume would be.
    glBindTexture(GL_TEXTURE_2D, texture_.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBindTexture(GL_TEXTURE_2D, 0);
    imageCurrent_ = imageRequest_ && p.input == *imageRequest_;
    ++images_;
    changed = true;
  }
  return changed;
}

void VolumePreview::requestImage(const Project& project, int width, int height) {
  if (!classified_ || !error_.empty()) return;
  ImageInput input;
  input.classified = *classified_;
  input.look = look_;
  input.camera = project.camera;
  input.width = std::max(1, width);
  input.height = std::max(1, height);
  input.threads = threads_;
  if (imageRequest_ && input == *imageRequest_) return;
  imageRequest_ = input;
  imageCurrent_ = false;
  image_.submit(std::move(input));
}

bool VolumePreview::pictureFinal() const {
  return finished() && imageCurrent_ && classified_ && classified_->source == source_ &&
         classified_->look.classifiesLike(look_) && imageRequest_ && imageRequest_->look == look_;
}

}  // namespace gridifs::ui
