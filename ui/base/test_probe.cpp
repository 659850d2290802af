#include "ui/base/test_probe.h"

namespace gridifs::ui {
namespace {
/// False in a window's first frame: a popup or an auto-sized dialog is placed only once its size
/// is known, so its items are not yet where the user will see them.
bool windowIsPlaced() { return !ImGui::IsWindowAppearing(); }
}  // namespace

void UiProbe::item(const std::string& name) {
  if (!enabled || !windowIsPlaced()) return;
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  rects[name] = ImVec4(a.x, a.y, b.x - a.x, b.y - a.y);
}

void UiProbe::frame(const std::string& name) {
  if (!enabled || !windowIsPlaced()) return;
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  rects[name] = ImVec4(a.x, a.y, ImGui::CalcItemWidth(), b.y - a.y);
}

void UiProbe::window(const std::string& name) {
  if (!enabled || !windowIsPlaced()) return;
  const ImVec2 a = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  rects[name] = ImVec4(a.x, a.y, size.x, size.y);
}

}  // namespace gridifs::ui
