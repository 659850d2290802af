#include "ui/views/volume_preview.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include "base/system_memory.h"
#include "render/volume_light.h"
#include "volume/measure_attractor.h"

namespace gridifs::ui {
namespace {

using Clock = std::chrono::steady_clock;

/// How often the worker publishes a partial volume: the shadow precompute and the upload cost a
/// little each time, and a few pictures a second read as a steady fill.
constexpr double kPublishSeconds = 0.35;

/// Chaos-game projects (no median function) are binned in this many passes of a share of the
/// samples each, so that their picture fills progressively too.
constexpr int kPointPasses = 8;

/// Bytes a preview at resolution n needs at most: the worker's counts, colour sums, the published
/// frame (density, colour, shadow) and the voxel sets of a set iteration (the current set, its
/// image and one voxelized set per function, each at worst every voxel).
std::uint64_t volumeBytes(const Project& project, int n) {
  const std::uint64_t voxels = std::uint64_t(n) * std::uint64_t(n) * std::uint64_t(n);
  const std::uint64_t functions = project.functions.size();
  return voxels * (4 + 12 + 4 + 12 + 4 + 4 * (2 + functions)) * 2;  // ×2: a frame in flight and one on the UI side
}

void setTextureParameters(GLenum target, GLint filter) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
}

}  // namespace

VolumePreview::VolumePreview() = default;

VolumePreview::~VolumePreview() {
  const GLuint textures[] = {density_, color_, lightDepth_, palette_};
  for (GLuint t : textures)
    if (t) glDeleteTextures(1, &t);
  if (vao_) glDeleteVertexArrays(1, &vao_);
}

Vec3 VolumePreview::lightDirection(const Project& project) {
  const auto& lights = project.render.shading.lights;
  // The key light of the shading settings, so the volume and the shaded display agree; a project
  // without lights gets the shading settings' default key light.
  const Vec3 d = lights.empty() ? ShadingLight{}.direction : lights[0].direction;
  const double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  return length > 0.0 ? d / length : Vec3(0.0, 0.0, 1.0);
}

int VolumePreview::effectiveResolution(const Project& project, int requested) {
  const int cap = project.volume ? project.volume->resolution : VolumeSettings{}.resolution;
  return std::clamp(std::min(requested, cap), kMinVolumeResolution, kMaxVolumeResolution);
}

void VolumePreview::update(const Document& document, int threads) {
  const Project& project = document.project();
  paletteFolder_ = document.path().parent_path();
  const Vec3 light = lightDirection(project);
  if (!(light == light_)) {
    light_ = light;
    relightSource();  // the volume on screen gets its shadow again; a running one's frames on arrival
  }
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
  hasColor_ = hasColorVolume(project);

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
  request.light = light_;
  compute_.submit(std::move(request));
}

void VolumePreview::suspend() {
  if (!compute_.busy()) return;
  compute_.cancel();
  haveRequest_ = false;
}

void VolumePreview::relightSource() {
  if (source_) relight_.submit({source_, light_, threads_});
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
  if (context.stale()) return;  // spare the shadow of a volume nobody will see
  auto frame = std::make_shared<Frame>();
  frame->n = request.resolution;
  frame->final = final;
  frame->density = counts;
  float largest = 0.0f;
  for (float c : counts) largest = std::max(largest, c);
  if (!colorSums.empty()) {
    frame->color.resize(colorSums.size());
    for (std::size_t v = 0; v < counts.size(); ++v)
      for (int c = 0; c < 3; ++c)
        frame->color[3 * v + std::size_t(c)] = counts[v] > 0.0f ? colorSums[3 * v + std::size_t(c)] / counts[v] : 0.0f;
  }
  if (largest > 0.0f)
    for (float& d : frame->density) d /= largest;
  frame->light = request.light;
  frame->lightDepth = lightOpticalDepth(frame->density, frame->n, request.light, request.threads);
  context.publish(std::move(frame));
}

void VolumePreview::relight(const Relight& relight, RelightJob::Context& context) {
  auto frame = std::make_shared<Frame>(*relight.source);
  frame->light = relight.light;
  frame->lightDepth = lightOpticalDepth(frame->density, frame->n, relight.light, relight.threads);
  context.publish({relight.source, std::move(frame)});
}

bool VolumePreview::upload() {
  if (auto computed = compute_.poll()) {
    const FramePtr& frame = computed->value;
    if (!frame->error.empty()) {
      error_ = frame->error;
      return true;
    }
    source_ = frame;
    // The light turned while this frame was computed: show it now, and its new shadow when ready.
    if (frame->light == light_)
      relight_.cancel();  // an older frame's shadow is moot
    else
      relightSource();
    uploadFrame(*frame);
    return true;
  }
  if (auto relit = relight_.poll()) {
    if (relit->value.source != source_) return false;  // a newer volume came meanwhile (it has its own shadow)
    uploadFrame(*relit->value.frame);
    return true;
  }
  return false;
}

