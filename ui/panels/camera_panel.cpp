// The Camera panel: the preview camera's projection (perspective, orthographic, fisheye for
// planetarium domes, equirectangular for 360° video), its orbit and field of view as keyable
// sliders, and the stereo pair. Each slider drag is one undo step (SetCamera); the ranges, labels
// and help come from the camera's settings tables.
#include <imgui.h>

#include <algorithm>
#include <string_view>

#include "edit/settings_edits.h"
#include "schema/settings_tables.h"
#include "ui/base/widgets.h"
#include "ui/panels/key_button.h"
#include "ui/panels/panels.h"
#include "ui/panels/setting_slider.h"

namespace gridifs::ui {
namespace {

/// A choice of `spec` as a combo box; returns the chosen index when it changed.
std::optional<int> choiceCombo(ModellerState& state, const SettingSpec& spec, int current, const char* probe) {
  std::optional<int> chosen;
  const std::vector<const char*>& labels = spec.choices->labels;
  if (ImGui::BeginCombo(spec.label, labels[std::size_t(current)])) {
    for (std::size_t i = 0; i < labels.size(); ++i)
      if (ImGui::Selectable(labels[i], int(i) == current) && int(i) != current) chosen = int(i);
    ImGui::EndCombo();
  }
  state.probe.item(probe);
  contextHelp(state, spec.tooltip);
  return chosen;
}

/// A slider of the camera's number `key` over its table's slider range, with a key button when
/// `keyable`: roll, the lens shift and the lens blur are written only when set, so they have no
/// track until they differ from 0.
void cameraSlider(ModellerState& state, EditQueue& edits, const Camera& camera, const char* key, bool keyable = true) {
  const SettingSpec& spec = cameraTable().field(key);
  double value = spec.number(&camera);
  ImGui::PushID(key);
  if (keyable) {
    keyButton(state, edits, std::string("camera.") + key, &value);
    ImGui::SameLine();
  }
  ImGui::SetNextItemWidth(-ImGui::GetFontSize() * 0.5f);
  // A flat camera's field of view ends at 170°.
  const double max = std::string_view(key) == "fov" && !camera.panoramic() ? kMaxFlatFov : spec.sliderMax;
  const bool changed = settingSliderWidget("##value", spec, value, spec.sliderMin, max);
  state.probe.frame(std::string("camera.") + key);
  Camera next = camera;
  spec.setNumber(&next, value);
  gestureItem(edits, spec.label, changed, SetCamera{next});
  contextHelp(state, spec.tooltip);
  ImGui::PopID();
}

}  // namespace

void drawCameraPanel(ModellerState& state, EditQueue& edits) {
  const Camera& camera = state.document.project().camera;
  const SettingTableOf<Camera>& table = cameraTable();
  const float width = ImGui::GetFontSize() * 11.0f;

  ImGui::SetNextItemWidth(width);
  if (const auto chosen = choiceCombo(state, table.field("projection"), int(camera.projection), "camera.projection")) {
    Camera next = camera;
    next.projection = CameraProjection(*chosen);
    // A flat lens ends at 170°; a panoramic camera starts where artists expect one (a 180° dome
    // master, a 360° panorama) when it comes from a flat one.
    if (next.panoramic() && !camera.panoramic())
      next.fov = next.projection == CameraProjection::Fisheye ? 180.0 : 360.0;
    if (!next.panoramic()) next.fov = std::min(next.fov, kMaxFlatFov);
    if (next.orthographic()) next.stereo.reset();                              // no parallax without perspective
    if (next.panoramic()) next.shift_x = next.shift_y = next.lens_blur = 0.0;  // no flat picture to slide or blur
    edits.commit(std::string("Projection: ") + projectionName(next.projection), SetCamera{next});
  }

  for (const char* key : {"fov", "yaw", "pitch", "distance"}) cameraSlider(state, edits, camera, key);
  cameraSlider(state, edits, camera, "roll", false);
  if (!camera.panoramic()) {
    cameraSlider(state, edits, camera, "shift_x", false);
    cameraSlider(state, edits, camera, "shift_y", false);
    cameraSlider(state, edits, camera, "lens_blur", false);
  }

  sectionTitle("Stereo");
  bool stereo = camera.stereo.has_value();
  ImGui::BeginDisabled(camera.orthographic());
  if (ImGui::Checkbox("Stereo pair", &stereo)) {
    Camera next = camera;
    if (stereo)
      next.stereo = StereoSettings{};
    else
      next.stereo.reset();
    edits.commit(stereo ? "Stereo on" : "Stereo off", SetCamera{next});
  }
  state.probe.item("camera.stereo");
  contextHelp(state, camera.panoramic() ? "Two eyes in one frame, omni-directional stereo (for VR and stereo domes)"
                                        : "Two eyes in one frame, parallel and converging at a distance");
  ImGui::EndDisabled();
  if (!camera.stereo) return;
  const StereoSettings& s = *camera.stereo;
  const SettingTableOf<StereoSettings>& stereoSpecs = stereoTable();
  ImGui::SetNextItemWidth(width);
  if (const auto chosen = choiceCombo(state, stereoSpecs.field("layout"), int(s.layout), "camera.stereo.layout")) {
    Camera next = camera;
    next.stereo->layout = StereoLayout(*chosen);
    edits.commit("Stereo layout", SetCamera{next});
  }
  for (const char* key : {"eye_separation", "convergence"}) {
    const SettingSpec& spec = stereoSpecs.field(key);
    double value = spec.number(&s);
    ImGui::SetNextItemWidth(-ImGui::GetFontSize() * 0.5f);
    const bool changed =
        settingSliderWidget((std::string("##") + key).c_str(), spec, value, spec.sliderMin, spec.sliderMax);
    state.probe.frame(std::string("camera.stereo.") + key);
    Camera next = camera;
    spec.setNumber(&*next.stereo, value);
    gestureItem(edits, spec.label, changed, SetCamera{next});
    contextHelp(state, spec.tooltip);
  }
}

}  // namespace gridifs::ui
