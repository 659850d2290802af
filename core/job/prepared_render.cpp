#include "job/prepared_render.h"

#include <algorithm>

#include "flame/palette_gradient.h"
#include "model/project_time.h"
#include "render/flame_render.h"
#include "render/shaded_image.h"
#include "volume/condensation_sampler.h"
#include "volume/measure_attractor.h"
#include "volume/volume_points.h"

namespace gridifs {

Project renderProjectAt(const Project& project, double time) {
  try {
    return projectAtTime(project, time);
  } catch (const ModelError& e) {
    throw RenderJobError(e);
  }
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

PreparedRender prepareRender(const Project& project, const RenderJobOptions& options) {
  PreparedRender r;
  r.project = options.time ? renderProjectAt(project, *options.time) : project;
  r.output = outputRenderJob(r.project, options);
  // The renderer would draw an empty picture: say so instead.
  if (r.output.samples < 1) throw RenderJobError("render.samples", "must be at least 1");
  try {
    validateRenderJob(r.output);
  } catch (const ModelError& e) {
    throw RenderJobError(e);
  }
  const EvaluationCache evaluation;
  r.ifs = compileChaosIfs(r.project, evaluation, options);
  const bool flame = options.preview || r.project.render.mode == DisplayMode::Flame;
  if (flame) r.palette = renderPalette(r.project, options.folder, options.preview);
  r.job = displayRenderJob(r.project, r.output, *r.ifs, r.palette, options.preview);
  try {
    validateRenderJob(r.job);
  } catch (const ModelError& e) {
    // Only the flame display's supersampling makes the renderer's job larger than the output.
    if (r.project.render.mode == DisplayMode::Flame && !options.preview)
      throw RenderJobError(
          e.path(),
          "with supersample " + std::to_string(std::max(1, r.project.render.flame.supersample)) + ", " + e.message());
    throw RenderJobError(e);
  }
  r.display = renderDisplaySettings(r.project);
  r.device = r.project.render.mode == DisplayMode::Shaded ? "cpu" : options.device;
  return r;
}

}  // namespace gridifs
