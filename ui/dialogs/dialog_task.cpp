#include "ui/dialogs/dialog_task.h"

#include <imgui.h>

namespace gridifs::ui {

const char* taskPhaseName(TaskPhase phase) {
  static const char* names[] = {"options", "running", "done", "failed", "cancelled"};
  return names[int(phase)];
}

void DialogTask::start(Work work) { job_.submit(std::move(work)); }

bool DialogTask::poll(TaskPhase& phase, std::string& message) {
  auto outcome = job_.poll();
  if (!outcome) return false;
  phase = outcome->value.phase;
  message = std::move(outcome->value.message);
  return true;
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
