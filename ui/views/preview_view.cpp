#include "ui/views/preview_view.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "edit/view_camera.h"
#include "render/camera.h"
#include "schema/settings_tables.h"
#include "ui/base/widgets.h"
#include "ui/panels/setting_slider.h"
#include "ui/panels/timeline_panel.h"

namespace gridifs::ui {

void PreviewView::build(ModellerState& state, EditQueue& edits, float framebufferScale) {
  framebufferScale_ = framebufferScale;
  visible_ = false;
  buildToolbar(state, edits);
  // Display mode and its controls (ui/views/preview_modes.cpp).
  modes_.buildToolbar(state, edits);

  // Progress.
  const RenderStats& s = state.previewStats;
  const float progress = s.budget > 0 ? float(std::min(1.0, s.progress())) : 0.0f;
  ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(0, 0));
  ImGui::ProgressBar(progress, ImVec2(-1, ImGui::GetFontSize() * 0.3f), "");
  ImGui::PopStyleVar();

  const bool hovered = buildImage(state);
  handleMouse(state, edits, hovered);
}

void PreviewView::buildToolbar(ModellerState& state, EditQueue& edits) {
  const Project& project = state.document.project();
  if (ImGui::Button(state.previewPaused ? "Resume" : "Pause", ImVec2(ImGui::GetFontSize() * 4.5f, 0)))
    state.previewPaused = !state.previewPaused;
  state.probe.item("preview.pause");
  contextHelp(state, "Pause or resume the background renderer (Space)");
  ImGui::SameLine();
  if (ImGui::Button("Restart")) renderer_.forceRestart();
  contextHelp(state, "Start the chaos game again from scratch");
  ImGui::SameLine();
  if (ImGui::Button("Camera")) state.showCamera = !state.showCamera;
  state.probe.item("preview.camera");
  contextHelp(state,
              "The camera's projection (perspective, orthographic, fisheye dome, 360° panorama), orbit and stereo");
  ImGui::SameLine();
  static const std::int64_t budgets[] = {1'000'000, 4'000'000, 20'000'000, 100'000'000, 1'000'000'000};
  static const char* budgetNames[] = {"1M points", "4M points", "20M points", "100M points", "1G points"};
  int current = -1;
  for (int i = 0; i < 5; ++i)
    if (budgets[i] == project.render.samples) current = i;
  char preview[32];
  if (project.render.quality) {
    current = -1;  // a quality (samples per pixel) decides, not one of the budgets
    std::snprintf(preview, sizeof preview, "%.4g / pixel", *project.render.quality);
  } else {
    std::snprintf(preview, sizeof preview, "%.3gM points", double(project.render.samples) / 1e6);
  }
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.5f);
  if (ImGui::BeginCombo("##budget", current >= 0 ? budgetNames[current] : preview)) {
    for (int i = 0; i < 5; ++i)
      if (ImGui::Selectable(budgetNames[i], i == current)) {
        const std::int64_t n = budgets[i];
        edits.commit(SetSampleBudget{n});
      }
    ImGui::EndCombo();
  }
  contextHelp(state, "Sample budget: how many chaos-game points the preview renders before it stops");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.0f);
  settingSlider(state, edits, renderSettingsTable(), "render", "depth_cue", project.render,
                {.id = "##cue", .probe = "preview"});
  ImGui::SameLine();
  const SettingSpec& background = renderSettingsTable().field("background");
  float bg[3] = {float(project.render.background.x), float(project.render.background.y),
                 float(project.render.background.z)};
  const bool changed = ImGui::ColorEdit3(background.label, bg, ImGuiColorEditFlags_NoInputs);
  gestureItem(edits, background.label, changed, SetBackground{Vec3(bg[0], bg[1], bg[2])});
  contextHelp(state, background.tooltip);
}

