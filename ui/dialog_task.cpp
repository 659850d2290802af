#include "ui/dialog_task.h"

#include <imgui.h>

namespace gridifs::ui {

const char* taskPhaseName(TaskPhase phase) {
  static const char* names[] = {"options", "running", "done", "failed", "cancelled"};
  return names[int(phase)];
}

DialogTask::~DialogTask() {
  cancel_ = true;
  join();
}

void DialogTask::join() {
  if (worker_.joinable()) worker_.join();
}

void DialogTask::start(std::function<void()> work) {
  join();
  cancel_ = false;
  progress_ = 0.0;
  {
    std::lock_guard lock(mutex_);
    haveResult_ = false;
  }
  running_ = true;
  worker_ = std::thread(std::move(work));
}

void DialogTask::finish(TaskPhase phase, std::string message) {
  std::lock_guard lock(mutex_);
  result_ = phase;
  resultMessage_ = std::move(message);
  haveResult_ = true;
  running_ = false;
}

bool DialogTask::poll(TaskPhase& phase, std::string& message) {
  bool finished = false;
  {
    std::lock_guard lock(mutex_);
    if (haveResult_) {
      haveResult_ = false;
      phase = result_;
      message = resultMessage_;
      finished = true;
    }
  }
  if (!running()) join();
  return finished;
}

bool beginTaskModal(const char* title, float widthEm, bool busy, bool& open, bool& justOpened, bool& keepOpen) {
  if (justOpened) {
    ImGui::OpenPopup(title);
    justOpened = false;
  }
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float width = ImGui::GetFontSize() * widthEm;
  ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + vp->WorkSize.x * 0.5f, vp->WorkPos.y + vp->WorkSize.y * 0.5f),
                          ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  // Fixed width, height fitted to the contents (plans and messages wrap).
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0), ImVec2(width, vp->WorkSize.y * 0.9f));
  keepOpen = true;
  if (!ImGui::BeginPopupModal(title, busy ? nullptr : &keepOpen, ImGuiWindowFlags_AlwaysAutoResize)) {
    if (!busy) open = false;
    return false;
  }
  return true;
}

void endTaskModal(bool keepOpen, bool& open) {
  ImGui::EndPopup();
  if (!keepOpen) open = false;
}

}  // namespace gridifs::ui
