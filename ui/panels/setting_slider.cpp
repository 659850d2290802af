#include "ui/panels/setting_slider.h"

#include <imgui.h>

#include "ui/base/widgets.h"

namespace gridifs::ui {

bool settingSliderWidget(const char* id, const SettingSpec& spec, double& value, double min, double max) {
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

void settingSlider(ModellerState& state, EditQueue& edits, const SettingSpec& spec, double value, SettingGroup group,
                   const SettingSliderPlace& place, std::size_t light) {
  const bool own = place.min < place.max;
  const bool changed = settingSliderWidget(place.id ? place.id : spec.label, spec, value,
                                           own ? place.min : spec.sliderMin, own ? place.max : spec.sliderMax);
  state.probe.frame(place.probe + "." + spec.label);
  gestureItem(edits, spec.label, changed, SetSettingNumber{group, spec.key, value, light});
  contextHelp(state, spec.tooltip);
}

}  // namespace gridifs::ui
