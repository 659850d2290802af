#pragma once
// The bridge between the Document and the background ChaosRenderer: when the
// document's revision or the preview size changes, compile a new immutable snapshot and
// restart the workers (a new generation); each frame, merge what the workers have so far.
// Never waits on workers: restart() only publishes, snapshot() reads while they run.
#include <cstdint>
#include <memory>
#include <string>

#include "edit/document.h"
#include "job/preview_plan.h"
#include "render/chaos_renderer.h"

namespace gridifs::ui {

class PreviewRenderer {
 public:
  /// Renders on the CPU worker pool until useDevice() picks another renderer.
  PreviewRenderer();
  /// Picks the preview's renderer (auto | gpu | cpu): the GPU compute renderer on its own headless
  /// context when asked for or, for auto, when a hardware GPU offers OpenGL 4.3 compute; else the
  /// CPU. Returns an error sentence when `gpu` was asked for and cannot be had ("" otherwise).
  std::string useDevice(const std::string& device);
  /// "cpu" or "gpu (renderer name)".
  const char* deviceName() const { return renderer_->deviceName(); }
  /// Publishes a new snapshot when the project (or size, or thread count) changed since the
  /// last call. When the project cannot be compiled the previous image stays and error() says why.
  void publish(const Document& document, int width, int height, int threads);
  /// Merges the current buffers into `image` when new points arrived; returns true when
  /// `image` changed.
  bool fetch(RenderImage& image);
  void setPaused(bool paused);
  /// The next publish() restarts even when nothing changed.
  void forceRestart() {
    last_.started = false;
    revision_ = 0;
  }
  RenderStats stats() const { return renderer_->stats(); }
  std::uint64_t restarts() const { return restarts_; }
  /// Why the current project cannot be rendered (empty when it can).
  const std::string& error() const { return error_; }
  /// Whether the workers still have work (the UI keeps animating while they do).
  bool busy() const;

 private:
  std::unique_ptr<Renderer> renderer_;
  std::shared_ptr<const CompiledIfs> ifs_;  // the last one restarted with
  std::string device_ = "cpu";
  std::uint64_t revision_ = 0;
  PreviewInputs last_;                        // what the workers last started from (job/preview_plan.h)
  int width_ = 0, height_ = 0, threads_ = 0;  // the last publish's size and threads
  DisplaySettings display_;
  bool displayChanged_ = true;
  std::int64_t lastSamples_ = -1;
  std::uint64_t lastGeneration_ = 0;
  std::uint64_t restarts_ = 0;
  bool paused_ = false;
  bool running_ = false;
  std::string error_;
};

}  // namespace gridifs::ui
