// The flame display's controls in the preview toolbar: the palette picker with
// swatch strips (flam3's collection and ours) and the tone-mapping settings of Draves & Reckase 2003, §4–8 as
// edits of render.flame, one undo step per slider drag.
#include <algorithm>
#include <cstdio>

#include "flame/palette.h"
#include "model/settings_tables.h"
#include "ui/key_button.h"
#include "ui/preview_modes.h"
#include "ui/setting_slider.h"
#include "ui/widgets.h"

namespace gridifs::ui {
namespace {

std::vector<ImU32> swatchOf(const Palette& palette) {
  std::vector<ImU32> colors;
  for (int i = 0; i < PaletteCatalog::kSwatchSteps; ++i) {
    const Rgb c = palette.lookup((i + 0.5) / PaletteCatalog::kSwatchSteps);
    colors.push_back(ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, 1.0f)));
  }
  return colors;
}

void drawSwatch(ImDrawList* draw, ImVec2 min, ImVec2 max, const std::vector<ImU32>& colors) {
  if (colors.empty()) return;
  const float step = (max.x - min.x) / float(colors.size());
  for (std::size_t i = 0; i < colors.size(); ++i) {
    const float x0 = std::floor(min.x + step * float(i)), x1 = std::floor(min.x + step * float(i + 1));
    draw->AddRectFilled(ImVec2(x0, min.y), ImVec2(x1, max.y), colors[i]);
  }
  draw->AddRect(min, max, IM_COL32(0, 0, 0, 160));
}

/// The slider of render.flame's field `key` (range, format, label and tooltip from its table), with
/// its keyframe button, as one gesture. `min` < `max` replaces the table's slider range.
void flameSlider(ModellerState& state, EditQueue& edits, const FlameSettings& f, const char* key, double min = 0.0,
                 double max = 0.0) {
  const SettingSpec& spec = flameSettingsTable().field(key);
  double value = spec.number(&f);
  keyButton(state, edits, std::string("render.flame.") + key, &value);
  settingSlider(state, edits, spec, value, SettingGroup::Flame, {.probe = "flame", .min = min, .max = max});
}

}  // namespace

void PaletteCatalog::load() {
  loaded = true;
  for (const std::string& name : builtinPaletteNames())
    entries.push_back({name, name + "  (GridIFS)", swatchOf(builtinPalette(name))});
  try {
    for (const Palette& p : flam3Palettes()) {
      const std::string number = std::to_string(&p - flam3Palettes().data());
      // flam3 palettes are addressed by their number; the name is shown when there is one.
      entries.push_back({"flam3:" + number, "flam3 " + number + (p.name.empty() ? "" : "  " + p.name), swatchOf(p)});
    }
  } catch (const PaletteError& e) {
    flam3Error = e.what();
  }
}

const PaletteCatalog::Entry* PaletteCatalog::find(const std::string& reference) const {
  for (const Entry& e : entries)
    if (e.reference == reference) return &e;
  return nullptr;
}

