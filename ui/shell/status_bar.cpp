// The status line (Gröller & Wegenkittl 1994, §4.2: "a status line, which contains context dependent
// information"): points rendered, points/s, function count, the hovered control's help, and
// the last message.
#include <imgui.h>

#include <cstdio>
#include <string>

#include "ui/shell/app_commands.h"

namespace gridifs::ui {
namespace {

std::string humanCount(double n) {
  char text[32];
  if (n >= 1e9)
    std::snprintf(text, sizeof text, "%.2fG", n / 1e9);
  else if (n >= 1e6)
    std::snprintf(text, sizeof text, "%.2fM", n / 1e6);
  else if (n >= 1e3)
    std::snprintf(text, sizeof text, "%.1fk", n / 1e3);
  else
    std::snprintf(text, sizeof text, "%.0f", n);
  return text;
}

/// `text` cut to `width` pixels with an ellipsis, on a UTF-8 character boundary: the status line
/// has no scroll bar, so a long hint on a narrow window ends visibly instead of mid-word at the edge.
std::string fitText(const std::string& text, float width) {
  if (ImGui::CalcTextSize(text.c_str()).x <= width) return text;
  std::string cut = text;
  while (!cut.empty()) {
    while (!cut.empty() && (static_cast<unsigned char>(cut.back()) & 0xC0) == 0x80) cut.pop_back();
    if (!cut.empty()) cut.pop_back();  // the character's lead byte, or one ASCII character
    if (ImGui::CalcTextSize((cut + "…").c_str()).x <= width) break;
  }
  return cut + "…";
}

}  // namespace

void drawStatusBar(ModellerState& state, float height) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x, vp->Pos.y + vp->Size.y - height));
  ImGui::SetNextWindowSize(ImVec2(vp->Size.x, height));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1.0f, 1.0f));  // thinner than a window's 32 px minimum
  ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0.0f);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding,
                      ImVec2(ImGui::GetFontSize() * 0.6f, (height - ImGui::GetFontSize()) * 0.5f));
  ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.075f, 0.08f, 0.09f, 1.0f));
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoBringToFrontOnFocus |
                   ImGuiWindowFlags_NoScrollWithMouse);
  state.probe.window("panel.status");
  const RenderStats& s = state.previewStats;
  const auto& functions = state.document.project().functions;
  int active = 0;
  for (const Function& f : functions) active += f.muted ? 0 : 1;
  const char* phase = s.paused ? "paused" : s.done ? "done" : "rendering";
  if (!state.volumeStatus.empty()) {
    // The volume mode computes the measure attractor instead of the chaos game's picture, and the
    // chaos game is paused meanwhile: its point count would read as a stalled render.
    ImGui::TextColored(ImVec4(0.6f, 0.8f, 0.95f, 1.0f), "%s", state.volumeStatus.c_str());
    ImGui::SameLine();
    ImGui::Text(" ·  %d function%s", active, active == 1 ? "" : "s");
  } else {
    ImGui::TextColored(s.done ? ImVec4(0.55f, 0.8f, 0.55f, 1.0f) : ImVec4(0.95f, 0.75f, 0.35f, 1.0f), "%s", phase);
    ImGui::SameLine();
    ImGui::Text("%s points  ·  %s pts/s  ·  %s  ·  %d function%s", humanCount(double(s.samples)).c_str(),
                humanCount(s.pointsPerSecond).c_str(), state.previewDevice.compare(0, 3, "gpu") == 0 ? "GPU" : "CPU",
                active, active == 1 ? "" : "s");
    if (ImGui::IsItemHovered()) state.contextHelp = "Preview renderer: " + state.previewDevice;
  }
  ImGui::SameLine();
  ImGui::TextDisabled("  |  ");
  ImGui::SameLine();
  // Messages fade after a while (errors stay longer); dialogs keep the full text meanwhile.
  const bool recentMessage =
      !state.statusText.empty() && state.now - state.statusTime < (state.statusIsError ? 15.0 : 6.0);
  if (recentMessage && (state.contextHelp.empty() || state.statusIsError)) {
    ImGui::TextColored(state.statusIsError ? ImVec4(1.0f, 0.45f, 0.35f, 1.0f) : ImVec4(0.6f, 0.85f, 1.0f, 1.0f), "%s",
                       fitText(state.statusText, ImGui::GetContentRegionAvail().x).c_str());
  } else if (!state.contextHelp.empty()) {
    ImGui::TextDisabled("%s", fitText(state.contextHelp, ImGui::GetContentRegionAvail().x).c_str());
  } else {
    ImGui::TextDisabled("F1: shortcuts");
  }
  ImGui::End();
  ImGui::PopStyleColor();
  ImGui::PopStyleVar(4);
}

}  // namespace gridifs::ui
