// The Shading panel: every setting of the shaded display (lights, ambient, specular, occlusion,
// fog, depth of field) as edits of render.shading, one undo step per slider drag. Shown beside the
// preview while it is in the shaded mode.
#include <imgui.h>

#include <cmath>
#include <cstdio>

#include "ui/panels.h"
#include "ui/widgets.h"

namespace gridifs::ui {
namespace {

using ShadingChange = std::function<void(ShadingSettings&)>;

const double kZero = 0.0, kAzimuthMin = -180.0, kAzimuthMax = 180.0, kElevationMin = -89.0, kElevationMax = 90.0,
             kIntensityMax = 4.0, kApertureMax = 0.5, kFocusMin = 0.05, kFocusMax = 100.0;

/// One gesture on the item just submitted, editing a copy of render.shading.
void shadingGesture(EditQueue& edits, const char* label, bool changed, ShadingChange change) {
  gestureItem(edits, label, changed, [change](Project& p) { change(p.render.shading); });
}

void slider(ModellerState& state, EditQueue& edits, const char* id, const char* undoLabel, double value, double min,
            double max, const char* format, ShadingChange (*make)(double), const char* help, bool logarithmic = false) {
  ImGui::SetNextItemWidth(-ImGui::GetFontSize() * 0.5f);
  const bool changed =
      ImGui::SliderScalar(id, ImGuiDataType_Double, &value, &min, &max, format,
                          ImGuiSliderFlags_AlwaysClamp | (logarithmic ? ImGuiSliderFlags_Logarithmic : 0));
  state.probe.frame(std::string("shading.") + undoLabel);
  shadingGesture(edits, undoLabel, changed, make(value));
  contextHelp(state, help);
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
  gestureItem(edits, "Light direction", changed, [index, azimuth, elevation](Project& p) {
    p.render.shading.lights.at(index).direction = fromAngles(azimuth, elevation);
  });
  contextHelp(state,
              "Where the light comes from, around the vertical axis (Alt+drag on the preview moves the key light)");
  ImGui::SetNextItemWidth(width);
  changed = ImGui::SliderScalar("##elevation", ImGuiDataType_Double, &elevation, &kElevationMin, &kElevationMax,
                                "elevation %.0f°", ImGuiSliderFlags_AlwaysClamp);
  state.probe.frame("shading.light" + std::to_string(index) + ".elevation");
  gestureItem(edits, "Light direction", changed, [index, azimuth, elevation](Project& p) {
    p.render.shading.lights.at(index).direction = fromAngles(azimuth, elevation);
  });
  contextHelp(state, "How high the light stands above the horizon (90°: straight above)");
  float color[3] = {float(light.color.x), float(light.color.y), float(light.color.z)};
  changed = ImGui::ColorEdit3("##color", color, ImGuiColorEditFlags_NoInputs);
  gestureItem(edits, "Light colour", changed, [index, color](Project& p) {
    p.render.shading.lights.at(index).color = Vec3(color[0], color[1], color[2]);
  });
  contextHelp(state, "The light's colour");
  ImGui::SameLine();
  double intensity = light.intensity;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.0f);
  changed = ImGui::SliderScalar("##intensity", ImGuiDataType_Double, &intensity, &kZero, &kIntensityMax,
                                "intensity %.2f", ImGuiSliderFlags_AlwaysClamp);
  state.probe.frame("shading.light" + std::to_string(index) + ".intensity");
  gestureItem(edits, "Light intensity", changed,
              [index, intensity](Project& p) { p.render.shading.lights.at(index).intensity = intensity; });
  contextHelp(state, "How bright the light is");
  bool shadows = light.shadows;
  if (ImGui::Checkbox("Shadows", &shadows))
    edits.commit(shadows ? "Light casts shadows" : "Light casts no shadows",
                 [index, shadows](Project& p) { p.render.shading.lights.at(index).shadows = shadows; });
  state.probe.item("shading.light" + std::to_string(index) + ".shadows");
  contextHelp(state, "Shadows: the chaos game also fills a depth buffer seen from this light (re-renders)");
  ImGui::SameLine();
  if (ImGui::SmallButton("Remove light"))
    edits.commit("Remove light", [index](Project& p) {
      auto& lights = p.render.shading.lights;
      if (index < lights.size()) lights.erase(lights.begin() + std::ptrdiff_t(index));
    });
  ImGui::PopID();
}

}  // namespace

