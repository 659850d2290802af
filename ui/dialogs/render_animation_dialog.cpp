#include "ui/dialogs/render_animation_dialog.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "base/command_line_executable.h"
#include "base/errors.h"
#include "base/text_format.h"
#include "farm/farm_job.h"
#include "job/animation_frames.h"
#include "job/prepared_render.h"
#include "render/chaos_renderer.h"
#include "render/image_file.h"
#include "ui/base/widgets.h"
#include "ui/panels/timeline_panel.h"

namespace gridifs::ui {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxFrames = 100000;

}  // namespace

void RenderAnimationDialog::openFor(const ModellerState& state) {
  startLoadingImageWriter();  // the frames are written through it; load it while the artist decides
  const Project& project = state.document.project();
  const AnimationSettings a = timelineOf(project);
  if (!running()) {
    first_ = int(std::lround(a.start * a.fps));
    last_ = int(std::lround(a.end * a.fps));
    width_ = project.render.width;
    height_ = project.render.height;
    samples_ = renderSampleCount(project.render);
    motionBlur_ = a.motion_blur;
    motionFade_ = a.motion_fade;
    if (!state.document.path().empty()) {
      const fs::path folder = state.document.path().parent_path() / (state.document.path().stem().string() + "_frames");
      pattern_ = (folder / (state.document.path().stem().string() + "_%04d.png")).string();
      farmDir_ = (state.document.path().parent_path() / (state.document.path().stem().string() + "_farm")).string();
    }
    slurm_ = slurmAvailable();
    farmStatus_.clear();
    phase_ = TaskPhase::Options;
    message_.clear();
  }
  open_ = justOpened_ = true;
}

void RenderAnimationDialog::start(ModellerState& state) {
  message_.clear();
  // What can fail fast fails here, inline, before the thread starts.
  if (auto problem = checkFramePattern(pattern_)) {
    message_ = "Cannot render: " + *problem + ".";
    return;
  }
  if (last_ < first_) {
    message_ = "Cannot render: the last frame comes before the first.";
    return;
  }
  if (last_ - first_ + 1 > kMaxFrames) {
    message_ = "Cannot render: more than 100000 frames.";
    return;
  }
  const fs::path firstFile = frameFileName(pattern_, first_);
  const fs::path folder = firstFile.parent_path().empty() ? fs::path(".") : firstFile.parent_path();
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (!fs::is_directory(folder, ec)) {
    message_ = "Cannot render: the folder " + folder.string() + " cannot be made.";
    return;
  }
  Project project = state.document.project();
  project.render.width = width_;
  project.render.height = height_;
  project.render.samples = samples_;
  project.render.quality.reset();  // the dialog's sample count is the one asked for
  AnimationSettings animation = timelineOf(project);
  animation.motion_blur = motionBlur_;
  animation.motion_fade = motionFade_;
  project.animation = animation;
  try {
    checkRenderOutput(project, RenderJobOptions{});
  } catch (const ModelError& e) {
    message_ = std::string("Cannot render: ") + e.what();
    return;
  }
  const std::string pattern = pattern_;
  const long first = first_, last = last_;
  const fs::path projectFolder = state.document.path().parent_path();
  const std::string source = state.document.path().filename().string();
  const int threads = state.renderThreads;
  framesDone_ = 0;
  frameCount_ = int(last - first + 1);
  phase_ = TaskPhase::Running;
  task_.start(
      [this, project, pattern, first, last, projectFolder, source, threads](JobContext& context) -> TaskOutcome {
        const double count = double(last - first + 1);
        long frame = first;
        try {
          for (; frame <= last; ++frame) {
            const double done = double(frame - first);
            renderAnimationFrame(project, frame, frameFileName(pattern, frame), threads, projectFolder, source,
                                 [&](double f) {
                                   context.progress((done + f) / count);
                                   return !context.stopRequested();
                                 });
            ++framesDone_;
          }
          return {TaskPhase::Done, "Rendered " + std::to_string(last - first + 1) +
                                       " frames: " + frameFileName(pattern, first) + " … " +
                                       fs::path(frameFileName(pattern, last)).filename().string() + "."};
        } catch (const RenderCancelled&) {
          return {TaskPhase::Cancelled, "Cancelled at frame " + std::to_string(frame) + "; " +
                                            std::to_string(frame - first) + " frames were written, frame " +
                                            std::to_string(frame) + " was not."};
        } catch (const std::exception& e) {
          return {TaskPhase::Failed, "Frame " + std::to_string(frame) + ": " + e.what()};
        }
      });
}

