#include "job/preview_plan.h"

#include <algorithm>

namespace gridifs {

PreviewDecision decidePreview(const PreviewInputs& last, const Revisions& now, int width, int height, int threads) {
  PreviewDecision d;
  // Background, depth cue, the display mode and the flame tone mapping only change how the
  // buffers become a picture; the palette is looked up per sample, so it is a render input.
  d.redisplay = now.display != last.revisions.display;
  const bool sameInput = now.geometry == last.revisions.geometry && now.render == last.revisions.render &&
                         now.camera == last.revisions.camera;
  const bool sameSize = width == last.width && height == last.height && threads == last.threads;
  d.restart = !last.started || !sameInput || !sameSize;
  d.recompile = d.restart && (!last.started || !last.haveIfs || now.geometry != last.revisions.geometry);
  return d;
}

PreparedRender preparePreview(const Document& document, int width, int height, int threads,
                              std::shared_ptr<const CompiledIfs> reuse) {
  PreparedRender r;
  r.project = document.project();
  const std::filesystem::path folder = document.path().parent_path().empty() ? "." : document.path().parent_path();
  RenderJobOptions options;
  options.threads = threads;
  options.width = std::max(width, kMinPreviewSide);
  options.height = std::max(height, kMinPreviewSide);
  options.folder = folder;
  options.setResolution = kPreviewSetResolution;
  options.preview = true;
  r.output = outputRenderJob(r.project, options);
  try {
    validateRenderJob(r.output);
  } catch (const ModelError& e) {
    throw RenderJobError(e);
  }
  // The document's evaluated grids: an edit re-evaluates only the function it changed.
  r.ifs = reuse ? std::move(reuse) : compileRenderIfs(r.project, document.evaluation(), folder, options.setResolution);
  r.palette = renderPalette(r.project, folder, /*preview=*/true);
  r.job = displayRenderJob(r.project, r.output, *r.ifs, r.palette, /*preview=*/true);
  try {
    validateRenderJob(r.job);
  } catch (const ModelError& e) {
    throw RenderJobError(e);
  }
  r.display = renderDisplaySettings(r.project);
  r.device = options.device;
  return r;
}

}  // namespace gridifs
