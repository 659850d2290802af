#include "ui/views/preview_renderer.h"

#include "job/preview_plan.h"
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
  width = std::max(width, kMinPreviewSide);
  height = std::max(height, kMinPreviewSide);
  if (document.revision() == revision_ && width == last_.width && height == last_.height && threads == last_.threads)
    return;
  revision_ = document.revision();
  const Project& project = document.project();
  // What the edit asks for is core's decision (job/preview_plan.h).
  const PreviewDecision decision = decidePreview(last_, document.revisions(), width, height, threads);
  if (decision.redisplay) {
    // The shaded display develops the structural colour itself: no depth cueing in its buffers.
    const DisplaySettings display = renderDisplaySettings(project);
    if (!(display.background == display_.background) || display.depthCue != display_.depthCue) {
      display_ = display;
      displayChanged_ = true;
    }
  }
  last_.revisions = document.revisions();
  // Without a restart the size and threads are the ones started with (else decidePreview restarts).
  if (!decision.restart) return;
  last_.width = width;
  last_.height = height;
  last_.threads = threads;
  last_.started = true;
  try {
    const PreparedRender prepared =
        preparePreview(document, width, height, threads, decision.recompile ? nullptr : ifs_);
#if GRIDIFS_HAVE_GPU
    try {
      renderer_->restart(prepared.ifs, prepared.job);
    } catch (const gpu::GpuUnavailable& e) {
      // The GPU cannot hold this preview (e.g. its memory): auto goes on on the CPU.
      if (device_ != "auto") throw ModelError("", std::string("the GPU cannot render the preview: ") + e.what());
      renderer_ = std::make_unique<ChaosRenderer>();
      renderer_->restart(prepared.ifs, prepared.job);
    }
#else
    renderer_->restart(prepared.ifs, prepared.job);
#endif
    ifs_ = prepared.ifs;
    last_.haveIfs = true;
    if (paused_) renderer_->pause();
    ++restarts_;
    running_ = true;
    error_.clear();
  } catch (const ModelError& e) {
    // Keep showing the last image; the artist sees why in the status bar. The next restart
    // compiles again (this one may have failed to compile what is now published).
    ifs_.reset();
    last_.haveIfs = false;
    error_ = e.what();
  }
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
