#include "ui/views/preview_renderer.h"

#include "job/prepared_render.h"
#include "render/compiled_ifs.h"
#include "render/shaded_image.h"
#if GRIDIFS_HAVE_GPU
#include "gpu/render_device.h"
#endif
#include "ui/views/flame_display.h"

namespace gridifs::ui {

PreviewRenderer::PreviewRenderer() : renderer_(std::make_unique<ChaosRenderer>()) {}

std::string PreviewRenderer::useDevice(const std::string& device) {
#if !GRIDIFS_HAVE_GPU
  if (device == "gpu") return "cannot render on the GPU: this build of gridifs has no GPU renderer";
  return "";
#else
  gpu::RenderDevice d = gpu::RenderDevice::Auto;
  if (!gpu::parseRenderDevice(device, d)) return "unknown render device " + device;
  try {
    gpu::RendererChoice choice = gpu::openRenderer(d);
    renderer_ = std::move(choice.renderer);
  } catch (const gpu::GpuUnavailable& e) {
    return std::string("cannot render on the GPU: ") + e.what();
  }
  device_ = device;
  forceRestart();
  running_ = false;
  return "";
#endif
}

void PreviewRenderer::publish(const Document& document, int width, int height, int threads) {
  width = std::max(width, 16);
  height = std::max(height, 16);
  if (document.revision() == revision_ && width == width_ && height == height_ && threads == threads_) return;
  revision_ = document.revision();
  const Project& project = document.project();
  const Revisions& now = document.revisions();
  if (now.display != published_.display) {
    // The shaded display develops the structural colour itself: no depth cueing in its buffers.
    const DisplaySettings display = renderDisplaySettings(project);
    if (!(display.background == display_.background) || display.depthCue != display_.depthCue) {
      display_ = display;
      displayChanged_ = true;
    }
  }
  // Background, depth cue, the display mode and the flame tone mapping only change how the
  // buffers become a picture (snapshot(), ui/views/flame_display.cpp): no restart. The palette is
  // looked up per sample, so it is a render input.
  const bool sameInput =
      now.geometry == published_.geometry && now.render == published_.render && now.camera == published_.camera;
  const bool sameGeometry = havePublished_ && ifs_ && now.geometry == published_.geometry;
  published_ = now;
  if (havePublished_ && sameInput && width == width_ && height == height_ && threads == threads_) return;
  try {
    // Condensation sets read from files are sampled from 128³ voxels beside the project: coarser
    // than the CLI's 256³, so an edit restarts the preview quickly.
    const std::filesystem::path folder = document.path().parent_path().empty() ? "." : document.path().parent_path();
    // The same compiled IFS while the functions are unchanged: a restart that then changes only
    // the shadowed lights keeps the camera's buffers (ChaosRenderer::restart).
    auto ifs = sameGeometry ? ifs_ : compileRenderIfs(document.project(), document.evaluation(), folder, 128);
    // The steps of prepareRender (job/prepared_render.h) for the preview: low priority threads
    // (the modeller stays at ≥ 30 fps while rendering), colour sums always on so that the mode
    // switch is instant, and the shaded display's lights.
    RenderJobOptions options;
    options.threads = threads;
    options.width = width;
    options.height = height;
    options.preview = true;
    const RenderJob job = displayRenderJob(project, outputRenderJob(project, options), *ifs,
                                           renderPalette(project, folder, /*preview=*/true), /*preview=*/true);
#if GRIDIFS_HAVE_GPU
    try {
      renderer_->restart(ifs, job);
    } catch (const gpu::GpuUnavailable& e) {
      // The GPU cannot hold this preview (e.g. its memory): auto goes on on the CPU.
      if (device_ != "auto") throw ModelError("", std::string("the GPU cannot render the preview: ") + e.what());
      renderer_ = std::make_unique<ChaosRenderer>();
      renderer_->restart(ifs, job);
    }
#else
    renderer_->restart(ifs, job);
#endif
    ifs_ = ifs;
    if (paused_) renderer_->pause();
    ++restarts_;
    running_ = true;
    error_.clear();
  } catch (const ModelError& e) {
    // Keep showing the last image; the artist sees why in the status bar. The next restart
    // compiles again (this one may have failed to compile what is now published).
    ifs_.reset();
    havePublished_ = true;
    width_ = width;
    height_ = height;
    threads_ = threads;
    error_ = e.what();
    return;
  }
  havePublished_ = true;
  width_ = width;
  height_ = height;
  threads_ = threads;
}

bool PreviewRenderer::fetch(RenderImage& image) {
  if (!running_) return false;
  const RenderStats s = renderer_->stats();
  if (!displayChanged_ && s.generation == lastGeneration_ && s.samples == lastSamples_) return false;
  renderer_->snapshot(image, display_);
  displayChanged_ = false;
  lastGeneration_ = s.generation;
  lastSamples_ = s.samples;
  return true;
}

void PreviewRenderer::setPaused(bool paused) {
  if (paused == paused_) return;
  paused_ = paused;
  if (!running_) return;
  if (paused)
    renderer_->pause();
  else
    renderer_->resume();
}

bool PreviewRenderer::busy() const {
  if (!running_ || paused_) return false;
  const RenderStats s = renderer_->stats();
  return !s.done || s.generation != lastGeneration_ || s.samples != lastSamples_;
}

}  // namespace gridifs::ui
