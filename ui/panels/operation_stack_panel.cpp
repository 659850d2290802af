// The active function's operation stack (Gröller & Wegenkittl 1994, §2, §4.3): add each
// op with the current selection, pick, reorder, mute and delete.
#include <imgui.h>

#include <cmath>
#include <cstdio>

#include "model/stack_evaluator.h"
#include "ui/base/widgets.h"
#include "ui/panels/panels.h"

namespace gridifs::ui {
namespace {

std::string summary(const Operation& op) {
  std::string s = operationSummary(op.params);
  if (!op.selection.empty()) s += "  [sel]";
  return s;
}

}  // namespace

void addOperation(ModellerState& state, EditQueue& edits, const OperationSpec& spec) {
  state.clampIndices();
  const Function& f = state.function();
  if (isSetKind(f.kind)) {
    state.error(f.name + " is a set function: it has no grid to operate on.");
    return;
  }
  if (int(f.ops.size()) >= limits::kMaxOpsPerFunction) {
    state.error("A function has at most " + std::to_string(limits::kMaxOpsPerFunction) + " operations.");
    return;
  }
  const Operation op = newOperation(spec, state.selection(), state.newOpCenter, state.pointCenter, state.localGrid());
  const int at = state.activeOp < 0 ? int(f.ops.size()) : state.activeOp + 1;
  edits.commit(AddOperation{state.activeFunction, at, op});
  edits.after([&state, at] { state.activeOp = at; });
}

void deleteActiveOperation(ModellerState& state, EditQueue& edits) {
  if (!state.op()) return;
  const FunctionRef fi = state.activeFunction;
  const int oi = state.activeOp;
  edits.commit(RemoveOperation{fi, oi});
  edits.after([&state, oi] {
    state.activeOp = oi - 1;
    state.clampIndices();
    if (state.activeOp < 0 && !state.function().ops.empty()) state.activeOp = 0;
  });
}

namespace {

/// Rows of the add toolbar's buttons, wrapped to `available` pixels.
int toolbarRows(float available) {
  const ImGuiStyle& style = ImGui::GetStyle();
  int rows = 1;
  float x = 0.0f;
  for (const OperationSpec& spec : operationTable()) {
    if (!spec.addable) continue;
    const float w = ImGui::CalcTextSize(spec.title).x + style.FramePadding.x * 2;
    if (x > 0.0f && x + style.ItemSpacing.x + w <= available) {
      x += style.ItemSpacing.x + w;
    } else {
      if (x > 0.0f) ++rows;
      x = w;
    }
  }
  return rows;
}

constexpr float kStackRowsShown = 3.5f;  // the first rows always in sight (and a hint of more)

float stackButtonsHeight() { return ImGui::GetFrameHeightWithSpacing() + ImGui::GetStyle().ItemSpacing.y; }

}  // namespace

float operationStackPanelMinHeight(float panelWidth) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float title = ImGui::GetFontSize() + style.FramePadding.y * 2;
  const float inner = panelWidth - style.WindowPadding.x * 2 - style.ScrollbarSize;
  return std::ceil(title + style.WindowPadding.y * 2 + ImGui::GetTextLineHeightWithSpacing() +
                   float(toolbarRows(inner)) * ImGui::GetFrameHeightWithSpacing() + style.ItemSpacing.y +
                   kStackRowsShown * ImGui::GetFrameHeightWithSpacing() + stackButtonsHeight());
}

