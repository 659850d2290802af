#include "ui/views/palette_editor.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "tone/palette_gradient.h"
#include "ui/base/widgets.h"
#include "ui/views/preview_modes.h"

namespace gridifs::ui {
namespace {

/// The edit that stores `keys` as the gradient being edited (one undo step).
SetPaletteKeys setKeys(const std::vector<PaletteKey>& keys) { return SetPaletteKeys{formatPaletteKeys(keys)}; }

ImU32 colorOf(float r, float g, float b) { return ImGui::ColorConvertFloat4ToU32(ImVec4(r, g, b, 1.0f)); }

}  // namespace

void PaletteEditor::draw(ModellerState& state, EditQueue& edits, const PaletteCatalog& catalog) {
  if (!open_) return;
  const float em = ImGui::GetFontSize();
  ImGui::SetNextWindowSize(ImVec2(em * 38.0f, em * 19.0f), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Palette editor", &open_)) {
    ImGui::End();
    return;
  }
  const FlameSettings& f = state.document.project().render.flame;
  const std::vector<PaletteKey> keys = parsePaletteKeys(f.palette_keys).value_or(std::vector<PaletteKey>{});
  drawStart(state, edits, catalog, keys);
  if (keys.empty()) {
    ImGui::TextWrapped(
        "Start a gradient from the current palette or from one of the list; its keys then replace "
        "the palette until you save or discard them.");
  } else {
    drawGradient(state, edits, keys);
    drawKey(state, edits, keys);
    drawSave(state, edits, keys);
  }
  if (!message_.empty()) ImGui::TextWrapped("%s", message_.c_str());
  ImGui::End();
}

void PaletteEditor::drawStart(ModellerState& state, EditQueue& edits, const PaletteCatalog& catalog,
                              const std::vector<PaletteKey>& keys) {
  const FlameSettings& f = state.document.project().render.flame;
  if (ImGui::Button("From current palette")) {
    FlameSettings plain = f;
    plain.palette_keys.clear();
    try {
      edits.commit("Gradient from current palette", setKeys(keysToEdit(plain, state.document.path().parent_path())));
      selected_ = 0;
      message_.clear();
    } catch (const std::exception& e) {
      message_ = std::string("The current palette cannot be read: ") + e.what();
    }
  }
  state.probe.item("palette_editor.from_current");
  contextHelp(state, "Sample 16 keys from the palette the display uses now");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 12.0f);
  if (ImGui::BeginCombo("##start", "From palette...", ImGuiComboFlags_HeightLarge)) {
    ImGuiListClipper clipper;
    clipper.Begin(int(catalog.entries.size()));
    while (clipper.Step())
      for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
        const auto& e = catalog.entries[std::size_t(i)];
        if (ImGui::Selectable(e.label.c_str())) {
          try {
            edits.commit("Gradient from " + e.reference, setKeys(keysFromPalette(resolvePalette(e.reference))));
            selected_ = 0;
            message_.clear();
          } catch (const std::exception& ex) {
            message_ = ex.what();
          }
        }
      }
    ImGui::EndCombo();
  }
  state.probe.item("palette_editor.from_palette");
  if (!keys.empty()) {
    ImGui::SameLine();
    if (ImGui::Button("Discard")) edits.commit(SetPaletteKeys{});
    contextHelp(state, "Go back to the palette the gradient replaced");
  }
}

void PaletteEditor::drawGradient(ModellerState& state, EditQueue& edits, const std::vector<PaletteKey>& keys) {
  // The 256 entries as the display uses them, with the keys as handles below.
  const float em = ImGui::GetFontSize();
  const Palette palette = paletteFromKeys(keys);
  const float barHeight = em * 2.2f, handle = em * 0.55f;
  // Inset by a handle's half width so that the keys at 0 and 1 stay inside the window.
  const float width = std::max(em * 10.0f, ImGui::GetContentRegionAvail().x - 2.0f * handle);
  const ImVec2 origin(ImGui::GetCursorScreenPos().x + handle, ImGui::GetCursorScreenPos().y);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  for (int i = 0; i < Palette::kSize; ++i) {
    const Rgb& c = palette.colors[std::size_t(i)];
    const float x0 = origin.x + width * float(i) / Palette::kSize,
                x1 = origin.x + width * float(i + 1) / Palette::kSize;
    draw->AddRectFilled(ImVec2(x0, origin.y), ImVec2(x1 + 1.0f, origin.y + barHeight), colorOf(c.r, c.g, c.b));
  }
  draw->AddRect(origin, ImVec2(origin.x + width, origin.y + barHeight), IM_COL32(0, 0, 0, 200));
  // A double click on the bar adds a key there, with the colour the gradient has at that place.
  ImGui::SetCursorScreenPos(origin);
  ImGui::InvisibleButton("##bar", ImVec2(width, barHeight));
  state.probe.item("palette_editor.bar");
  if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && keys.size() < kMaxPaletteKeys) {
    const double at = std::clamp(double((ImGui::GetIO().MousePos.x - origin.x) / width), 0.0, 1.0);
    const Rgb c = palette.lookup(std::min(at, 0.9999));
    std::vector<PaletteKey> added = keys;
    added.push_back({at, c.r, c.g, c.b});
    selected_ = int(added.size()) - 1;
    edits.commit("Add palette key", setKeys(added));
  }
  contextHelp(state, "The 256 palette entries; double-click to add a key");
  const float rowY = ImGui::GetCursorScreenPos().y;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const float x = origin.x + float(keys[i].position) * width;
    ImGui::SetCursorScreenPos(ImVec2(x - handle, rowY));
    ImGui::PushID(int(i));
    ImGui::InvisibleButton("##key", ImVec2(2.0f * handle, 2.0f * handle));
    if (ImGui::IsItemActivated()) selected_ = int(i);
    // Dragging a key is one gesture: one undo step from press to release.
    const bool dragging = ImGui::IsItemActive() && ImGui::GetIO().MouseDelta.x != 0.0f;
    std::vector<PaletteKey> moved = keys;
    if (dragging) moved[i].position = std::clamp(double((ImGui::GetIO().MousePos.x - origin.x) / width), 0.0, 1.0);
    gestureItem(edits, "Move palette key", dragging, setKeys(moved));
    const bool chosen = int(i) == selected_;
    const ImVec2 tip(x, rowY), left(x - handle, rowY + 2.0f * handle), right(x + handle, rowY + 2.0f * handle);
    draw->AddTriangleFilled(tip, right, left, colorOf(keys[i].r, keys[i].g, keys[i].b));
    draw->AddTriangle(tip, right, left, chosen ? IM_COL32(255, 255, 255, 255) : IM_COL32(0, 0, 0, 220),
                      chosen ? 2.0f : 1.0f);
    ImGui::PopID();
  }
  ImGui::SetCursorScreenPos(ImVec2(origin.x, rowY + 2.0f * handle + em * 0.4f));
  ImGui::Dummy(ImVec2(width, 1.0f));
}

