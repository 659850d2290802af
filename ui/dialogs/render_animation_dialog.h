#pragma once
// File › Render animation…: the plan (frames A..B, their times, size, samples, output names),
// the render of every frame on a worker thread with a progress bar over all frames that can be
// cancelled, each frame written atomically (core/job/animation_frames.h). The worker renders a copy of
// the project taken when it starts, so the artist may go on editing. Or, on a Slurm cluster, the
// same frames split into parts: the job folder written (core/farm/farm_job.h), submitted when
// sbatch is on the PATH, and the folder's status shown.
#include <atomic>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ui/base/modeller_state.h"
#include "ui/dialogs/dialog_task.h"

namespace gridifs::ui {

class RenderAnimationDialog {
 public:
  RenderAnimationDialog() = default;
  RenderAnimationDialog(const RenderAnimationDialog&) = delete;
  RenderAnimationDialog& operator=(const RenderAnimationDialog&) = delete;

  /// Opens when state.showRenderAnimation is set (File menu); call every frame at top level.
  void draw(ModellerState& state);
  bool running() const { return task_.running(); }
  nlohmann::json probeJson() const;

 private:
  void openFor(const ModellerState& state);
  void start(ModellerState& state);
  void drawMotionBlur(ModellerState& state);
  void drawFarm(ModellerState& state);
  /// Writes the job folder of the current settings (and submits it); false with message_ set.
  bool writeFarm(ModellerState& state, bool submit);
  void refreshFarmStatus();

  bool open_ = false, justOpened_ = false;
  std::string pattern_ = "frames/frame_%04d.png";
  int first_ = 0, last_ = 0, width_ = 0, height_ = 0;
  std::int64_t samples_ = 0;
  int motionBlur_ = 1;       // time samples per frame (Draves & Reckase 2003, §9)
  double motionFade_ = 0.0;  // directional motion blur: earlier time samples dimmer
  TaskPhase phase_ = TaskPhase::Options;
  std::atomic<int> framesDone_{0};
  int frameCount_ = 0;
  std::string message_, lastFile_;
  // The render farm (Slurm): parts per frame, the job folder, extra #SBATCH options.
  bool farm_ = false, slurm_ = false;
  int farmParts_ = 4;
  std::string farmDir_, farmSbatch_;
  std::vector<std::string> farmStatus_;
  DialogTask task_;  // progress over all frames; last: destroyed first, it joins the worker
};

}  // namespace gridifs::ui