void drawOperationStackPanel(ModellerState& state, EditQueue& edits) {
  state.clampIndices();
  const Function& f = state.function();
  const FunctionRef fi = state.activeFunction;
  const int count = int(f.ops.size());

  // Toolbar: one button per op kind, wrapping to the panel width; where the panel is too short
  // for the buttons and the first rows of the stack, one button opens the same list.
  ImGui::TextDisabled("Add to %s%s:", f.name.c_str(), state.hasSelection() ? " (selection)" : "");
  const float available = ImGui::GetContentRegionAvail().x;
  const float rowsLeft = ImGui::GetContentRegionAvail().y - stackButtonsHeight() - ImGui::GetStyle().ItemSpacing.y -
                         float(toolbarRows(available)) * ImGui::GetFrameHeightWithSpacing();
  const bool compact = rowsLeft < 2.0f * ImGui::GetFrameHeightWithSpacing();
  if (compact) {
    ImGui::SameLine();
    if (ImGui::SmallButton("Add operation...")) ImGui::OpenPopup("addop");
    state.probe.item("ops.add");
    contextHelp(state, "Add an operation after the active one, applied to the current selection");
    if (ImGui::BeginPopup("addop")) {
      for (const OperationSpec& spec : operationTable()) {
        if (!spec.addable) continue;
        if (ImGui::Selectable(spec.title)) addOperation(state, edits, spec);
        state.probe.item(std::string("ops.add.") + spec.title);
      }
      ImGui::EndPopup();
    }
  } else {
    float x = 0.0f;
    for (const OperationSpec& spec : operationTable()) {
      if (!spec.addable) continue;
      const char* label = spec.title;
      const float w = ImGui::CalcTextSize(label).x + ImGui::GetStyle().FramePadding.x * 2;
      if (x > 0.0f && x + ImGui::GetStyle().ItemSpacing.x + w <= available)
        ImGui::SameLine();
      else
        x = 0.0f;
      if (ImGui::Button(label)) addOperation(state, edits, spec);
      state.probe.item(std::string("ops.add.") + label);
      if (ImGui::IsItemHovered())
        state.contextHelp =
            std::string("Add a ") + label + " operation after the active one, applied to the current selection";
      x += (x > 0.0f ? ImGui::GetStyle().ItemSpacing.x : 0.0f) + w;
    }
  }
  ImGui::Separator();

  if (ImGui::BeginChild("stack", ImVec2(0, -stackButtonsHeight()), false)) {
    state.probe.window("ops.stack");
    if (count == 0) ImGui::TextDisabled("No operations: the grid is undistorted.");
    for (int o = 0; o < count; ++o) {
      const Operation& op = f.ops[std::size_t(o)];
      ImGui::PushID(o);
      bool on = !op.muted;
      if (ImGui::Checkbox("##on", &on)) edits.commit(SetOperationMuted{fi, o, !on});
      contextHelp(state, "Mute: skip this operation when evaluating the stack");
      ImGui::SameLine();
      char label[64];
      std::snprintf(label, sizeof label, "%d  %s", o + 1, operationSpec(op.params).title);
      ImGui::PushStyleColor(ImGuiCol_Text, op.muted ? ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]
                                                    : ImGui::GetStyle().Colors[ImGuiCol_Text]);
      if (ImGui::Selectable(label, o == state.activeOp, ImGuiSelectableFlags_AllowItemOverlap))
        state.activeOp = (o == state.activeOp) ? -1 : o;
      ImGui::PopStyleColor();
      state.probe.item("ops.row." + std::to_string(o));
      ImGui::SameLine(ImGui::GetFontSize() * 9.5f);
      ImGui::TextDisabled("%s", summary(op).c_str());
      ImGui::PopID();
    }
  }
  ImGui::EndChild();

  const int active = state.activeOp;
  ImGui::BeginDisabled(active <= 0);
  if (ImGui::ArrowButton("##up", ImGuiDir_Up)) {
    edits.commit(MoveOperation{fi, active, active - 1});
    state.activeOp = active - 1;
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(active < 0 || active + 1 >= count);
  if (ImGui::ArrowButton("##down", ImGuiDir_Down)) {
    edits.commit(MoveOperation{fi, active, active + 1});
    state.activeOp = active + 1;
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(active < 0);
  if (ImGui::Button("Duplicate") && count < limits::kMaxOpsPerFunction) {
    edits.commit(DuplicateOperation{fi, active});
    state.activeOp = active + 1;
  }
  ImGui::SameLine();
  if (ImGui::Button("Delete")) deleteActiveOperation(state, edits);
  contextHelp(state, "Delete the active operation (Delete key)");
  ImGui::EndDisabled();
}

}  // namespace gridifs::ui
