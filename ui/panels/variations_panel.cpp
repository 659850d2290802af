// A function's flame variations (Draves & Reckase 2003, §3 and the appendix's catalogue): f(p) =
// post(Σ w_i V_i(g(p))). Each variation's blend weight and parameters are sliders (one undo step
// per drag, keyable); a searchable list adds one; the post map is a placement after the sum.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cctype>

#include "ui/base/widgets.h"
#include "ui/panels/key_button.h"
#include "ui/panels/panels.h"
#include "variations/flame_variations.h"

namespace gridifs::ui {
namespace {

bool matches(const std::string& name, const std::string& filter) {
  if (filter.empty()) return true;
  auto lower = [](std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  return lower(name).find(lower(filter)) != std::string::npos;
}

/// One variation of the function: its weight, a remove button, then its parameters.
void drawVariation(ModellerState& state, EditQueue& edits, FunctionRef ref, const Function& f, const std::string& name,
                   double weight) {
  const FlameVariation* v = findFlameVariation(name);
  const std::string path = ref.path();
  ImGui::PushID(name.c_str());
  keyButton(state, edits, path + ".variations." + name, &weight);
  const bool changed = dragDouble(name.c_str(), weight, 0.005, -10.0, 10.0, "%.3f");
  state.probe.frame("variations.weight." + name);
  gestureItem(edits, "Variation weight", changed,
              SetParameter{path + ".variations." + name, weight, "Variation weight"});
  contextHelp(state, "Blend weight w of this variation in f(p) = post(Σ w V(g(p)))");
  ImGui::SameLine();
  if (ImGui::SmallButton("x")) edits.commit(RemoveVariation{ref, name});
  state.probe.item("variations.remove." + name);
  contextHelp(state, "Remove this variation (and its parameters)");
  if (v && !v->params.empty()) {
    ImGui::Indent();
    for (const auto& [attribute, fallback] : v->params) {
      const auto it = f.variation_params.find(attribute);
      double value = it == f.variation_params.end() ? fallback : it->second;
      // A parameter is keyable once the file holds it (after its first edit).
      if (it != f.variation_params.end()) keyButton(state, edits, path + ".variation_params." + attribute, &value);
      const bool moved = dragDouble(attribute, value, 0.01, -1000.0, 1000.0, "%.3f");
      state.probe.frame(std::string("variations.param.") + attribute);
      gestureItem(edits, "Variation parameter", moved,
                  SetParameter{path + ".variation_params." + attribute, value, "Variation parameter"});
    }
    ImGui::Unindent();
  }
  if (v && v->random) {
    ImGui::SameLine();
    ImGui::TextDisabled("(random)");
  }
  ImGui::PopID();
}

/// The searchable list of every variation the function does not use yet.
void drawAddVariation(ModellerState& state, EditQueue& edits, FunctionsPanelState& panel, FunctionRef ref,
                      const Function& f) {
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::InputTextWithHint("##variation_filter", "Add a variation: type to search", &panel.variationFilter);
  state.probe.frame("variations.filter");
  if (!ImGui::BeginListBox("##variation_list", ImVec2(-1.0f, ImGui::GetTextLineHeightWithSpacing() * 5.5f))) return;
  for (const FlameVariation& v : flameVariations()) {
    const std::string name = v.name;
    if (f.variations.count(name) || !matches(name, panel.variationFilter)) continue;
    if (ImGui::Selectable(v.name)) {
      edits.commit(AddVariation{ref, name});
      panel.variationFilter.clear();
    }
    state.probe.item("variations.add." + name);
  }
  ImGui::EndListBox();
}

/// The post map: off, or a placement (rotate, scale, translate) after the variations' sum; a
/// flame's general post matrix is shown as its rows.
void drawPost(ModellerState& state, EditQueue& edits, FunctionRef ref, const Function& f) {
  bool on = f.post.has_value();
  if (ImGui::Checkbox("Post transform", &on))
    edits.commit(SetPostTransform{ref, on ? std::optional<PostTransform>(PostTransform{}) : std::nullopt});
  state.probe.item("variations.post");
  contextHelp(state, "An affine map after the variations' sum (flam3's post transform)");
  if (!f.post) return;
  const std::string path = ref.path() + ".post";
  PostTransform post = *f.post;
  if (post.matrix) {
    for (int r = 0; r < 3; ++r) {
      auto& row = (*post.matrix)[std::size_t(r)];
      float values[4] = {float(row[0]), float(row[1]), float(row[2]), float(row[3])};
      const std::string label = std::string("Row ") + "xyz"[r];
      const bool changed = ImGui::DragFloat4(label.c_str(), values, 0.005f);
      for (int c = 0; c < 4; ++c) row[std::size_t(c)] = double(values[c]);
      gestureItem(edits, "Post transform", changed, SetPostTransform{ref, post});
    }
    return;
  }
  keyButton(state, edits, path + ".rotate", &post.placement.rotate.x, 3);
  bool changed = dragVec3("Post rotate", post.placement.rotate, 0.5, -360.0, 360.0, "%.1f°");
  gestureItem(edits, "Post transform", changed, SetPostTransform{ref, post});
  keyButton(state, edits, path + ".scale", &post.placement.scale.x, 3);
  changed = dragVec3("Post scale", post.placement.scale, 0.005, -4.0, 4.0);
  gestureItem(edits, "Post transform", changed, SetPostTransform{ref, post});
  keyButton(state, edits, path + ".translate", &post.placement.translate.x, 3);
  changed = dragVec3("Post move", post.placement.translate, 0.005);
  gestureItem(edits, "Post transform", changed, SetPostTransform{ref, post});
}

}  // namespace

void drawVariationsSection(ModellerState& state, EditQueue& edits, FunctionsPanelState& panel, FunctionRef ref,
                           const Function& f) {
  const ImGuiTreeNodeFlags flags = f.hasVariationStage() ? ImGuiTreeNodeFlags_DefaultOpen : 0;
  const bool open = ImGui::CollapsingHeader("Variations", flags);
  state.probe.item("variations.header");
  if (!open) return;
  if (f.variations.empty())
    ImGui::TextWrapped("None: the function is its grid map. Add flame variations to bend it as flames do.");
  for (const auto& [name, weight] : f.variations) drawVariation(state, edits, ref, f, name, weight);
  drawAddVariation(state, edits, panel, ref, f);
  drawPost(state, edits, ref, f);
}

}  // namespace gridifs::ui
