#include "ui/views/transfer_editor.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "ui/base/widgets.h"

namespace gridifs::ui {
namespace {

/// Colour and opacity at density d of sorted stops (linear between them), for the strip.
TransferStop stopAt(const std::vector<TransferStop>& stops, double d) {
  if (d <= stops.front().density) return stops.front();
  if (d >= stops.back().density) return stops.back();
  std::size_t i = 1;
  while (stops[i].density < d) ++i;
  const TransferStop &a = stops[i - 1], &b = stops[i];
  const double w = (d - a.density) / (b.density - a.density);
  return {d, a.color + (b.color - a.color) * w, a.opacity + (b.opacity - a.opacity) * w};
}

void drawStrip(const std::vector<TransferStop>& stops, float width, float height) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  constexpr int kSteps = 64;
  for (int s = 0; s < kSteps; ++s) {
    const TransferStop t = stopAt(stops, (s + 0.5) / kSteps);
    // The colour over black weighted by the opacity: what a thin slab of that density shows.
    const auto channel = [&](double c) { return float(std::clamp(c * t.opacity, 0.0, 1.0)); };
    const ImU32 color =
        ImGui::ColorConvertFloat4ToU32(ImVec4(channel(t.color.x), channel(t.color.y), channel(t.color.z), 1.0f));
    const float x0 = origin.x + width * s / kSteps, x1 = origin.x + width * (s + 1) / kSteps;
    draw->AddRectFilled(ImVec2(x0, origin.y), ImVec2(x1, origin.y + height), color);
  }
  // The opacity curve over the strip.
  for (std::size_t i = 0; i + 1 < stops.size(); ++i) {
    const auto at = [&](const TransferStop& t) {
      return ImVec2(origin.x + width * float(t.density), origin.y + height * float(1.0 - t.opacity));
    };
    draw->AddLine(at(stops[i]), at(stops[i + 1]), IM_COL32(255, 255, 255, 200), 1.5f);
  }
  ImGui::Dummy(ImVec2(width, height));
}

}  // namespace

void TransferEditor::draw(ModellerState& state, EditQueue& edits) {
  if (!open_) return;
  const float em = ImGui::GetFontSize();
  ImGui::SetNextWindowSize(ImVec2(em * 30.0f, em * 17.0f), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Volume transfer function", &open_)) {
    ImGui::End();
    return;
  }
  state.probe.item("volume.transfer.window");
  const VolumeRenderSettings settings = state.document.project().render.volume.value_or(VolumeRenderSettings{});
  const std::vector<TransferStop>& stops = settings.transfer;
  bool enabled = !stops.empty();
  if (ImGui::Checkbox("Transfer function", &enabled))
    edits.commit(SetTransferFunction{enabled ? defaultTransferStops() : std::vector<TransferStop>{}});
  state.probe.item("volume.transfer.enable");
  contextHelp(state,
              "On: density maps to the colours and opacities below. Off: opacity follows the density and the "
              "colour is the functions' (or the flame palette's)");
  if (stops.empty()) {
    ImGui::TextWrapped("Opacity = density; colours from the functions.");
    ImGui::End();
    return;
  }
  drawStrip(stops, ImGui::GetContentRegionAvail().x, em * 1.6f);
  state.probe.item("volume.transfer.strip");
  for (std::size_t i = 0; i < stops.size(); ++i) {
    ImGui::PushID(int(i));
    std::vector<TransferStop> next = stops;
    TransferStop& s = next[i];
    // A stop stays between its neighbours, so the stops stay sorted while it is dragged.
    const float lo = i == 0 ? 0.0f : float(stops[i - 1].density) + 1e-3f;
    const float hi = i + 1 == stops.size() ? 1.0f : float(stops[i + 1].density) - 1e-3f;
    float density = float(s.density);
    ImGui::SetNextItemWidth(em * 7.0f);
    bool changed = ImGui::SliderFloat("##density", &density, lo, hi, "density %.3f", ImGuiSliderFlags_AlwaysClamp);
    s.density = std::clamp(double(density), double(lo), double(hi));
    gestureItem(edits, "Volume transfer function", changed, SetTransferFunction{next});
    state.probe.item("volume.transfer.density." + std::to_string(i));
    ImGui::SameLine();
    float color[3] = {float(s.color.x), float(s.color.y), float(s.color.z)};
    changed = ImGui::ColorEdit3("##color", color, ImGuiColorEditFlags_NoInputs | ImGuiColorEditFlags_Float);
    s.color = Vec3(color[0], color[1], color[2]);
    gestureItem(edits, "Volume transfer function", changed, SetTransferFunction{next});
    ImGui::SameLine();
    float opacity = float(s.opacity);
    ImGui::SetNextItemWidth(em * 7.0f);
    changed = ImGui::SliderFloat("##opacity", &opacity, 0.0f, 1.0f, "opacity %.2f", ImGuiSliderFlags_AlwaysClamp);
    s.opacity = std::clamp(double(opacity), 0.0, 1.0);
    gestureItem(edits, "Volume transfer function", changed, SetTransferFunction{next});
    state.probe.item("volume.transfer.opacity." + std::to_string(i));
    ImGui::SameLine();
    ImGui::BeginDisabled(stops.size() <= 1);
    if (ImGui::SmallButton("x")) {
      std::vector<TransferStop> fewer = stops;
      fewer.erase(fewer.begin() + std::ptrdiff_t(i));
      edits.commit(SetTransferFunction{fewer});
    }
    ImGui::EndDisabled();
    ImGui::PopID();
  }
  ImGui::BeginDisabled(stops.size() >= std::size_t(kMaxTransferStops));
  if (ImGui::Button("Add stop")) {
    // In the middle of the widest gap (or of the ends' room), with the colour and opacity there.
    std::vector<double> edges{0.0};
    for (const TransferStop& s : stops) edges.push_back(s.density);
    edges.push_back(1.0);
    std::size_t widest = 0;
    for (std::size_t g = 0; g + 1 < edges.size(); ++g)
      if (edges[g + 1] - edges[g] > edges[widest + 1] - edges[widest]) widest = g;
    const double d = 0.5 * (edges[widest] + edges[widest + 1]);
    std::vector<TransferStop> more = stops;
    if (edges[widest + 1] - edges[widest] > 2e-3) {
      more.push_back(stopAt(stops, d));
      more.back().density = d;
      std::sort(more.begin(), more.end(),
                [](const TransferStop& a, const TransferStop& b) { return a.density < b.density; });
      edits.commit(SetTransferFunction{more});
    }
  }
  ImGui::EndDisabled();
  state.probe.item("volume.transfer.add");
  ImGui::End();
}

}  // namespace gridifs::ui