void RenderAnimationDialog::draw(ModellerState& state) {
  if (task_.poll(phase_, message_)) {
    if (phase_ == TaskPhase::Done)
      state.info(message_);
    else
      state.error(message_);
  }
  if (state.showRenderAnimation) {
    state.showRenderAnimation = false;
    openFor(state);
  }
  if (!open_) return;
  bool keepOpen = true;
  if (!beginTaskModal("Render animation###renderanimation", 36.0f, running(), open_, justOpened_, keepOpen)) return;
  const float em = ImGui::GetFontSize();
  const bool busy = running();
  const AnimationSettings a = timelineOf(state.document.project());
  ImGui::BeginDisabled(busy);
  ImGui::SetNextItemWidth(-em * 6.0f);
  ImGui::InputText("Output", &pattern_);
  state.probe.item("animation.output");
  contextHelp(state, "Numbered image files: %04d becomes the frame number (frame_0000.png, frame_0001.png, ...)");
  ImGui::SetNextItemWidth(em * 10.0f);
  int range[2] = {first_, last_};
  if (ImGui::InputInt2("Frames", range)) {
    first_ = range[0];
    last_ = range[1];
  }
  state.probe.item("animation.frames");
  ImGui::SetNextItemWidth(em * 10.0f);
  int size[2] = {width_, height_};
  if (ImGui::InputInt2("Size", size)) {
    width_ = std::clamp(size[0], 1, 8192);
    height_ = std::clamp(size[1], 1, 8192);
  }
  state.probe.item("animation.size");
  ImGui::SetNextItemWidth(em * 10.0f);
  const std::int64_t step = 100'000, fast = 1'000'000;
  ImGui::InputScalar("Samples per frame", ImGuiDataType_S64, &samples_, &step, &fast);
  samples_ = std::clamp<std::int64_t>(samples_, 1, std::int64_t(1) << 40);
  state.probe.item("animation.samples");
  drawMotionBlur(state);
  ImGui::EndDisabled();

  // The plan.
  const long frames = long(last_) - long(first_) + 1;
  ImGui::Spacing();
  if (frames >= 1) {
    ImGui::TextWrapped("%ld frame%s at %.3g fps: t = %.3f s to %.3f s, %d x %d, %.3g M samples each (%.3g M in all).",
                       frames, frames == 1 ? "" : "s", a.fps, first_ / a.fps, last_ / a.fps, width_, height_,
                       double(samples_) / 1e6, double(samples_) * double(frames) / 1e6);
    if (!checkFramePattern(pattern_))
      ImGui::TextDisabled("%s",
                          (frameFileName(pattern_, first_) +
                           (frames > 1 ? " ... " + fs::path(frameFileName(pattern_, last_)).filename().string() : ""))
                              .c_str());
  } else {
    ImGui::TextWrapped("The last frame comes before the first.");
  }
  ImGui::TextDisabled("Display mode: %s (as the preview).", displayModeName(state.document.project().render.mode));

  drawFarm(state);
  if (busy) {
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "frame %d of %d", std::min(framesDone_.load() + 1, frameCount_),
                  frameCount_);
    ImGui::ProgressBar(float(task_.progress()), ImVec2(-em * 7.0f, 0), overlay);
    state.probe.item("animation.progress");
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(-1, 0))) task_.cancel();
    state.probe.item("animation.cancel");
  } else {
    if (!farm_) {
      if (ImGui::Button("Render", ImVec2(em * 7.0f, 0))) start(state);
      state.probe.item("animation.render");
    } else {
      if (ImGui::Button("Write job", ImVec2(em * 7.0f, 0)) && writeFarm(state, false))
        message_ = "Wrote the job folder " + farmDir_ + (slurm_ ? "." : "; submit it on the cluster (docs/FARM.md).");
      state.probe.item("animation.farm_write");
      ImGui::SameLine();
      ImGui::BeginDisabled(!slurm_);
      if (ImGui::Button("Submit", ImVec2(em * 7.0f, 0))) writeFarm(state, true);
      ImGui::EndDisabled();
      state.probe.item("animation.farm_submit");
      ImGui::SameLine();
      if (ImGui::Button("Status", ImVec2(em * 7.0f, 0))) refreshFarmStatus();
      state.probe.item("animation.farm_status");
    }
    ImGui::SameLine();
    if (ImGui::Button("Close", ImVec2(em * 7.0f, 0))) {
      open_ = false;
      ImGui::CloseCurrentPopup();
    }
    state.probe.item("animation.close");
  }
  if (!message_.empty()) {
    const bool bad = phase_ == TaskPhase::Failed || message_.rfind("Cannot", 0) == 0;
    if (bad) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.35f, 1.0f));
    ImGui::TextWrapped("%s", message_.c_str());
    if (bad) ImGui::PopStyleColor();
  }
  endTaskModal(keepOpen, open_);
}

