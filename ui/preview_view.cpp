#include "ui/preview_view.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "edit/view_camera.h"
#include "ui/widgets.h"

namespace gridifs::ui {

void PreviewView::build(ModellerState& state, EditQueue& edits, float framebufferScale) {
  framebufferScale_ = framebufferScale;
  visible_ = false;
  const Project& project = state.document.project();

  // Toolbar.
  if (ImGui::Button(state.previewPaused ? "Resume" : "Pause", ImVec2(ImGui::GetFontSize() * 4.5f, 0)))
    state.previewPaused = !state.previewPaused;
  state.probe.item("preview.pause");
  contextHelp(state, "Pause or resume the background renderer (Space)");
  ImGui::SameLine();
  if (ImGui::Button("Restart")) renderer_.forceRestart();
  contextHelp(state, "Start the chaos game again from scratch");
  ImGui::SameLine();
  static const std::int64_t budgets[] = {1'000'000, 4'000'000, 20'000'000, 100'000'000, 1'000'000'000};
  static const char* budgetNames[] = {"1M points", "4M points", "20M points", "100M points", "1G points"};
  int current = -1;
  for (int i = 0; i < 5; ++i)
    if (budgets[i] == project.render.samples) current = i;
  char preview[32];
  std::snprintf(preview, sizeof preview, "%.3gM points", double(project.render.samples) / 1e6);
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.5f);
  if (ImGui::BeginCombo("##budget", current >= 0 ? budgetNames[current] : preview)) {
    for (int i = 0; i < 5; ++i)
      if (ImGui::Selectable(budgetNames[i], i == current)) {
        const std::int64_t n = budgets[i];
        edits.commit("Sample budget", [n](Project& p) { p.render.samples = n; });
      }
    ImGui::EndCombo();
  }
  contextHelp(state, "Sample budget: how many chaos-game points the preview renders before it stops");
  ImGui::SameLine();
  double cue = project.render.depth_cue;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.0f);
  bool changed = sliderDouble("##cue", cue, 0.0, 1.0, "depth cue %.2f");
  gestureItem(edits, "Depth cue", changed, [cue](Project& p) { p.render.depth_cue = cue; });
  contextHelp(state, "Depth cueing (Gröller & Wegenkittl 1994, §3.1): 0 keeps colors, 1 fades the farthest points to black");
  ImGui::SameLine();
  float bg[3] = {float(project.render.background.x), float(project.render.background.y), float(project.render.background.z)};
  changed = ImGui::ColorEdit3("Background", bg, ImGuiColorEditFlags_NoInputs);
  gestureItem(edits, "Background", changed, [bg](Project& p) { p.render.background = Vec3(bg[0], bg[1], bg[2]); });
  contextHelp(state, "Background color of the preview and of renders");

  // Display mode and its controls (issues 5, 6: ui/preview_modes.cpp).
  modes_.buildToolbar(state, edits);

