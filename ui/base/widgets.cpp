#include "ui/base/widgets.h"

#include "ui/base/modeller_state.h"

namespace gridifs::ui {

bool sliderDouble(const char* label, double& value, double min, double max, const char* format) {
  return ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &min, &max, format);
}

bool dragDouble(const char* label, double& value, double speed, double min, double max, const char* format) {
  return ImGui::DragScalar(label, ImGuiDataType_Double, &value, float(speed), min < max ? &min : nullptr,
                           min < max ? &max : nullptr, format);
}

bool dragVec3(const char* label, Vec3& value, double speed, double min, double max, const char* format) {
  return ImGui::DragScalarN(label, ImGuiDataType_Double, &value.x, 3, float(speed), min < max ? &min : nullptr,
                            min < max ? &max : nullptr, format);
}

void contextHelp(ModellerState& state, const char* text) {
  if (ImGui::IsItemHovered()) state.contextHelp = text;
}

void sectionTitle(const char* text) {
  ImGui::Spacing();
  ImGui::TextDisabled("%s", text);
  ImGui::Separator();
}

void helpMarker(const char* text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
    ImGui::TextUnformatted(text);
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
}

}  // namespace gridifs::ui