bool PreviewView::buildImage(ModellerState& state) {
  // Above the timeline.
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  size_ = glm::dvec2(std::max(avail.x, 16.0f), std::max(avail.y - timelinePanelHeight(state), 16.0f));
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  screenOrigin_ = glm::dvec2(origin.x, origin.y);
  visible_ = true;
  ImGui::InvisibleButton(
      "##previewinput", ImVec2(float(size_.x), float(size_.y)),
      ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight | ImGuiButtonFlags_MouseButtonMiddle);
  state.probe.item("preview.image");
  const bool hovered = ImGui::IsItemHovered();
  // The volume mode does not show the chaos game (which cannot run a median function's sets).
  if (!error_.empty() && state.previewMode != PreviewMode::Volume)
    ImGui::GetWindowDrawList()->AddText(ImVec2(origin.x + 8, origin.y + 8), IM_COL32(255, 120, 100, 255),
                                        error_.c_str());
  if (const std::string message = modes_.overlayMessage(state); !message.empty()) {
    ImGui::GetWindowDrawList()->AddText(nullptr, 0.0f, ImVec2(origin.x + 8, origin.y + 8 + ImGui::GetFontSize() * 1.4f),
                                        IM_COL32(255, 120, 100, 255), message.c_str(), nullptr, float(size_.x) - 16.0f);
    state.probe.item("preview.message");
  }
  return hovered;
}

void PreviewView::handleMouse(ModellerState& state, EditQueue& edits, bool hovered) {
  const Project& project = state.document.project();
  const ImVec2 origin(float(screenOrigin_.x), float(screenOrigin_.y));
  ImGuiIO& io = ImGui::GetIO();
  // The volume mode is lit by the same key light: Alt+drag turns it there too.
  const bool shaded = (state.previewMode == PreviewMode::Shaded || state.previewMode == PreviewMode::Volume) &&
                      !project.render.shading.lights.empty();
  if (shaded) drawLightGizmo(state, origin);
  drawProjectionOutline(state, origin);
  if (hovered)
    state.contextHelp = shaded ? "Drag: orbit · middle/Shift+drag: pan · wheel: zoom · Alt+drag: move the key light"
                               : "Drag: orbit the preview camera · middle/Shift+drag: pan · wheel: zoom";
  orbit_.settleWheel(edits, state.now);
  const bool idle = orbit_.motion() == OrbitController::Motion::None && !lightDrag_;
  if (hovered && io.MouseWheel != 0.0f && idle) orbit_.zoomProject(project.camera, edits, io.MouseWheel, state.now);
  const glm::dvec2 mouse(io.MousePos.x - origin.x, io.MousePos.y - origin.y);
  if (idle && hovered) {
    for (int b = 0; b < 3; ++b)
      if (ImGui::IsMouseClicked(b)) {
        orbit_.settleWheel(edits, -1.0);
        dragButton_ = b;
        dragMoved_ = false;
        dragStart_ = mouse;
        if (b == 0 && io.KeyAlt && shaded) {
          lightDrag_ = true;
          dragLight_ = project.render.shading.lights[0].direction;
        } else {
          orbit_.begin((b == 2 || io.KeyShift) ? OrbitController::Motion::Pan : OrbitController::Motion::Orbit,
                       project.camera, mouse);
        }
        break;
      }
  }
  if (lightDrag_)
    dragKeyLight(edits, mouse);
  else if (orbit_.motion() != OrbitController::Motion::None)
    dragCamera(edits, mouse);
}

void PreviewView::dragKeyLight(EditQueue& edits, glm::dvec2 mouse) {
  if (ImGui::IsMouseDown(dragButton_)) {
    const glm::dvec2 delta = mouse - dragStart_;
    if (!dragMoved_ && glm::length(delta) > 3.0) {
      dragMoved_ = true;
      edits.begin("Move key light");
    }
    if (dragMoved_) {
      // The key light turns with the mouse: right/left about the vertical axis, up/down in elevation.
      const double length = glm::length(dragLight_);
      const double azimuth = std::atan2(dragLight_.y, dragLight_.x) - delta.x * 0.01;
      double elevation = std::asin(std::clamp(dragLight_.z / length, -1.0, 1.0)) - delta.y * 0.01;
      elevation = std::clamp(elevation, -1.55, 1.5705);
      const Vec3 direction(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                           std::sin(elevation));
      edits.update(SetLightDirection{0, direction});
    }
  } else {
    if (dragMoved_) edits.end();
    lightDrag_ = false;
  }
}

