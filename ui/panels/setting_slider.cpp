#include "ui/panels/setting_slider.h"

#include <imgui.h>

#include "edit/parameter_edit.h"
#include "ui/base/widgets.h"

namespace gridifs::ui {

bool settingSliderWidget(const char* id, const SettingSpec& spec, double& value, double min, double max) {
  if (!(min < max)) {
    // No slider range: a drag over the field's whole valid range (a function's weight).
    double lo = spec.min, hi = spec.max;
    return ImGui::DragScalar(id, ImGuiDataType_Double, &value, float(spec.speed), &lo, &hi, spec.format,
                             ImGuiSliderFlags_AlwaysClamp);
  }
  const ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp | (spec.logarithmic ? ImGuiSliderFlags_Logarithmic : 0);
  if (spec.type == SettingType::Integer || spec.type == SettingType::Count) {
    int v = int(value);
    const int lo = int(min), hi = int(max);
    const bool changed = ImGui::SliderScalar(id, ImGuiDataType_S32, &v, &lo, &hi, spec.format, flags);
    value = double(v);
    return changed;
  }
  return ImGui::SliderScalar(id, ImGuiDataType_Double, &value, &min, &max, spec.format, flags);
}

bool settingDrag(const SettingSpec& spec, void* owner) {
  const bool ranged = spec.sliderMin < spec.sliderMax;
  const double lo = ranged ? spec.sliderMin : spec.min, hi = ranged ? spec.sliderMax : spec.max;
  if (spec.type == SettingType::Vector)
    return dragVec3(spec.label, spec.value<Vec3>(owner), spec.speed, lo, hi, spec.format);
  return dragDouble(spec.label, spec.value<double>(owner), spec.speed, lo, hi, spec.format);
}

void settingSlider(ModellerState& state, EditQueue& edits, const SettingSpec& spec, double value,
                   const std::string& group, const SettingSliderPlace& place) {
  const bool own = place.min < place.max;
  const bool changed = settingSliderWidget(place.id ? place.id : spec.label, spec, value,
                                           own ? place.min : spec.sliderMin, own ? place.max : spec.sliderMax);
  state.probe.frame(place.probe + "." + spec.label);
  gestureItem(edits, spec.label, changed, SetParameter{settingPath(group, spec.key), value, spec.label});
  contextHelp(state, spec.tooltip);
}

}  // namespace gridifs::ui
