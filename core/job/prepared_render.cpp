#include "job/prepared_render.h"

#include <algorithm>
#include <map>
#include <mutex>

#include "live/live_drive.h"
#include "render/flame_render.h"
#include "render/shaded_image.h"
#include "schema/project_time.h"
#include "tone/palette_gradient.h"
#include "volume/condensation_sampler.h"
#include "volume/measure_attractor.h"
#include "volume/volume_points.h"

namespace gridifs {

namespace {

/// The sound's drive of `project`, analysed once per process and sound (not once per frame).
const LiveDrive& soundDriveFor(const Project& project, const std::filesystem::path& folder) {
  static std::mutex lock;
  static std::map<std::string, std::pair<Project, LiveDrive>> drives;
  const std::lock_guard<std::mutex> hold(lock);
  const std::string key = std::filesystem::absolute(folder.empty() ? "." : folder).lexically_normal().string();
  auto it = drives.find(key);
  if (it == drives.end() || it->second.first.audio != project.audio || it->second.first.bindings != project.bindings ||
      it->second.first.animation != project.animation) {
    Project kept;
    kept.audio = project.audio;
    kept.bindings = project.bindings;
    kept.animation = project.animation;
    LiveDrive drive = LiveDrive::forProject(project, folder);
    it = drives.insert_or_assign(key, std::pair{std::move(kept), std::move(drive)}).first;
  }
  return it->second.second;
}

/// The project at options.time (as given without one), adjusted.
Project projectFor(const Project& project, const RenderJobOptions& options) {
  Project at = options.time ? renderProjectAt(project, *options.time, options.folder) : project;
  if (options.adjust) options.adjust(at);
  return at;
}

/// The display job within the renderer's limits; only the flame display's supersampling makes it
/// larger than the output.
void validateDisplayJob(const PreparedRender& r, bool preview) {
  try {
    validateRenderJob(r.job);
  } catch (const ModelError& e) {
    if (r.project.render.mode == DisplayMode::Flame && !preview)
      throw RenderJobError(
          e.path(),
          "with supersample " + std::to_string(std::max(1, r.project.render.flame.supersample)) + ", " + e.message());
    throw RenderJobError(e);
  }
}

}  // namespace

Project renderProjectAt(const Project& project, double time, const std::filesystem::path& folder) {
  try {
    Project at = projectAtTime(project, time);
    if (!project.bindings.empty()) soundDriveFor(project, folder).applyBindings(at, time);
    return at;
  } catch (const ModelError& e) {
    throw RenderJobError(e);
  } catch (const IoError& e) {
    throw RenderJobError("audio.file", e.what());
  }
}

std::int64_t frameSampleCount(const Project& project, const RenderJobOptions& options) {
  return outputRenderJob(projectFor(project, options), options).samples;
}

RenderJob outputRenderJob(const Project& project, const RenderJobOptions& options) {
  RenderJob job = RenderJob::fromProject(project, options.threads);
  if (options.width) job.width = *options.width;
  if (options.height) job.height = *options.height;
  if (options.seed) job.seed = *options.seed;
  if (project.render.quality) {
    // Quality is samples per pixel of the image actually rendered (another size: other samples).
    RenderSettings size = project.render;
    size.width = job.width;
    size.height = job.height;
    job.samples = renderSampleCount(size);
  }
  if (options.samples) job.samples = *options.samples;
  // The UI thread gets a core first: the modeller stays responsive while the preview renders.
  if (options.preview) job.lowPriority = true;
  return job;
}

std::shared_ptr<const CompiledIfs> compileRenderIfs(const Project& project, const EvaluationCache& evaluation,
                                                    const std::filesystem::path& folder, int setResolution) {
  try {
    return compileIfs(project, evaluation,
                      makeCondensationSampler(project, folder.empty() ? "." : folder, setResolution));
  } catch (const ModelError& e) {
    throw RenderJobError(e);
  }
}

std::shared_ptr<const CompiledIfs> compileChaosIfs(const Project& project, const EvaluationCache& evaluation,
                                                   const RenderJobOptions& options,
                                                   std::shared_ptr<const DensityVolume> volume) {
  if (!volume && !usesSetIteration(project))
    return compileRenderIfs(project, evaluation, options.folder, options.setResolution);
  // Sokolov & Gentil, §3.2: median functions map sets, not points, so the renderer draws the
  // points of the project's density volume (what `gridifs volume` writes) from its "volume"
  // settings.
  try {
    if (volume) return compileVolumePoints(project, *volume);
    VolumeJob volumeJob;
    volumeJob.settings = project.volume.value_or(VolumeSettings{});
    volumeJob.threads = options.threads;
    volumeJob.projectFolder = options.folder.empty() ? std::filesystem::path(".") : options.folder;
    return compileVolumePoints(project, computeDensityVolume(project, volumeJob));
  } catch (const RenderJobError&) {
    throw;
  } catch (const ModelError& e) {
    throw RenderJobError(e);
  }
}

std::shared_ptr<const Palette> renderPalette(const Project& project, const std::filesystem::path& folder,
                                             bool preview) {
  try {
    return std::make_shared<const Palette>(resolveFlamePalette(project.render.flame, folder));
  } catch (const std::exception& e) {
    if (preview) return std::make_shared<const Palette>(builtinPalette(kDefaultPaletteRef));
    throw RenderJobError("render.flame.palette", e.what());
  }
}

RenderJob displayRenderJob(const Project& project, const RenderJob& output, const CompiledIfs& ifs,
                           std::shared_ptr<const Palette> palette, bool preview) {
  try {
    if (preview) {
      // Colour sums in every mode, at the preview's pixels and without a gutter, so that the
      // z-buffer image stays the frame and switching to the flame display needs no restart.
      FlameSettings flame = project.render.flame;
      flame.supersample = 1;
      RenderJob job = flameRenderJob(output, flame, std::move(palette), /*gutter=*/false);
      // Shadow maps and depth of field are filled by the same chaos game (render/shaded_plot.h).
      if (project.render.mode == DisplayMode::Shaded) job = shadedRenderJob(job, project.render.shading, ifs);
      return job;
    }
    switch (project.render.mode) {
      case DisplayMode::Flame: {
        // Draves & Reckase 2003, §4–8: supersampled, with a gutter, palette colours per sample,
        // developed from hit counts and colour sums alone (no z-buffer keys).
        RenderJob job = flameRenderJob(output, project.render.flame, std::move(palette));
        job.depthKeys = false;
        return job;
      }
      case DisplayMode::Shaded:
        return shadedRenderJob(output, project.render.shading, ifs);
      default:
        return output;
    }
  } catch (const ModelError& e) {
    throw RenderJobError(e);
  }
}

DisplaySettings renderDisplaySettings(const Project& project) {
  return project.render.mode == DisplayMode::Shaded ? shadedDisplaySettings(project)
                                                    : DisplaySettings::fromProject(project);
}

void checkRenderOutput(const Project& project, const RenderJobOptions& options) {
  const RenderJob output = outputRenderJob(project, options);
  // The renderer would draw an empty picture: say so instead.
  if (output.samples < 1) throw RenderJobError("render.samples", "must be at least 1");
  try {
    validateRenderJob(output);
  } catch (const ModelError& e) {
    throw RenderJobError(e);
  }
}

PreparedRender preparePoints(const Project& project, const RenderJobOptions& options) {
  PreparedRender r;
  r.project = projectFor(project, options);
  checkRenderOutput(r.project, options);
  r.output = outputRenderJob(r.project, options);
  const EvaluationCache fresh;
  r.ifs = compileChaosIfs(r.project, options.evaluation ? *options.evaluation : fresh, options, options.volume);
  r.job = r.output;
  r.display = renderDisplaySettings(r.project);
  r.device = options.device;
  return r;
}

PreparedRender prepareRender(const Project& project, const RenderJobOptions& options) {
  PreparedRender r = preparePoints(project, options);
  const bool flame = options.preview || r.project.render.mode == DisplayMode::Flame;
  if (flame) r.palette = renderPalette(r.project, options.folder, options.preview);
  r.job = displayRenderJob(r.project, r.output, *r.ifs, r.palette, options.preview);
  validateDisplayJob(r, options.preview);
  r.device = r.project.render.mode == DisplayMode::Shaded ? "cpu" : options.device;
  return r;
}

PreparedRender prepareDevelop(const Project& project, const RenderJobOptions& options) {
  PreparedRender r;
  r.project = projectFor(project, options);
  r.output = outputRenderJob(r.project, options);
  r.job = r.output;
  if (r.project.render.mode == DisplayMode::Flame)
    r.job = displayRenderJob(r.project, r.output, CompiledIfs{}, nullptr);
  validateDisplayJob(r, false);
  r.display = renderDisplaySettings(r.project);
  r.device = "cpu";
  return r;
}

}  // namespace gridifs
