// The flame display's controls in the preview toolbar: the palette picker with
// swatch strips (flam3's collection and ours) and the tone-mapping settings of Draves & Reckase 2003, §4–8 as
// edits of render.flame, one undo step per slider drag.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "schema/settings_tables.h"
#include "tone/palette.h"
#include "tone/palette_gradient.h"
#include "ui/base/widgets.h"
#include "ui/panels/key_button.h"
#include "ui/panels/setting_slider.h"
#include "ui/views/preview_modes.h"

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
  settingSlider(state, edits, spec, value, "render.flame", {.probe = "flame", .min = min, .max = max});
}

/// "log" / "linear" / "binary": Draves & Reckase 2003, figure 3 c, b and a.
void densityDisplayCombo(ModellerState& state, EditQueue& edits, const FlameSettings& f) {
  static const char* const kNames[] = {"log", "linear", "binary"};
  static const char* const kLabels[] = {"log density", "linear", "binary (membership)"};
  int current = 0;
  for (int i = 0; i < 3; ++i)
    if (f.density_display == kNames[i]) current = i;
  if (ImGui::Combo("Density display", &current, kLabels, 3)) {
    const std::string name = kNames[current];
    edits.commit(SetDensityDisplay{name});
  }
  state.probe.item("flame.density_display");
  contextHelp(state, flameSettingsTable().field("density_display").tooltip);
}

/// Quality (samples per pixel) when set decides the renders' sample count; the check box sets it
/// from the current sample budget or goes back to the budget.
void qualityControl(ModellerState& state, EditQueue& edits) {
  const RenderSettings& r = state.document.project().render;
  bool useQuality = r.quality.has_value();
  if (ImGui::Checkbox("Quality", &useQuality)) {
    const double perPixel = std::clamp(double(r.samples) / (double(r.width) * double(r.height)), 1.0, 1e6);
    edits.commit(useQuality ? "Quality on" : "Quality off",
                 SetQuality{useQuality ? std::optional<double>(std::round(perPixel)) : std::nullopt});
  }
  state.probe.item("flame.quality");
  contextHelp(state, "Samples per pixel: the sample count follows the image size (off: the sample budget)");
  if (!useQuality) return;
  ImGui::SameLine();
  const SettingSpec& spec = renderSettingsTable().field("quality");
  settingSlider(state, edits, spec, r.quality.value_or(50.0), "render", {.id = "##quality", .probe = "flame"});
}

