// The Shading panel: every setting of the shaded display (lights, ambient, specular, occlusion,
// fog, depth of field) as edits of render.shading, one undo step per slider drag. Shown beside the
// preview while it is in the shaded mode.
#include <imgui.h>

#include <cmath>
#include <cstdio>

#include "schema/settings_tables.h"
#include "ui/base/widgets.h"
#include "ui/panels/panels.h"
#include "ui/panels/setting_slider.h"

namespace gridifs::ui {
namespace {

const double kAzimuthMin = -180.0, kAzimuthMax = 180.0, kElevationMin = -89.0, kElevationMax = 90.0;

/// A full-width slider with its label hidden: the format names the value ("ambient %.2f").
SettingSliderPlace fullWidth(const char* id) {
  ImGui::SetNextItemWidth(-ImGui::GetFontSize() * 0.5f);
  return {.id = id, .probe = "shading"};
}

/// Azimuth (degrees from +x towards +y) and elevation (degrees above the xy plane) of a direction.
void toAngles(const Vec3& d, double& azimuth, double& elevation) {
  const double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  azimuth = std::atan2(d.y, d.x) * 180.0 / M_PI;
  elevation = length > 0.0 ? std::asin(std::clamp(d.z / length, -1.0, 1.0)) * 180.0 / M_PI : 90.0;
}

Vec3 fromAngles(double azimuth, double elevation) {
  const double a = azimuth * M_PI / 180.0, e = elevation * M_PI / 180.0;
  return Vec3(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
}

void drawLight(ModellerState& state, EditQueue& edits, std::size_t index, const ShadingLight& light) {
  ImGui::PushID(int(index));
  char title[48];
  std::snprintf(title, sizeof title, index == 0 ? "Key light" : "Light %zu", index + 1);
  sectionTitle(title);
  double azimuth, elevation;
  toAngles(light.direction, azimuth, elevation);
  const float width = -ImGui::GetFontSize() * 0.5f;
  ImGui::SetNextItemWidth(width);
  bool changed = ImGui::SliderScalar("##azimuth", ImGuiDataType_Double, &azimuth, &kAzimuthMin, &kAzimuthMax,
                                     "azimuth %.0f°", ImGuiSliderFlags_AlwaysClamp);
  state.probe.frame("shading.light" + std::to_string(index) + ".azimuth");
  gestureItem(edits, "Light direction", changed, SetLightDirection{index, fromAngles(azimuth, elevation)});
  contextHelp(state,
              "Where the light comes from, around the vertical axis (Alt+drag on the preview moves the key light)");
  ImGui::SetNextItemWidth(width);
  changed = ImGui::SliderScalar("##elevation", ImGuiDataType_Double, &elevation, &kElevationMin, &kElevationMax,
                                "elevation %.0f°", ImGuiSliderFlags_AlwaysClamp);
  state.probe.frame("shading.light" + std::to_string(index) + ".elevation");
  gestureItem(edits, "Light direction", changed, SetLightDirection{index, fromAngles(azimuth, elevation)});
  contextHelp(state, "How high the light stands above the horizon (90°: straight above)");
  const SettingTableOf<ShadingLight>& table = shadingLightTable();
  const SettingSpec& colorSpec = table.field("color");
  float color[3] = {float(light.color.x), float(light.color.y), float(light.color.z)};
  changed = ImGui::ColorEdit3("##color", color, ImGuiColorEditFlags_NoInputs);
  gestureItem(edits, colorSpec.label, changed, SetLightColor{index, Vec3(color[0], color[1], color[2])});
  contextHelp(state, colorSpec.tooltip);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.0f);
  settingSlider(state, edits, table.field("intensity"), light.intensity,
                "render.shading.lights[" + std::to_string(index) + "]",
                {.id = "##intensity", .probe = "shading.light" + std::to_string(index)});
  bool shadows = light.shadows;
  const SettingSpec& shadowSpec = table.field("shadows");
  if (ImGui::Checkbox(shadowSpec.label, &shadows)) edits.commit(SetLightShadows{index, shadows});
  state.probe.item("shading.light" + std::to_string(index) + ".shadows");
  contextHelp(state, shadowSpec.tooltip);
  ImGui::SameLine();
  if (ImGui::SmallButton("Remove light")) edits.commit(RemoveLight{index});
  ImGui::PopID();
}

}  // namespace

void drawShadingPanel(ModellerState& state, EditQueue& edits) {
  const ShadingSettings& s = state.document.project().render.shading;
  for (std::size_t i = 0; i < s.lights.size(); ++i) drawLight(state, edits, i, s.lights[i]);
  if (s.lights.size() < std::size_t(limits::kMaxLights)) {
    if (ImGui::Button("Add light")) edits.commit(AddLight{});
    state.probe.item("shading.add_light");
    contextHelp(state, "Add a directional light (up to 3)");
  }

  sectionTitle("Surface");
  for (const auto& [key, id] :
       {std::pair{"ambient", "##ambient"}, {"specular", "##specular"}, {"shininess", "##shininess"}})
    settingSlider(state, edits, shadingSettingsTable(), "render.shading", key, s, fullWidth(id));

  sectionTitle("Ambient occlusion");
  for (const auto& [key, id] :
       {std::pair{"radius", "##aoradius"}, {"strength", "##aostrength"}, {"directions", "##aodirs"}})
    settingSlider(state, edits, ambientOcclusionTable(), "render.shading.ao", key, s.ao, fullWidth(id));

  sectionTitle("Fog");
  const SettingSpec& fogColor = fogTable().field("color");
  float fog[3] = {float(s.fog.color.x), float(s.fog.color.y), float(s.fog.color.z)};
  const bool fogChanged = ImGui::ColorEdit3("##fogcolor", fog, ImGuiColorEditFlags_NoInputs);
  gestureItem(edits, fogColor.label, fogChanged, SetFogColor{Vec3(fog[0], fog[1], fog[2])});
  contextHelp(state, fogColor.tooltip);
  ImGui::SameLine();
  settingSlider(state, edits, fogTable(), "render.shading.fog", "density", s.fog, fullWidth("##fogdensity"));

  sectionTitle("Depth of field");
  // An aperture needs a focus distance; the first one is the camera's distance to its target.
  const double focus = s.dof.focus.value_or(state.document.project().camera.distance);
  const SettingSpec& apertureSpec = depthOfFieldTable().field("aperture");
  double aperture = s.dof.aperture;
  ImGui::SetNextItemWidth(-ImGui::GetFontSize() * 0.5f);
  const bool changed =
      settingSliderWidget("##aperture", apertureSpec, aperture, apertureSpec.sliderMin, apertureSpec.sliderMax);
  state.probe.frame(std::string("shading.") + apertureSpec.label);
  gestureItem(edits, apertureSpec.label, changed, SetAperture{aperture, focus});
  contextHelp(state, apertureSpec.tooltip);
  ImGui::SetNextItemWidth(-ImGui::GetFontSize() * 0.5f);
  settingSlider(state, edits, depthOfFieldTable().field("focus"), focus, "render.shading.dof",
                {.id = "##focus", .probe = "shading"});
}

}  // namespace gridifs::ui