void PaletteEditor::drawKey(ModellerState& state, EditQueue& edits, const std::vector<PaletteKey>& keys) {
  selected_ = std::clamp(selected_, 0, int(keys.size()) - 1);
  const std::size_t i = std::size_t(selected_);
  ImGui::Text("Key %d of %zu", selected_ + 1, keys.size());
  ImGui::SameLine();
  ImGui::PushItemWidth(ImGui::GetFontSize() * 8.0f);
  double position = keys[i].position;
  const bool moved = sliderDouble("Position", position, 0.0, 1.0, "%.4f");
  std::vector<PaletteKey> changed = keys;
  changed[i].position = position;
  gestureItem(edits, "Move palette key", moved, setKeys(changed));
  state.probe.item("palette_editor.position");
  ImGui::PopItemWidth();
  float color[3] = {keys[i].r, keys[i].g, keys[i].b};
  const bool recoloured = ImGui::ColorEdit3("Colour", color, ImGuiColorEditFlags_Float);
  std::vector<PaletteKey> coloured = keys;
  coloured[i].r = color[0], coloured[i].g = color[1], coloured[i].b = color[2];
  gestureItem(edits, "Recolour palette key", recoloured, setKeys(coloured));
  state.probe.item("palette_editor.colour");
  ImGui::BeginDisabled(keys.size() <= 2);
  if (ImGui::Button("Delete key")) {
    std::vector<PaletteKey> fewer = keys;
    fewer.erase(fewer.begin() + std::ptrdiff_t(i));
    selected_ = std::max(0, selected_ - 1);
    edits.commit("Delete palette key", setKeys(fewer));
  }
  ImGui::EndDisabled();
  state.probe.item("palette_editor.delete");
  contextHelp(state, "A gradient keeps at least two keys");
  ImGui::SameLine();
  ImGui::BeginDisabled(keys.size() >= kMaxPaletteKeys);
  if (ImGui::Button("Add key")) {
    // In the middle of the widest gap, with the colour the gradient has there.
    std::vector<PaletteKey> sorted = keys;
    std::sort(sorted.begin(), sorted.end(),
              [](const PaletteKey& a, const PaletteKey& b) { return a.position < b.position; });
    double at = 0.5, widest = -1.0;
    for (std::size_t k = 0; k + 1 < sorted.size(); ++k)
      if (sorted[k + 1].position - sorted[k].position > widest)
        widest = sorted[k + 1].position - sorted[k].position, at = 0.5 * (sorted[k].position + sorted[k + 1].position);
    const Rgb c = paletteFromKeys(keys).lookup(std::min(at, 0.9999));
    std::vector<PaletteKey> added = keys;
    added.push_back({at, c.r, c.g, c.b});
    selected_ = int(added.size()) - 1;
    edits.commit("Add palette key", setKeys(added));
  }
  ImGui::EndDisabled();
  state.probe.item("palette_editor.add");
}

void PaletteEditor::drawSave(ModellerState& state, EditQueue& edits, const std::vector<PaletteKey>& keys) {
  ImGui::Separator();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10.0f);
  ImGui::InputText("##name", &name_);
  state.probe.item("palette_editor.name");
  ImGui::SameLine();
  ImGui::TextDisabled(".palette.json");
  ImGui::SameLine();
  if (ImGui::Button("Save palette")) {
    const std::filesystem::path projectFile = state.document.path();
    if (projectFile.empty()) {
      message_ = "Save the project first: the palette file goes beside it.";
    } else {
      try {
        const std::string reference = savePaletteGradient(projectFile.parent_path(), name_, keys);
        // One step: the project now names the file, and the keys it held are in the file.
        edits.commit("Save palette " + name_, SetPalette{reference});
        message_ = "Saved " + (projectFile.parent_path() / (name_ + ".palette.json")).string() + ".";
        state.info(message_);
      } catch (const std::exception& e) {
        message_ = std::string("Cannot save the palette: ") + e.what();
      }
    }
  }
  state.probe.item("palette_editor.save");
  contextHelp(state, "Write NAME.palette.json beside the project and use it as the palette");
}

}  // namespace gridifs::ui