void PreviewModes::drawFlameControls(ModellerState& state, EditQueue& edits) {
  if (!palettes_.loaded) palettes_.load();
  const Project& project = state.document.project();
  const FlameSettings& f = project.render.flame;
  const float em = ImGui::GetFontSize();
  if (f.palette != checkedPalette_) {
    checkedPalette_ = f.palette;
    paletteError_.clear();
    try {
      (void)resolvePalette(f.palette, state.document.path().parent_path());
    } catch (const std::exception& e) {
      paletteError_ = e.what();
    }
  }

  // Palette picker: the combo lists every palette with its swatch; the strip beside it shows the
  // current one (Draves & Reckase 2003, §5: the color coordinate c indexes a 256-entry palette).
  const PaletteCatalog::Entry* current = palettes_.find(f.palette);
  ImGui::SetNextItemWidth(em * 7.5f);
  ImGui::SetNextWindowSizeConstraints(ImVec2(em * 27.0f, 0), ImVec2(em * 34.0f, em * 24.0f));
  if (ImGui::BeginCombo("##palette", current ? current->reference.c_str() : f.palette.c_str(),
                        ImGuiComboFlags_HeightLargest)) {
    ImGuiListClipper clipper;
    clipper.Begin(int(palettes_.entries.size()));
    while (clipper.Step()) {
      for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
        const PaletteCatalog::Entry& e = palettes_.entries[std::size_t(i)];
        ImGui::PushID(i);
        const bool selected = e.reference == f.palette;
        if (ImGui::Selectable("##entry", selected, 0, ImVec2(0, em * 1.1f))) {
          edits.commit(SetPalette{e.reference});
        }
        if (selected && ImGui::IsWindowAppearing()) ImGui::SetScrollHereY();
        const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
        ImDrawList* draw = ImGui::GetWindowDrawList();
        const float swatchW = em * 9.0f;
        drawSwatch(draw, ImVec2(min.x + 2, min.y + 2), ImVec2(min.x + 2 + swatchW, max.y - 2), e.swatch);
        draw->AddText(ImVec2(min.x + swatchW + em * 0.6f, min.y + (max.y - min.y - em) * 0.5f),
                      ImGui::GetColorU32(ImGuiCol_Text), e.label.c_str());
        ImGui::PopID();
      }
    }
    if (!palettes_.flam3Error.empty()) ImGui::TextDisabled("flam3 palettes: %s", palettes_.flam3Error.c_str());
    ImGui::EndCombo();
  }
  state.probe.item("flame.palette");
  contextHelp(state,
              "Palette of the flame display: ours and flam3's collection (Draves & Reckase 2003, §5); a change restarts the preview");
  ImGui::SameLine();
  {
    const ImVec2 pos = ImGui::GetCursorScreenPos();
    const ImVec2 size(em * 3.5f, ImGui::GetFrameHeight());
    ImGui::Dummy(size);
    if (current)
      drawSwatch(ImGui::GetWindowDrawList(), ImVec2(pos.x, pos.y + 3), ImVec2(pos.x + size.x, pos.y + size.y - 3),
                 current->swatch);
  }
  ImGui::SameLine();
  if (ImGui::Button("Tone...")) ImGui::OpenPopup("##tonemapping");
  state.probe.item("flame.tone");
  contextHelp(state, "Brightness, gamma, vibrancy, highlights and density estimation of the flame display");
  if (!paletteError_.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "palette: %s", paletteError_.c_str());
  }

  if (ImGui::BeginPopup("##tonemapping")) {
    sectionTitle("Tone mapping (Draves & Reckase 2003, §4, §6)");
    ImGui::PushItemWidth(em * 14.0f);
    for (const char* key : {"brightness", "gamma", "gamma_threshold", "vibrancy", "highlight_power"})
      flameSlider(state, edits, f, key);
    ImGui::Spacing();
    sectionTitle("Density estimation (Draves & Reckase 2003, §8)");
    bool estimate = f.estimator_radius > 0.0;
    if (ImGui::Checkbox("Density estimation", &estimate)) {
      edits.commit(SetDensityEstimation{estimate});
    }
    state.probe.item("flame.estimation");
    contextHelp(state, "Blur thin areas with a kernel that shrinks as density grows (off: faster, noisier)");
    if (estimate) {
      const SettingSpec& radius = flameSettingsTable().field("estimator_radius");
      flameSlider(state, edits, f, "estimator_radius", std::max(radius.sliderMin, f.estimator_minimum), radius.sliderMax);
    }
    ImGui::PopItemWidth();
    ImGui::Spacing();
    if (ImGui::Button("Defaults")) {
      edits.commit(ResetFlameSettings{});
    }
    ImGui::SameLine();
    const double ms = flame_.developer().lastMs();
    ImGui::TextDisabled("develop %.0f ms", ms);
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)) && !ImGui::IsAnyItemActive())
      ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
}

}  // namespace gridifs::ui