void drawShadingPanel(ModellerState& state, EditQueue& edits) {
  const ShadingSettings& s = state.document.project().render.shading;
  for (std::size_t i = 0; i < s.lights.size(); ++i) drawLight(state, edits, i, s.lights[i]);
  if (s.lights.size() < std::size_t(limits::kMaxLights)) {
    if (ImGui::Button("Add light"))
      edits.commit("Add light", [](Project& p) {
        ShadingLight fill;
        fill.direction = Vec3(-0.6, 0.8, 0.4);
        fill.intensity = 0.4;
        fill.shadows = false;
        p.render.shading.lights.push_back(fill);
      });
    state.probe.item("shading.add_light");
    contextHelp(state, "Add a directional light (up to 3)");
  }

  sectionTitle("Surface");
  slider(
      state, edits, "##ambient", "Ambient", s.ambient, 0.0, 1.0, "ambient %.2f",
      [](double v) -> ShadingChange { return [v](ShadingSettings& x) { x.ambient = v; }; },
      "Light that reaches every point, scaled by the ambient occlusion");
  slider(
      state, edits, "##specular", "Specular", s.specular, 0.0, 2.0, "specular %.2f",
      [](double v) -> ShadingChange { return [v](ShadingSettings& x) { x.specular = v; }; },
      "Strength of the highlights (Blinn-Phong)");
  slider(
      state, edits, "##shininess", "Shininess", s.shininess, 1.0, 512.0, "shininess %.0f",
      [](double v) -> ShadingChange { return [v](ShadingSettings& x) { x.shininess = v; }; },
      "How small and sharp the highlights are", true);

  sectionTitle("Ambient occlusion");
  slider(
      state, edits, "##aoradius", "Occlusion radius", s.ao.radius, 0.0, 64.0, "radius %.0f px",
      [](double v) -> ShadingChange { return [v](ShadingSettings& x) { x.ao.radius = v; }; },
      "How far (in pixels) the occlusion looks for surrounding surfaces");
  slider(
      state, edits, "##aostrength", "Occlusion strength", s.ao.strength, 0.0, 1.0, "strength %.2f",
      [](double v) -> ShadingChange { return [v](ShadingSettings& x) { x.ao.strength = v; }; },
      "How much creases and corners darken (0: off)");
  int directions = s.ao.directions;
  ImGui::SetNextItemWidth(-ImGui::GetFontSize() * 0.5f);
  const bool dirChanged = ImGui::SliderInt("##aodirs", &directions, 1, limits::kMaxAoDirections, "%d directions",
                                           ImGuiSliderFlags_AlwaysClamp);
  state.probe.frame("shading.Occlusion directions");
  gestureItem(edits, "Occlusion directions", dirChanged,
              [directions](Project& p) { p.render.shading.ao.directions = directions; });
  contextHelp(state, "Screen directions searched for the horizon (more: smoother, slower)");

  sectionTitle("Fog");
  float fog[3] = {float(s.fog.color.x), float(s.fog.color.y), float(s.fog.color.z)};
  const bool fogColor = ImGui::ColorEdit3("##fogcolor", fog, ImGuiColorEditFlags_NoInputs);
  gestureItem(edits, "Fog colour", fogColor,
              [fog](Project& p) { p.render.shading.fog.color = Vec3(fog[0], fog[1], fog[2]); });
  contextHelp(state, "The colour distant points fade to");
  ImGui::SameLine();
  slider(
      state, edits, "##fogdensity", "Fog density", s.fog.density, 0.0, 2.0, "density %.3f",
      [](double v) -> ShadingChange { return [v](ShadingSettings& x) { x.fog.density = v; }; },
      "How quickly points fade with distance (0: no fog)");

  sectionTitle("Depth of field");
  // An aperture needs a focus distance; the first one is the camera's distance to its target.
  const double focus = s.dof.focus.value_or(state.document.project().camera.distance);
  double aperture = s.dof.aperture;
  ImGui::SetNextItemWidth(-ImGui::GetFontSize() * 0.5f);
  bool changed = ImGui::SliderScalar("##aperture", ImGuiDataType_Double, &aperture, &kZero, &kApertureMax,
                                     "aperture %.3f", ImGuiSliderFlags_AlwaysClamp);
  state.probe.frame("shading.Aperture");
  gestureItem(edits, "Aperture", changed, [aperture, focus](Project& p) {
    p.render.shading.dof.aperture = aperture;
    p.render.shading.dof.focus = focus;
  });
  contextHelp(state, "Blur away from the focus distance (0: everything sharp; re-renders the chaos game)");
  double focusValue = focus;
  ImGui::SetNextItemWidth(-ImGui::GetFontSize() * 0.5f);
  changed = ImGui::SliderScalar("##focus", ImGuiDataType_Double, &focusValue, &kFocusMin, &kFocusMax, "focus %.2f",
                                ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic);
  state.probe.frame("shading.Focus");
  gestureItem(edits, "Focus distance", changed, [focusValue](Project& p) { p.render.shading.dof.focus = focusValue; });
  contextHelp(state, "The view depth that stays sharp (the camera's distance puts the target in focus)");
}

}  // namespace gridifs::ui