void RenderAnimationDialog::drawMotionBlur(ModellerState& state) {
  // Draves & Reckase 2003, §9: each frame sums time samples spread over the shutter; with a fade
  // the earlier ones are drawn dimmer, so the motion reads as having a direction.
  const float em = ImGui::GetFontSize();
  ImGui::SetNextItemWidth(em * 10.0f);
  if (ImGui::InputInt("Motion blur", &motionBlur_)) motionBlur_ = std::clamp(motionBlur_, 1, 256);
  state.probe.item("animation.motion_blur");
  contextHelp(state, "Time samples per frame, spread over the shutter (the samples are shared among them); 1: none");
  ImGui::BeginDisabled(motionBlur_ <= 1);
  ImGui::SetNextItemWidth(em * 10.0f);
  float fade = float(motionFade_);
  if (ImGui::SliderFloat("Motion fade", &fade, 0.0f, 8.0f, "%.2f")) motionFade_ = std::clamp(double(fade), 0.0, 16.0);
  state.probe.item("animation.motion_fade");
  contextHelp(state, "Directional motion blur: earlier time samples are drawn dimmer (0: uniform blur)");
  ImGui::EndDisabled();
}

void RenderAnimationDialog::drawFarm(ModellerState& state) {
  const float em = ImGui::GetFontSize();
  ImGui::Spacing();
  ImGui::BeginDisabled(running());
  ImGui::Checkbox("On a Slurm cluster", &farm_);
  state.probe.item("animation.farm");
  contextHelp(state,
              "Split every frame into parts that Slurm runs on the cluster's nodes, then merge them: "
              "the frames are the same images, bit for bit");
  if (farm_) {
    ImGui::SetNextItemWidth(em * 6.0f);
    if (ImGui::InputInt("Parts per frame", &farmParts_)) farmParts_ = std::clamp(farmParts_, 1, int(kMaxFarmParts));
    state.probe.item("animation.farm_parts");
    ImGui::SetNextItemWidth(-em * 6.0f);
    ImGui::InputText("Job folder", &farmDir_);
    state.probe.item("animation.farm_dir");
    contextHelp(state, "On a filesystem the cluster's nodes share, like the project and the output");
    ImGui::SetNextItemWidth(-em * 6.0f);
    ImGui::InputTextWithHint("sbatch", "--partition=render --time=2:00:00", &farmSbatch_);
    state.probe.item("animation.farm_sbatch");
    if (!slurm_) ImGui::TextDisabled("sbatch is not on the PATH here: write the job and submit it on the cluster.");
  }
  ImGui::EndDisabled();
  if (farm_ && !farmStatus_.empty()) {
    // describeFarmStatus: one line per frame, then the summary and the queued jobs. The summary
    // first; the frames in a box of their own, which scrolls for long animations.
    std::size_t frames = 0;
    while (frames < farmStatus_.size() &&
           (farmStatus_[frames].rfind("frame ", 0) == 0 || farmStatus_[frames].rfind("still", 0) == 0))
      ++frames;
    for (std::size_t i = frames; i < farmStatus_.size(); ++i) ImGui::TextWrapped("%s", farmStatus_[i].c_str());
    const float lines = float(std::min<std::size_t>(frames, 8));
    ImGui::BeginChild("farmframes", ImVec2(0, lines * ImGui::GetTextLineHeightWithSpacing() + em * 0.5f), true);
    for (std::size_t i = 0; i < frames; ++i) ImGui::TextUnformatted(farmStatus_[i].c_str());
    ImGui::EndChild();
  }
}

