#include "explore/thumbnail.h"

#include "job/prepared_render.h"
#include "render/chaos_renderer.h"
#include "render/flame_render.h"

namespace gridifs {

Thumbnail renderThumbnail(const Project& project, const std::filesystem::path& folder, int width, int height,
                          std::int64_t samples, int threads, const std::atomic<bool>* cancel, Renderer* renderer) {
  RenderJobOptions options;
  options.threads = threads;
  options.width = width;
  options.height = height;
  options.samples = samples;
  options.seed = 1;
  options.folder = folder;
  options.setResolution = 64;
  options.preview = true;  // the default palette while the project's cannot be read
  const PreparedRender prepared = prepareRender(project, options);
  const bool flame = prepared.project.render.mode == DisplayMode::Flame;
  // The shaded display's lights and shadows are the preview's own work; a thumbnail shows its
  // z-buffer.
  const RenderJob& job = flame ? prepared.job : prepared.output;
  RenderImage image;
  const auto goOn = [cancel](const RenderStats&) { return !(cancel && cancel->load()); };
  bool rendered = false;
  if (renderer && prepared.device != "cpu") {
    try {
      renderer->restart(prepared.ifs, job);
      if (!renderer->waitUntilDone(goOn)) return {};
      renderer->snapshot(image, prepared.display);
      rendered = true;
    } catch (const ModelError&) {
      throw;
    } catch (const std::exception&) {
      // A job the device cannot hold: the CPU renders it, as `render --device auto` falls back.
    }
  }
  if (!rendered) {
    try {
      image = renderToCompletion(prepared.ifs, job, prepared.display, goOn);
    } catch (const RenderCancelled&) {
      return {};
    }
  }
  Thumbnail thumbnail{width, height, {}};
  if (flame) {
    const FlameImage developed =
        developFlameSnapshot(image, prepared.project.render.flame, prepared.project.camera, width, height,
                             prepared.project.render.background, false, threads);
    flameImageToRgba8(developed, thumbnail.rgba);
  } else {
    thumbnail.rgba = std::move(image.rgba);
  }
  return thumbnail;
}

}  // namespace gridifs
