#pragma once
// File › Render animation…: the plan (frames A..B, their times, size, samples, output names),
// the render of every frame on a worker thread with a progress bar over all frames that can be
// cancelled, each frame written atomically (ui/animation_frames.h). The worker renders a copy of
// the project taken when it starts, so the artist may go on editing.
#include <atomic>
#include <cstdint>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "ui/modeller_state.h"

namespace gridifs::ui {

class RenderAnimationDialog {
 public:
  RenderAnimationDialog() = default;
  ~RenderAnimationDialog();  // cancels and joins a running render
  RenderAnimationDialog(const RenderAnimationDialog&) = delete;
  RenderAnimationDialog& operator=(const RenderAnimationDialog&) = delete;

  /// Opens when state.showRenderAnimation is set (File menu); call every frame at top level.
  void draw(ModellerState& state);
  bool running() const { return running_.load(); }
  nlohmann::json probeJson() const;

 private:
  enum class Phase { Options, Running, Done, Failed, Cancelled };
  void openFor(const ModellerState& state);
  void start(ModellerState& state);
  void finish(Phase phase, std::string message);

  bool open_ = false, justOpened_ = false;
  std::string pattern_ = "frames/frame_%04d.png";
  int first_ = 0, last_ = 0, width_ = 0, height_ = 0;
  std::int64_t samples_ = 0;
  Phase phase_ = Phase::Options;
  std::thread worker_;
  std::atomic<bool> running_{false}, cancel_{false};
  std::atomic<double> progress_{0.0};  // over all frames
  std::atomic<int> framesDone_{0};
  int frameCount_ = 0;
  mutable std::mutex mutex_;
  Phase result_ = Phase::Options;
  std::string resultMessage_, message_, lastFile_;
  bool haveResult_ = false;
};

}  // namespace gridifs::ui