  // Progress.
  const RenderStats& s = state.previewStats;
  const float progress = s.budget > 0 ? float(std::min(1.0, s.progress())) : 0.0f;
  ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(0, 0));
  ImGui::ProgressBar(progress, ImVec2(-1, ImGui::GetFontSize() * 0.3f), "");
  ImGui::PopStyleVar();

  // Image.
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  size_ = glm::dvec2(std::max(avail.x, 16.0f), std::max(avail.y, 16.0f));
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  screenOrigin_ = glm::dvec2(origin.x, origin.y);
  visible_ = true;
  ImGui::InvisibleButton("##previewinput", ImVec2(float(size_.x), float(size_.y)),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight | ImGuiButtonFlags_MouseButtonMiddle);
  state.probe.item("preview.image");
  const bool hovered = ImGui::IsItemHovered();
  if (!state.previewError.empty())
    ImGui::GetWindowDrawList()->AddText(ImVec2(origin.x + 8, origin.y + 8), IM_COL32(255, 120, 100, 255),
                                        state.previewError.c_str());

  ImGuiIO& io = ImGui::GetIO();
  if (hovered) state.contextHelp = "Drag: orbit the preview camera · middle/Shift+drag: pan · wheel: zoom";
  orbit_.settleWheel(edits, state.now);
  if (hovered && io.MouseWheel != 0.0f && orbit_.motion() == OrbitController::Motion::None)
    orbit_.zoomProject(project.camera, edits, io.MouseWheel, state.now);
  const glm::dvec2 mouse(io.MousePos.x - origin.x, io.MousePos.y - origin.y);
  if (orbit_.motion() == OrbitController::Motion::None && hovered) {
    for (int b = 0; b < 3; ++b)
      if (ImGui::IsMouseClicked(b)) {
        orbit_.settleWheel(edits, -1.0);
        dragButton_ = b;
        dragMoved_ = false;
        orbit_.begin((b == 2 || io.KeyShift) ? OrbitController::Motion::Pan : OrbitController::Motion::Orbit,
                     project.camera, mouse);
        dragStart_ = mouse;
        break;
      }
  }
  if (orbit_.motion() != OrbitController::Motion::None) {
    if (ImGui::IsMouseDown(dragButton_)) {
      const bool firstMove = !dragMoved_ && glm::length(mouse - dragStart_) > 3.0;
      if (firstMove) dragMoved_ = true;
      if (dragMoved_) orbit_.dragProject(edits, mouse, ViewAxis::User, size_.y, firstMove);
    } else {
      if (dragMoved_) edits.end();
      orbit_.end();
    }
  }
}

void PreviewView::publish(ModellerState& state) {
  // The mesh mode shows F^n(A) instead: the chaos game waits (same generation) so the mesh builds faster.
  renderer_.setPaused(state.previewPaused || state.previewMode == PreviewMode::Mesh);
  const int w = int(std::lround(size_.x * framebufferScale_)), h = int(std::lround(size_.y * framebufferScale_));
  renderer_.publish(state.document, w, h, state.renderThreads);
  state.previewError = renderer_.error().empty() ? std::string() : "Preview stopped: " + renderer_.error();
  state.previewStats = renderer_.stats();
  state.previewDevice = renderer_.deviceName();
}

void PreviewView::render(ModellerState& state, ViewRenderer& renderer) {
  // While the workers fill the buffers, merge and upload at most ~20 times a second: the
  // picture still streams, and the UI keeps its frame budget for the artist's input. A new
  // generation (an edit) is shown at once.
  const RenderStats s = renderer_.stats();
  const bool newGeneration = s.generation != image_.generation;
  const bool due = newGeneration || s.done || state.now - lastFetch_ >= 0.05;
  const bool fetched = due && renderer_.fetch(image_) && image_.width > 0;
  if (fetched) lastFetch_ = state.now;
  // The display mode decides what the texture shows: the z-buffer image or the developed flame.
  if (modes_.updateTexture(state, image_, fetched, texture_)) needsDraw_ = true;
  const int w = int(std::lround(size_.x * framebufferScale_)), h = int(std::lround(size_.y * framebufferScale_));
  if (modes_.drawMesh(state, target_, w, h, visible_)) {  // F^n(A) drawn into the view's target
    needsDraw_ = true;  // the image is drawn again when the mode changes back
    return;
  }
  const Vec3 bg = state.document.project().render.background;
  if (w != target_.width() || h != target_.height() || !(bg == drawnBackground_)) needsDraw_ = true;
  if (!needsDraw_ || !visible_) return;
  target_.resize(w, h);
  renderer.drawImage(target_, texture_.id(), texture_.width(), texture_.height(), glm::vec3(bg));
  drawnBackground_ = bg;
  needsDraw_ = false;
}

void PreviewView::present(int framebufferHeight) const {
  if (!visible_) return;
  const int x = int(std::lround(screenOrigin_.x * framebufferScale_));
  const int top = int(std::lround(screenOrigin_.y * framebufferScale_));
  target_.blitTo(x, framebufferHeight - top - target_.height());
}

}  // namespace gridifs::ui