bool RenderAnimationDialog::writeFarm(ModellerState& state, bool submit) {
  message_.clear();
  // The tasks render the file on disk, so it must hold what the artist sees.
  if (state.document.path().empty() || state.document.dirty()) {
    message_ = "Cannot write the job: save the project first (the cluster renders the saved file).";
    return false;
  }
  if (auto problem = checkFramePattern(pattern_)) {
    message_ = "Cannot write the job: " + *problem + ".";
    return false;
  }
  FarmRequest request;
  request.project = state.document.path();
  request.output = pattern_;
  request.firstFrame = first_;
  request.lastFrame = last_;
  request.parts = farmParts_;
  request.dir = farmDir_;
  request.renderOptions = {"--width",   std::to_string(width_),  "--height", std::to_string(height_),
                           "--samples", std::to_string(samples_)};
  if (motionBlur_ > 1) {
    request.renderOptions.insert(request.renderOptions.end(), {"--motion-blur", std::to_string(motionBlur_)});
    if (motionFade_ > 0.0)
      request.renderOptions.insert(request.renderOptions.end(), {"--motion-fade", std::to_string(motionFade_)});
  }
  std::istringstream words(farmSbatch_);
  for (std::string w; words >> w;) request.sbatchOptions.push_back(w);
  std::error_code ec;
  request.executable = commandLineExecutable(ec);
  const fs::path outputs = fs::path(frameFileName(pattern_, first_)).parent_path();
  if (!outputs.empty()) fs::create_directories(outputs, ec);
  try {
    writeFarmJob(request);
    if (submit) {
      const FarmPlan plan = planFarm(readFarmStatus(farmDir_, false, PartCheck::WholeData));
      const std::vector<std::string> jobs = submitFarm(farmDir_, plan);
      message_ = jobs.empty() ? "Nothing to submit: every part is rendered and every frame merged."
                              : "Submitted " + std::to_string(jobs.size()) + " job" + (jobs.size() == 1 ? "" : "s") +
                                    " (" + jobs.front() + (jobs.size() > 1 ? ", ..." : "") + ").";
      state.info(message_);
    }
  } catch (const std::exception& e) {
    message_ = std::string("Cannot write the job: ") + e.what();
    return false;
  }
  refreshFarmStatus();
  return true;
}

void RenderAnimationDialog::refreshFarmStatus() {
  try {
    farmStatus_ = describeFarmStatus(readFarmStatus(farmDir_, slurm_));
  } catch (const std::exception& e) {
    farmStatus_ = {e.what()};
  }
}

nlohmann::json RenderAnimationDialog::probeJson() const {
  return {{"open", open_},
          {"farm_status", farmStatus_},
          {"running", running()},
          {"phase", taskPhaseName(phase_)},
          {"progress", task_.progress()},
          {"frames_done", framesDone_.load()},
          {"output", pattern_},
          {"message", message_}};
}

}  // namespace gridifs::ui