void VolumePreview::uploadFrame(const Frame& frame) {
  const GLsizei n = frame.n;
  auto upload3d = [n](GLuint& texture, GLint internal, GLenum format, const std::vector<float>& data) {
    if (!texture) glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_3D, texture);
    setTextureParameters(GL_TEXTURE_3D, GL_LINEAR);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage3D(GL_TEXTURE_3D, 0, internal, n, n, n, 0, format, GL_FLOAT, data.data());
  };
  upload3d(density_, GL_R16F, GL_RED, frame.density);
  upload3d(lightDepth_, GL_R16F, GL_RED, frame.lightDepth);
  hasColor_ = !frame.color.empty();
  if (hasColor_) upload3d(color_, GL_RGB16F, GL_RGB, frame.color);
  glBindTexture(GL_TEXTURE_3D, 0);
  shownResolution_ = frame.n;
  shownFinal_ = frame.final;
  error_.clear();
  ++uploads_;
}

void VolumePreview::draw(const RenderTarget& target, const Project& project) {
  target.bind();
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  const glm::vec3 background(project.render.background);
  glClearColor(background.x, background.y, background.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (density_ && error_.empty() && shownResolution_ > 0) {
    if (!program_) program_.emplace("fullscreen.vert.glsl", "volume.frag.glsl");
    // The palette colours the density where the functions share one colour (no colour volume).
    if (!palette_ || paletteRef_ != project.render.flame.palette) {
      paletteRef_ = project.render.flame.palette;
      Palette palette;
      try {
        palette = resolvePalette(paletteRef_, paletteFolder_);
      } catch (const std::exception&) {
        palette = builtinPalette(kDefaultPaletteRef);  // the flame controls say why
      }
      std::vector<float> rgb;
      for (const Rgb& c : palette.colors) rgb.insert(rgb.end(), {c.r, c.g, c.b});
      if (!palette_) glGenTextures(1, &palette_);
      glBindTexture(GL_TEXTURE_2D, palette_);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB16F, Palette::kSize, 1, 0, GL_RGB, GL_FLOAT, rgb.data());
    }
    try {
      const OrbitCamera camera(project.camera, target.width(), target.height());
      const glm::mat4 inverse = glm::inverse(camera.projectionF() * camera.viewF());
      const auto& lights = project.render.shading.lights;
      const glm::vec3 lightColor = lights.empty() ? glm::vec3(1.0f) : glm::vec3(lights[0].color * lights[0].intensity);
      const GLuint program = program_->id();
      glUseProgram(program);
      glUniform4f(program_->uniform("uRect"), -1.0f, -1.0f, 1.0f, 1.0f);
      glUniformMatrix4fv(program_->uniform("uInverseViewProjection"), 1, GL_FALSE, glm::value_ptr(inverse));
      glUniform3f(program_->uniform("uLightColor"), lightColor.x, lightColor.y, lightColor.z);
      glUniform1f(program_->uniform("uAmbient"), float(project.render.shading.ambient));
      glUniform3f(program_->uniform("uBackground"), background.x, background.y, background.z);
      glUniform1f(program_->uniform("uDensityScale"), view.densityScale);
      glUniform1f(program_->uniform("uStep"), 1.0f / float(shownResolution_));  // half a voxel
      glUniform1i(program_->uniform("uHasColor"), hasColor_ ? 1 : 0);
      glUniform1i(program_->uniform("uDensity"), 0);
      glUniform1i(program_->uniform("uLightDepth"), 1);
      glUniform1i(program_->uniform("uColor"), 2);
      glUniform1i(program_->uniform("uPalette"), 3);
      glActiveTexture(GL_TEXTURE0);
      glBindTexture(GL_TEXTURE_3D, density_);
      glActiveTexture(GL_TEXTURE1);
      glBindTexture(GL_TEXTURE_3D, lightDepth_);
      glActiveTexture(GL_TEXTURE2);
      glBindTexture(GL_TEXTURE_3D, hasColor_ ? color_ : density_);
      glActiveTexture(GL_TEXTURE3);
      glBindTexture(GL_TEXTURE_2D, palette_);
      if (!vao_) glGenVertexArrays(1, &vao_);
      glBindVertexArray(vao_);
      glDrawArrays(GL_TRIANGLES, 0, 3);
      glBindVertexArray(0);
      glUseProgram(0);
      glActiveTexture(GL_TEXTURE0);
    } catch (const std::exception&) {
      // A degenerate camera (validated elsewhere) draws the background only.
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace gridifs::ui