/// Draves & Reckase 2003, figure 4: pixels by density on log–log axes (power-of-two bins), with the
/// gamma threshold and saturation marked and the tone curve (brightness against density) over it.
void drawDensityPlot(ModellerState& state, const DensityPlotData& plot, const FlameSettings& f) {
  const float em = ImGui::GetFontSize();
  const ImVec2 size(em * 22.0f, em * 7.0f);
  const ImVec2 o = ImGui::GetCursorScreenPos();
  ImGui::Dummy(size);
  state.probe.item("flame.density_plot");
  contextHelp(state,
              "Pixels by density on log-log axes (Draves & Reckase 2003, figure 4); the curve is the brightness "
              "each density gets; dashed: where the gamma threshold ends the linear part and where pixels turn white");
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(o, ImVec2(o.x + size.x, o.y + size.y), IM_COL32(20, 20, 24, 255));
  if (!plot.valid || plot.histogram.bins.empty()) {
    draw->AddText(ImVec2(o.x + em * 0.5f, o.y + em * 0.5f), IM_COL32(160, 160, 160, 255), "no points yet");
    return;
  }
  const auto& bins = plot.histogram.bins;
  const double xMax = double(bins.size());  // log2 of the densest pixel's hits, rounded up
  double yMax = 1.0;
  for (std::int64_t c : bins) yMax = std::max(yMax, std::log10(double(c) + 1.0));
  auto px = [&](double log2Hits) { return o.x + float(log2Hits / xMax) * size.x; };
  auto py = [&](double fraction) { return o.y + size.y - float(fraction) * (size.y - em * 0.2f); };
  for (std::size_t k = 0; k < bins.size(); ++k) {
    if (bins[k] == 0) continue;
    const double h = std::log10(double(bins[k]) + 1.0) / yMax;
    draw->AddRectFilled(ImVec2(px(double(k)) + 1.0f, py(h)), ImVec2(px(double(k + 1)) - 1.0f, py(0.0)),
                        IM_COL32(110, 140, 200, 255));
  }
  // The tone curve: brightness 0..1 against density (the same log2 axis).
  const LogDensityScale& scale = plot.scale;
  ImVec2 previous;
  for (int i = 0; i <= 96; ++i) {
    const double x = xMax * i / 96.0;
    const ImVec2 p(px(x), py(toneCurve(scale, f.gamma, f.gamma_threshold, std::exp2(x))));
    if (i > 0) draw->AddLine(previous, p, IM_COL32(255, 200, 80, 255), 2.0f);
    previous = p;
  }
  auto mark = [&](double hits, ImU32 color, const char* label) {
    if (!(hits >= 1.0) || !std::isfinite(hits) || std::log2(hits) > xMax) return;
    const float x = px(std::log2(hits));
    for (float y = o.y; y < o.y + size.y; y += 6.0f)
      draw->AddLine(ImVec2(x, y), ImVec2(x, std::min(y + 3.0f, o.y + size.y)), color);
    draw->AddText(ImVec2(x + 3.0f, o.y + 2.0f), color, label);
  };
  mark(hitsForAlpha(scale, f.gamma_threshold), IM_COL32(120, 230, 140, 255), "threshold");
  mark(hitsForAlpha(scale, 1.0), IM_COL32(255, 255, 255, 220), "white");
  char axis[64];
  std::snprintf(axis, sizeof axis, "1 .. %u hits", plot.histogram.maxHits);
  draw->AddText(ImVec2(o.x + 3.0f, o.y + size.y - em * 1.1f), IM_COL32(170, 170, 170, 255), axis);
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
  const std::string paletteInput = f.palette + "|" + f.palette_keys;
  if (paletteInput != checkedPalette_) {
    checkedPalette_ = paletteInput;
    paletteError_.clear();
    try {
      (void)resolveFlamePalette(f, state.document.path().parent_path());
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
              "Palette of the flame display: ours and flam3's collection (Draves & Reckase 2003, §5); a change "
              "restarts the preview");
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
  if (ImGui::Button(f.palette_keys.empty() ? "Gradient..." : "Gradient*...")) paletteEditor_.open();
  state.probe.item("flame.gradient");
  contextHelp(state, "Edit the palette as a gradient of keys and save it beside the project");
  paletteEditor_.draw(state, edits, palettes_);
  ImGui::SameLine();
  if (ImGui::Button("Tone...")) ImGui::OpenPopup("##tonemapping");
  state.probe.item("flame.tone");
  contextHelp(state, "Brightness, gamma, vibrancy, highlights and density estimation of the flame display");
  if (!paletteError_.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "palette: %s", paletteError_.c_str());
  }

  if (ImGui::BeginPopup("##tonemapping")) {
    drawTonePopup(state, edits, f);
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)) && !ImGui::IsAnyItemActive())
      ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
}

void PreviewModes::drawTonePopup(ModellerState& state, EditQueue& edits, const FlameSettings& f) {
  const float em = ImGui::GetFontSize();
  sectionTitle("Tone mapping (Draves & Reckase 2003, §4, §6)");
  ImGui::PushItemWidth(em * 14.0f);
  flameSlider(state, edits, f, "hue");
  densityDisplayCombo(state, edits, f);
  for (const char* key : {"brightness", "gamma", "gamma_threshold", "vibrancy", "highlight_power"})
    flameSlider(state, edits, f, key);
  ImGui::PopItemWidth();
  drawDensityPlot(state, flame_.developer().densityPlot(), f);
  ImGui::Spacing();
  sectionTitle("Density estimation (Draves & Reckase 2003, §8)");
  ImGui::PushItemWidth(em * 14.0f);
  bool estimate = f.estimator_radius > 0.0;
  if (ImGui::Checkbox("Density estimation", &estimate)) {
    edits.commit(SetDensityEstimation{estimate});
  }
  state.probe.item("flame.estimation");
  contextHelp(state, "Blur thin areas with a kernel that shrinks as density grows (off: faster, noisier)");
  if (estimate) {
    const SettingSpec& radius = flameSettingsTable().field("estimator_radius");
    flameSlider(state, edits, f, "estimator_radius", std::max(radius.sliderMin, f.estimator_minimum), radius.sliderMax);
    flameSlider(state, edits, f, "estimator_minimum", 0.0, std::max(0.01, std::min(f.estimator_radius, 10.0)));
    flameSlider(state, edits, f, "estimator_curve", 0.05, 2.0);
  }
  ImGui::Spacing();
  sectionTitle("Filtering and quality of renders (Draves & Reckase 2003, §8)");
  flameSlider(state, edits, f, "supersample", 1.0, 4.0);
  flameSlider(state, edits, f, "filter_radius", 0.0, 3.0);
  qualityControl(state, edits);
  ImGui::PopItemWidth();
  ImGui::Spacing();
  if (ImGui::Button("Defaults")) {
    edits.commit(ResetFlameSettings{});
  }
  ImGui::SameLine();
  const double ms = flame_.developer().lastMs();
  ImGui::TextDisabled("develop %.0f ms", ms);
}

}  // namespace gridifs::ui