void PreviewView::dragCamera(EditQueue& edits, glm::dvec2 mouse) {
  if (ImGui::IsMouseDown(dragButton_)) {
    const bool firstMove = !dragMoved_ && glm::length(mouse - dragStart_) > 3.0;
    if (firstMove) dragMoved_ = true;
    if (dragMoved_) orbit_.dragProject(edits, mouse, ViewAxis::User, size_.y, firstMove);
  } else {
    if (dragMoved_) edits.end();
    orbit_.end();
  }
}

void PreviewView::drawProjectionOutline(ModellerState& state, ImVec2 origin) const {
  // A fisheye's circle (a dome master's edge) and the line between stereo eyes, over the picture
  // the renderer draws at the view's size.
  const Camera& camera = state.document.project().camera;
  if (camera.projection != CameraProjection::Fisheye && !camera.stereo) return;
  const int w = std::max(1, int(std::lround(size_.x))), h = std::max(1, int(std::lround(size_.y)));
  try {
    const OrbitCamera orbit(camera, w, h);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImU32 colour = IM_COL32(255, 255, 255, 90);
    for (int eye = 0; eye < orbit.eyes(); ++eye) {
      const EyeRegion r = orbit.eyeRegion(eye);
      if (camera.projection == CameraProjection::Fisheye) {
        const float radius = float(orbit.pixelsPerRadian() * camera.fov * M_PI / 360.0);
        draw->AddCircle(ImVec2(origin.x + float(r.x + 0.5 * r.width), origin.y + float(r.y + 0.5 * r.height)), radius,
                        colour, 96, 1.0f);
      }
      if (eye == 1) {
        const bool sideBySide = r.x > 0;
        draw->AddLine(ImVec2(origin.x + float(r.x), origin.y + float(r.y)),
                      ImVec2(origin.x + float(sideBySide ? r.x : w), origin.y + float(sideBySide ? h : r.y)), colour,
                      1.0f);
      }
    }
  } catch (const ModelError&) {
    // An unusable camera: the preview says why.
  }
}

void PreviewView::drawLightGizmo(ModellerState& state, ImVec2 origin) const {
  // The key light as seen from the camera: a line from the image centre towards the light, a
  // filled sun where the light is in front of the view, an outline where it is behind.
  const Project& project = state.document.project();
  const OrbitCamera camera(project.camera, 64, 64);
  const glm::dvec4 v = camera.view() * glm::dvec4(project.render.shading.lights[0].direction, 0.0);
  const double length = glm::length(glm::dvec3(v));
  if (!(length > 0.0)) return;
  const float radius = float(std::min(size_.x, size_.y) * 0.12);
  const ImVec2 centre(origin.x + float(size_.x) - radius * 1.4f, origin.y + radius * 1.4f);
  const ImVec2 sun(centre.x + float(v.x / length) * radius, centre.y - float(v.y / length) * radius);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImU32 colour = lightDrag_ ? IM_COL32(255, 230, 120, 255) : IM_COL32(255, 220, 120, 170);
  draw->AddCircle(centre, radius, IM_COL32(255, 255, 255, 60), 48, 1.0f);
  draw->AddLine(centre, sun, colour, 1.5f);
  if (v.z >= 0.0)
    draw->AddCircleFilled(sun, radius * 0.12f + 2.0f, colour);
  else
    draw->AddCircle(sun, radius * 0.12f + 2.0f, colour, 16, 1.5f);
}

void PreviewView::publish(ModellerState& state) {
  // The mesh and volume modes show F^n(A) or the measure attractor instead: the chaos game waits
  // (same generation) so that their own workers have the cores.
  renderer_.setPaused(state.previewPaused || state.previewMode == PreviewMode::Mesh ||
                      state.previewMode == PreviewMode::Volume);
  const int w = int(std::lround(size_.x * framebufferScale_)), h = int(std::lround(size_.y * framebufferScale_));
  renderer_.publish(state.document, w, h, state.renderThreads);
  error_ = renderer_.error().empty() ? std::string() : "Preview stopped: " + renderer_.error();
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
    needsDraw_ = true;                                    // the image is drawn again when the mode changes back
    return;
  }
  if (modes_.drawVolume(state, target_, renderer, w, h, visible_, dragging())) {  // the ray-marched measure attractor
    needsDraw_ = true;
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
