// The Field layers panel: the volume's fractal field layers ("volume.field") — Colonna's fields
// ("Animation of fractal objects", §2) that shape the measure attractor's density, lay clouds of
// their own or raise a mountain (his fig. 6), each optionally blended with a shape (fig. 3). Every
// parameter of the field operation but its amplitude, from the operation table, with the layer's
// strength, role, height and shape; one undo step per slider drag, key buttons on the numbers
// (tracks volume.field.KEY, or volume.field[i].KEY when there are several layers).
#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "base/text_format.h"
#include "edit/field_layer_edits.h"
#include "schema/field_layer.h"
#include "schema/settings_tables.h"
#include "ui/base/widgets.h"
#include "ui/panels/key_button.h"
#include "ui/panels/operation_editor.h"
#include "ui/panels/panels.h"
#include "ui/panels/setting_slider.h"

namespace gridifs::ui {
namespace {

/// What one layer's widgets share: the layer's index and the local copy they edit.
struct LayerEditor {
  ModellerState& state;
  EditQueue& edits;
  std::size_t index;
  VolumeDensityField value;

  /// The gesture of the item just submitted (one undo step per drag).
  void item(const std::string& label, bool changed, const std::string& probe) {
    state.probe.item("fieldlayer" + std::to_string(index) + "." + probe);
    gestureItem(edits, label, changed, SetFieldLayer{index, value});
  }
  void commit(const std::string& label) { edits.commit(label, SetFieldLayer{index, value}); }
  bool list = false;  // several layers: tracks name them volume.field[i]

  /// The layer's path: volume.field, or volume.field[i] in a list.
  std::string path() const {
    return list ? "volume.field[" + std::to_string(index) + "]" : std::string("volume.field");
  }
  /// The key button of the layer's number `key`.
  void key(const std::string& key, const double* values, int components) {
    keyButton(state, edits, path() + "." + key, values, components);
  }
  /// The key button and slider of one of the layer's own numbers (fieldLayerTable()): one
  /// SetParameter a gesture, named by the table's label.
  void number(const char* key) {
    const SettingSpec& spec = fieldLayerTable().field(key);
    const double current = spec.number(&value);
    this->key(key, &current, 1);
    settingSlider(state, edits, spec, current, path(), {.probe = "fieldlayer" + std::to_string(index)});
  }
};

void drawRole(LayerEditor& e) {
  static const char* roles[] = {"density", "cloud", "terrain"};
  int role = int(e.value.role);
  if (ImGui::Combo("Role", &role, roles, 3)) {
    e.value.role = FieldRole(role);
    e.commit(std::string("Field layer: ") + roles[role]);
  }
  e.state.probe.item("fieldlayer" + std::to_string(e.index) + ".role");
  contextHelp(e.state,
              "density: weights the attractor's density; cloud: a cloud of its own about its height, as thick as it "
              "is dense; terrain: a mountain, solid below height + strength·field");
  e.number("strength");
  if (e.value.role == FieldRole::Density) return;
  e.number("height");
  if (e.value.role != FieldRole::Cloud) return;
  e.number("thickness");
}

void drawFieldParams(LayerEditor& e) {
  const OperationSpec& spec = *findOperation("field");
  for (const ParamSpec& s : spec.params) {
    if (std::string_view(s.key) == "amplitude") continue;  // the strength plays its part
    OpParams params{e.value.field};
    if (s.type == ParamType::Number || s.type == ParamType::Vector) {
      double values[4] = {0, 0, 0, 0};
      const int n = std::min(s.type == ParamType::Vector ? s.components : 1, 4);
      for (int c = 0; c < n; ++c) values[c] = s.number(params, c);
      e.key(s.key, values, n);
    }
    const bool changed = scalarWidget(s, params);
    if (changed) e.value.field = std::get<FieldOp>(params);
    e.item("Field " + lowercase(s.label), changed, s.key);
    contextHelp(e.state, s.tooltip);
  }
}

void drawShape(LayerEditor& e) {
  bool blended = e.value.shape.has_value();
  if (ImGui::Checkbox("Blend with a shape", &blended)) {
    if (blended) {
      e.value.shape = CondensationSet{};
    } else {
      e.value.shape.reset();
    }
    e.commit(blended ? "Blend field with shape" : "Field without shape");
  }
  e.state.probe.item("fieldlayer" + std::to_string(e.index) + ".shape");
  contextHelp(e.state,
              "Colonna's interpolation between the field and a geometric shape: (1 − blend)·field + "
              "blend·shape, the shape 1 inside, −1 outside");
  if (!e.value.shape) return;
  CondensationSet& set = *e.value.shape;
  static const char* shapes[] = {"sphere", "box", "torus"};
  int shape = std::clamp(int(set.shape), 0, 2);
  if (ImGui::Combo("Shape", &shape, shapes, 3)) {
    set.shape = SetShape(shape);
    e.commit(std::string("Field shape: ") + shapes[shape]);
  }
  // The shape's numbers from the sets' table: the same ranges a function's set has.
  const SettingTableOf<CondensationSet>& table = condensationSetTable(set.shape);
  for (const SettingSpec& spec : table.fields) {
    const bool changed = settingDrag(spec, &set);
    e.item(std::string("Field shape ") + lowercase(spec.label), changed, std::string("shape.") + spec.key);
    contextHelp(e.state, spec.tooltip);
  }
  e.number("blend");
  e.number("softness");
}

void drawLayer(ModellerState& state, EditQueue& edits, std::size_t index, const VolumeDensityField& layer) {
  LayerEditor e{state, edits, index, layer, fieldLayerCount(state.document.project()) > 1};
  char title[48];
  std::snprintf(title, sizeof title, "Layer %zu: %s", index + 1, toString(layer.role));
  sectionTitle(title);
  drawRole(e);
  drawFieldParams(e);
  drawShape(e);
  if (ImGui::Button("Remove layer")) edits.commit(RemoveFieldLayer{index});
  state.probe.item("fieldlayer" + std::to_string(index) + ".remove");
}

}  // namespace

void drawFieldLayersPanel(ModellerState& state, EditQueue& edits) {
  const Project& project = state.document.project();
  const std::size_t count = fieldLayerCount(project);
  if (count == 0)
    ImGui::TextWrapped(
        "No field layer: the volume is the measure attractor's density as it is. Add a fractal field "
        "to shape it, lay clouds or raise a mountain.");
  ImGui::PushItemWidth(-ImGui::CalcTextSize("Interpolation_").x);
  for (std::size_t i = 0; i < count; ++i) {
    ImGui::PushID(int(i));
    drawLayer(state, edits, i, *fieldLayerAt(project, i));
    ImGui::PopID();
  }
  ImGui::PopItemWidth();
  ImGui::Spacing();
  ImGui::BeginDisabled(count >= kMaxFieldLayers);
  for (FieldRole role : {FieldRole::Density, FieldRole::Cloud, FieldRole::Terrain}) {
    if (role != FieldRole::Density) ImGui::SameLine();
    const std::string label = std::string("Add ") + toString(role);
    if (ImGui::Button(label.c_str())) edits.commit(AddFieldLayer{role});
    state.probe.item(std::string("fieldlayers.add.") + toString(role));
  }
  ImGui::EndDisabled();
  contextHelp(state, "A new field layer: density shapes the attractor, cloud and terrain add their own density");
}

}  // namespace gridifs::ui
