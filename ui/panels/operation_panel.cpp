// Every parameter of the active operation, edited live, drawn from the operation table
// (schema/operation_table.h): one widget per parameter with the table's label, range, format and
// tooltip (Gröller & Wegenkittl 1994, §2 and §4.3). Each slider drag is one undo step: the
// Document gesture begins on IsItemActivated and commits on deactivation; while dragging, the
// preview restarts every frame.
#include <imgui.h>

#include <algorithm>
#include <cctype>

#include "base/text_format.h"
#include "edit/node_picking.h"
#include "ui/base/widgets.h"
#include "ui/panels/key_button.h"
#include "ui/panels/operation_editor.h"
#include "ui/panels/panels.h"

namespace gridifs::ui {

bool scalarWidget(const ParamSpec& s, OpParams& params) {
  const bool slider = s.sliderMin < s.sliderMax;
  switch (s.type) {
    case ParamType::Number: {
      double& v = s.value<double>(params);
      const bool c = slider ? sliderDouble(s.label, v, s.sliderMin, s.sliderMax, s.format)
                            : dragDouble(s.label, v, s.speed, s.min, s.max, s.format);
      if (c) v = std::clamp(v, s.min, s.max);  // typed values too stay valid
      return c;
    }
    case ParamType::Integer: {
      int& v = s.value<int>(params);
      const bool c = slider ? ImGui::SliderInt(s.label, &v, int(s.sliderMin), int(s.sliderMax))
                            : ImGui::DragInt(s.label, &v, float(std::max(s.speed, 0.05)), int(s.min), int(s.max));
      if (c) v = std::clamp(v, int(s.min), int(s.max));
      return c;
    }
    case ParamType::Seed:
      return ImGui::InputScalar(s.label, ImGuiDataType_U64, &s.value<std::uint64_t>(params));
    case ParamType::Vector: {
      double* v = static_cast<double*>(s.locate(&params));
      const bool c = ImGui::DragScalarN(s.label, ImGuiDataType_Double, v, s.components, float(s.speed),
                                        slider ? &s.sliderMin : nullptr, slider ? &s.sliderMax : nullptr, s.format);
      if (c)
        for (int i = 0; i < s.components; ++i) v[i] = std::clamp(v[i], s.min, s.max);
      return c;
    }
    case ParamType::Choice: {
      int index = s.choice(params);
      if (!ImGui::Combo(s.label, &index, s.choices->labels.data(), int(s.choices->labels.size()))) return false;
      s.setChoice(params, index);
      return true;
    }
    default:
      return false;
  }
}

namespace {

void drawParams(OpEditor& e, const OperationSpec& spec) {
  bool expressionsDrawn = false;
  for (const ParamSpec& s : spec.params) {
    const std::string id = std::string(spec.type) + "." + s.key;
    switch (s.type) {
      case ParamType::Expression:
        if (!expressionsDrawn) drawExpressionParams(e, spec);
        expressionsDrawn = true;
        continue;
      case ParamType::CalculatorVars:
        drawCalculatorVars(e, spec, s);
        continue;
      case ParamType::MorphPairs:
        drawMorphPairs(e, spec, s);
        continue;
      case ParamType::NodeMoves:
        drawNodeMoves(e, s);
        continue;
      default:
        break;
    }
    const bool enabled = !s.enabled || s.enabled(&e.op.params);
    ImGui::BeginDisabled(!enabled);
    if (s.type == ParamType::Number || s.type == ParamType::Vector) {
      // Integers, seeds and choices are not keyed: a blend between two of them is not one of them.
      double values[4] = {0, 0, 0, 0};
      const int n = std::min(s.type == ParamType::Vector ? s.components : 1, 4);
      for (int c = 0; c < n; ++c) values[c] = s.number(e.op.params, c);
      keyButton(e.state, e.edits, e.function.path() + ".ops[" + std::to_string(e.index) + "]." + s.key, values, n);
    }
    const bool changed = scalarWidget(s, e.op.params);
    e.state.probe.item(id);
    e.item(std::string(spec.type) + " " + lowercase(s.label), changed);
    contextHelp(e.state, s.tooltip);
    ImGui::EndDisabled();
    if (s.placeable && ImGui::Button(("Move to center point##" + id).c_str())) {
      Vec3& point = s.value<Vec3>(e.op.params);
      point = e.state.pointCenter;
      e.commit(std::string("Place ") + lowercase(spec.title));
    }
    if (s.placeable) contextHelp(e.state, "Put it at the center point placed with Alt+click");
  }
}

void centerAndSelection(OpEditor& e) {
  if (ImGui::CollapsingHeader("Center and selection", ImGuiTreeNodeFlags_DefaultOpen)) {
    const bool absolute = operationSpec(e.op.params).absolute;
    ImGui::BeginDisabled(absolute);
    int kind = int(e.op.center.kind);
    static const char* kinds[] = {"grid center", "selection center", "point"};
    bool c = ImGui::Combo("Center", &kind, kinds, 3);
    if (c) {
      e.op.center.kind = Center::Kind(kind);
      if (e.op.center.kind == Center::Kind::Point) e.op.center.point = e.state.pointCenter;
    }
    e.item("Operation center", c);
    const std::string absoluteHelp = std::string(operationSpec(e.op.params).title) + " works in absolute coordinates";
    contextHelp(e.state,
                absolute ? absoluteHelp.c_str() : "Center of transformation (Gröller & Wegenkittl 1994, §4.3)");
    if (e.op.center.kind == Center::Kind::Point) {
      c = dragVec3("Point", e.op.center.point, 0.005);
      e.item("Center point", c);
      contextHelp(e.state, "Alt+click in a grid view to place it, or drag the cyan dot");
    }
    ImGui::EndDisabled();

    const Index3 res = e.state.function().resolution;
    const auto mask = e.op.selection.empty() ? std::vector<unsigned char>() : selectionMask(e.op.selection, res);
    std::size_t selected = 0;
    for (unsigned char m : mask) selected += m;
    if (e.op.selection.empty())
      ImGui::TextDisabled("Applies to all nodes");
    else
      ImGui::TextDisabled("Applies to %zu node%s (%zu box%s)", selected, selected == 1 ? "" : "s",
                          e.op.selection.size(), e.op.selection.size() == 1 ? "" : "es");
    if (ImGui::Button("Use current selection")) {
      e.edits.commit(SetOperationSelection{e.function, e.index, e.state.selection()});
    }
    contextHelp(e.state, "Apply this operation to the nodes selected now (all nodes when nothing is selected)");
    ImGui::SameLine();
    if (ImGui::Button("Select its nodes")) e.state.selection() = e.op.selection;
    contextHelp(e.state, "Make this operation's selection the current selection");
  }
}

}  // namespace

void drawOperationPanel(ModellerState& state, EditQueue& edits, OperationPanelState& panel) {
  state.clampIndices();
  if (isSetKind(state.function().kind)) {
    ImGui::TextWrapped("%s acts through its set, not a grid: it has no operations. Edit its set in the panel beside.",
                       state.function().name.c_str());
    return;
  }
  const Operation* current = state.op();
  if (!current) {
    ImGui::TextDisabled("Pick an operation in the stack, or add one.");
    return;
  }
  OpEditor e{state, panel, edits, state.activeFunction, state.activeOp, *current};
  const OperationSpec& spec = operationSpec(e.op.params);
  ImGui::PushItemWidth(-ImGui::CalcTextSize("Strength__").x);
  ImGui::PushID(int(state.activeOp));
  ImGui::TextUnformatted(spec.heading);
  drawParams(e, spec);
  ImGui::PopID();
  ImGui::PopItemWidth();
  ImGui::Spacing();
  centerAndSelection(e);
}

}  // namespace gridifs::ui
