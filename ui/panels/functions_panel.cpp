// The functions of the IFS (Gröller & Wegenkittl 1994, §4.5: each grid is positioned in the
// common initial grid by an affine placement).
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>

#include "edit/new_function.h"
#include "freeform/free_form.h"
#include "model/contractivity.h"
#include "model/final_function.h"
#include "schema/settings_tables.h"
#include "ui/base/widgets.h"
#include "ui/panels/key_button.h"
#include "ui/panels/panels.h"
#include "ui/panels/setting_slider.h"

namespace gridifs::ui {
namespace {

const ImVec4 kFinalColor{0.80f, 0.62f, 1.0f, 1.0f};  // the final function's row and lattice: violet

void setupColumns() {
  ImGui::TableSetupColumn("on", ImGuiTableColumnFlags_WidthFixed, ImGui::GetFrameHeight());
  ImGui::TableSetupColumn("color", ImGuiTableColumnFlags_WidthFixed, ImGui::GetFrameHeight());
  ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableSetupColumn("weight", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("w 0.000").x);
}

/// One row of the list: mute, colour, name (picks it), weight. The final function's row is violet
/// and shows its interpolation where the others show their weight.
void drawFunctionRow(ModellerState& state, EditQueue& edits, FunctionRef ref) {
  const Function& f = ref.in(state.document.project());
  const bool last = ref.isFinal();
  const std::string probeName = last ? "final" : std::to_string(ref.index());
  ImGui::PushID(last ? -1 : ref.index());
  ImGui::TableNextRow();
  if (last) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, ImGui::GetColorU32(ImVec4(0.45f, 0.30f, 0.65f, 0.22f)));
  ImGui::TableNextColumn();
  bool on = !f.muted;
  if (ImGui::Checkbox("##on", &on)) {
    const std::string what = last ? " final function" : " function";
    edits.commit((on ? "Unmute" : "Mute") + what, SetFunctionMuted{ref, !on});
  }
  state.probe.item("functions.mute." + probeName);
  contextHelp(state, last ? "A muted final function stays in the file; points are plotted as the IFS makes them"
                          : "Muted functions stay in the file but leave the IFS");
  ImGui::TableNextColumn();
  if (last)
    ImGui::TextColored(kFinalColor, " #");  // a lattice, not a colour of its own
  else
    ImGui::ColorButton("##c", ImVec4(float(f.color.x), float(f.color.y), float(f.color.z), 1.0f),
                       ImGuiColorEditFlags_NoTooltip, ImVec2(ImGui::GetFrameHeight(), ImGui::GetFrameHeight()));
  ImGui::TableNextColumn();
  if (last) ImGui::PushStyleColor(ImGuiCol_Text, kFinalColor);
  const std::string label = last ? "Final: " + f.name : f.name;
  const bool picked =
      ImGui::Selectable(label.c_str(), ref == state.activeFunction, ImGuiSelectableFlags_SpanAllColumns);
  if (last) ImGui::PopStyleColor();
  state.probe.item("functions.row." + probeName);
  if (last) contextHelp(state, "The final function: a lattice applied once more to every point before it is plotted");
  if (picked) state.activate(ref);
  ImGui::TableNextColumn();
  if (last)
    ImGui::TextDisabled("%s", f.interpolation == LatticeInterpolation::Bezier ? "Bézier" : "last");
  else
    ImGui::TextDisabled("w %.3g", f.weight);
  ImGui::PopID();
}

/// Name, resolution and placement: what every function has, the final one included.
void drawName(ModellerState& state, EditQueue& edits, FunctionRef ref, const Function& f) {
  std::string name = f.name;
  const bool changed = ImGui::InputText("Name", &name);
  gestureItem(edits, "Rename function", changed && !name.empty(), RenameFunction{ref, name});
  state.probe.frame(ref.isFinal() ? "final.name" : "function.name");
}

void drawResolution(ModellerState& state, EditQueue& edits, FunctionRef ref, const Function& f) {
  // A Bézier lattice's nodes are the control points of a tensor-product Bézier volume of degree
  // nodes − 1 per axis (Sederberg & Parry 1986, §2): at most 8 keeps the polynomial well behaved.
  const bool bezier = ref.isFinal() && f.interpolation == LatticeInterpolation::Bezier;
  const FieldInfo& field = gridResolutionField();
  const int fewest = int(field.min), most = bezier ? kMaxBezierLatticeNodes : int(field.max);
  int resolution[3] = {f.resolution[0], f.resolution[1], f.resolution[2]};
  const bool changed = ImGui::DragInt3(field.label, resolution, float(field.speed), fewest, most);
  state.probe.frame(ref.isFinal() ? "final.resolution" : "function.resolution");
  bool refused = false;
  for (int& r : resolution) {
    refused |= r > most;
    r = std::clamp(r, fewest, most);
  }
  if (refused && bezier) {
    state.finalFunctionMessage = "A Bézier lattice has at most " + std::to_string(kMaxBezierLatticeNodes) +
                                 " nodes per axis; switch to trilinear for a finer one.";
    state.error(state.finalFunctionMessage);
  } else if (changed && ref.isFinal()) {
    state.finalFunctionMessage.clear();  // a new resolution answers an earlier refusal
  }
  gestureItem(edits, "Grid resolution", changed,
              SetFunctionResolution{ref, {resolution[0], resolution[1], resolution[2]}});
  contextHelp(state, bezier ? "Nodes per axis (2..8 for a Bézier lattice); the stack is re-evaluated on the new grid"
                            : "Nodes per axis (2..128); the stack is re-evaluated on the new grid");
}

void drawPlacement(ModellerState& state, EditQueue& edits, FunctionRef ref, const Function& f) {
  if (!ImGui::CollapsingHeader("Placement", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const std::string path = ref.path();
  // Labels, drag speeds, formats and help from the placement's table (schema/settings_tables.h);
  // the drags of the rotation and the scale stop at a turn and at 4, which a hand needs.
  const SettingTableOf<Placement>& table = placementTable();
  const SettingSpec &translate = table.field("translate"), &rotate = table.field("rotate"),
                    &scale = table.field("scale");
  Placement pl = f.placement;
  keyButton(state, edits, path + ".placement.translate", &pl.translate.x, 3);
  bool changed = dragVec3(translate.label, pl.translate, translate.speed, 0.0, 0.0, translate.format);
  state.probe.frame("function.translate");
  gestureItem(edits, "Move placement", changed, SetPlacement{ref, pl});
  contextHelp(state, ref.isFinal() ? "Where the final lattice sits: it moves the whole picture" : translate.tooltip);
  keyButton(state, edits, path + ".placement.rotate", &pl.rotate.x, 3);
  changed = dragVec3(rotate.label, pl.rotate, rotate.speed, -360.0, 360.0, rotate.format);
  gestureItem(edits, "Rotate placement", changed, SetPlacement{ref, pl});
  contextHelp(state, rotate.tooltip);
  keyButton(state, edits, path + ".placement.scale", &pl.scale.x, 3);
  changed = dragVec3(scale.label, pl.scale, scale.speed, -4.0, 4.0, scale.format);
  state.probe.frame("function.scale");
  gestureItem(edits, "Scale placement", changed, SetPlacement{ref, pl});
  contextHelp(state, scale.tooltip);
}

/// The final function's own settings: how its lattice maps points, and its colour blend.
void drawFinalSettings(ModellerState& state, EditQueue& edits, const Function& f) {
  const FunctionRef ref = FunctionRef::finalFunction();
  const bool fitsBezier =
      std::all_of(f.resolution.begin(), f.resolution.end(), [](int r) { return r <= kMaxBezierLatticeNodes; });
  static const char* labels[] = {"Trilinear", "Bézier FFD"};
  const bool bezier = f.interpolation == LatticeInterpolation::Bezier;
  if (ImGui::BeginCombo("Interpolation", labels[bezier ? 1 : 0])) {
    if (ImGui::Selectable(labels[0], !bezier) && bezier) {
      state.finalFunctionMessage.clear();
      edits.commit(SetInterpolation{ref, LatticeInterpolation::Trilinear});
    }
    state.probe.item("final.interpolation.trilinear");
    contextHelp(state, "Each cell of the lattice maps its part of X trilinearly: what you see in the grid views");
    // Greyed, not disabled: a click on it says why it is refused.
    if (!fitsBezier) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    const bool picked = ImGui::Selectable(labels[1], bezier);
    if (!fitsBezier) ImGui::PopStyleColor();
    state.probe.item("final.interpolation.bezier");
    if (picked && !bezier) {
      if (fitsBezier) {
        state.finalFunctionMessage.clear();
        edits.commit(SetInterpolation{ref, LatticeInterpolation::Bezier});
      } else {
        char text[200];
        std::snprintf(
            text, sizeof text,
            "A Bézier lattice has at most %d nodes per axis, this one has %d×%d×%d: lower its resolution first.",
            kMaxBezierLatticeNodes, f.resolution[0], f.resolution[1], f.resolution[2]);
        state.finalFunctionMessage = text;
        state.error(text);
      }
    }
    contextHelp(state,
                fitsBezier
                    ? "The lattice's nodes as the control points of a smooth Bézier volume (Sederberg & Parry 1986)"
                    : "Needs at most 8 nodes per axis: lower the resolution first");
    ImGui::EndCombo();
  }
  state.probe.frame("final.interpolation");
  contextHelp(state, "How the lattice maps the attractor: trilinear cells, or a smooth Bézier free-form deformation");
  if (!state.finalFunctionMessage.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.6f, 0.3f, 1.0f));
    ImGui::TextWrapped("%s", state.finalFunctionMessage.c_str());
    ImGui::PopStyleColor();
    state.probe.item("final.message");
  }
  if (f.color_speed > 0.0) {
    // An imported flame's final xform also blends the colour (flam3); a new final function does not.
    float color[3] = {float(f.color.x), float(f.color.y), float(f.color.z)};
    const bool changed = ImGui::ColorEdit3("Color", color, ImGuiColorEditFlags_Float);
    gestureItem(edits, "Final function color", changed, SetFunctionColor{ref, Vec3(color[0], color[1], color[2])});
    contextHelp(state, "Each point's colour moves towards this one by the function's color speed");
  } else {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("Keeps each point's colour; weight and transitions do not apply.");
    ImGui::PopStyleColor();
  }
}

}  // namespace

void addFinalFunction(ModellerState& state, EditQueue& edits) {
  if (state.document.project().final_function) {
    state.activate(FunctionRef::finalFunction());
    return;
  }
  edits.commit(AddFinalFunction{});
  edits.after([&state] {
    state.finalSelection.clear();
    state.finalFunctionMessage.clear();
    state.activate(FunctionRef::finalFunction());
  });
}

void deleteFinalFunction(ModellerState& state, EditQueue& edits) {
  if (!state.document.project().final_function) return;
  edits.commit(RemoveFinalFunction{});
  edits.after([&state] {
    state.finalFunctionMessage.clear();
    state.clampIndices();  // the last function becomes active where the final one was
  });
}

void addFunction(ModellerState& state, EditQueue& edits) {
  const Project& p = state.document.project();
  if (int(p.functions.size()) >= limits::kMaxFunctions) {
    state.error("An IFS has at most " + std::to_string(limits::kMaxFunctions) + " functions.");
    return;
  }
  const int index = int(p.functions.size());
  edits.commit(AddFunction{newGridFunction(p)});
  edits.after([&state, index] { state.activate(FunctionRef(index)); });
}

void addSetFunction(ModellerState& state, EditQueue& edits, FunctionKind kind) {
  const Project& p = state.document.project();
  if (int(p.functions.size()) >= limits::kMaxFunctions) {
    state.error("An IFS has at most " + std::to_string(limits::kMaxFunctions) + " functions.");
    return;
  }
  if (p.space) {
    state.error("A free-form IFS takes matrix functions only.");
    return;
  }
  // The artist then moves the new set or picks another in the set editor.
  const int index = int(p.functions.size());
  edits.commit(AddFunction{newSetFunction(p, kind)});
  edits.after([&state, index] { state.activate(FunctionRef(index)); });
}

namespace {

/// Add, add a set function, duplicate, delete, and move the active function up or down.
void drawFunctionButtons(ModellerState& state, EditQueue& edits) {
  const Project& project = state.document.project();
  const int count = int(project.functions.size());
  const bool finalActive = state.activeFunction.isFinal();
  const int active = state.activeFunction.index();  // meaningless while the final function is active

  if (ImGui::Button("Add")) addFunction(state, edits);
  contextHelp(state, "Add a function: a new undistorted 6x6x6 grid placed at half size");
  state.probe.item("functions.add");
  if (!project.space) {
    // Set functions (Sokolov & Gentil, §3.1–3.2): Barnsley's constant map onto a set, or the
    // condensation function M(·, C) of the median images.
    ImGui::SameLine();
    if (ImGui::Button("Set...")) ImGui::OpenPopup("add_set");
    state.probe.item("functions.add_set");
    contextHelp(state, "Add a condensation or median function: one that acts through a set instead of a grid");
    if (ImGui::BeginPopup("add_set")) {
      if (ImGui::Selectable("Condensation function")) addSetFunction(state, edits, FunctionKind::Condensation);
      state.probe.item("functions.add_set.condensation");
      contextHelp(state, "When chosen, the point jumps to a random point of its set (Barnsley's condensation)");
      if (ImGui::Selectable("Median function")) addSetFunction(state, edits, FunctionKind::Median);
      state.probe.item("functions.add_set.median");
      contextHelp(state, "Maps a set halfway towards its own set (Sokolov & Gentil's median images); for volumes");
      ImGui::EndPopup();
    }
  }
  ImGui::SameLine();
  ImGui::BeginDisabled(finalActive);
  if (ImGui::Button("Duplicate") && count < limits::kMaxFunctions) {
    edits.commit(DuplicateFunction{active});
    edits.after([&state, active] { state.activeFunction = FunctionRef(active + 1); });
  }
  ImGui::EndDisabled();
  contextHelp(state, "Duplicate the active function with its whole operation stack");
  ImGui::SameLine();
  ImGui::BeginDisabled(!finalActive && count <= 1);
  if (ImGui::Button("Delete")) {
    if (finalActive) {
      deleteFinalFunction(state, edits);
    } else {
      edits.commit(RemoveFunction{active});
      edits.after([&state] {
        state.activeOp = -1;
        state.clampIndices();
      });
    }
  }
  ImGui::EndDisabled();
  contextHelp(state,
              finalActive ? "Remove the final function" : "Delete the active function (an IFS keeps at least one)");
  ImGui::SameLine();
  ImGui::BeginDisabled(finalActive || active == 0);
  if (ImGui::ArrowButton("##fup", ImGuiDir_Up)) {
    edits.commit(MoveFunction{active, active - 1});
    state.activeFunction = FunctionRef(active - 1);
    std::swap(state.selections[std::size_t(active)], state.selections[std::size_t(active - 1)]);
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(finalActive || active + 1 >= count);
  if (ImGui::ArrowButton("##fdown", ImGuiDir_Down)) {
    edits.commit(MoveFunction{active, active + 1});
    state.activeFunction = FunctionRef(active + 1);
    std::swap(state.selections[std::size_t(active)], state.selections[std::size_t(active + 1)]);
  }
  ImGui::EndDisabled();
}

void drawFunctionList(ModellerState& state, EditQueue& edits) {
  const Project& project = state.document.project();
  const int count = int(project.functions.size());
  // The list: mute, color, name, weight. The final function sits below it in a row of its own,
  // in violet, always in sight however long the list.
  const float rowHeight = ImGui::GetFrameHeightWithSpacing();
  const float listHeight = std::clamp(rowHeight * float(count) + 8.0f, rowHeight * 2.2f, rowHeight * 4.2f);
  const ImGuiTableFlags tableFlags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersOuter;
  if (ImGui::BeginTable("functions", 4, tableFlags | ImGuiTableFlags_ScrollY, ImVec2(0, listHeight))) {
    setupColumns();
    for (int i = 0; i < count; ++i) drawFunctionRow(state, edits, FunctionRef(i));
    ImGui::EndTable();
  }
  if (project.final_function) {
    if (ImGui::BeginTable("final", 4, tableFlags)) {
      setupColumns();
      drawFunctionRow(state, edits, FunctionRef::finalFunction());
      ImGui::EndTable();
    }
    if (ImGui::SmallButton("Remove final function")) deleteFinalFunction(state, edits);
    state.probe.item("functions.remove_final");
    contextHelp(state, "Remove the final function: points are plotted as the IFS makes them (Ctrl+Z brings it back)");
  } else {
    if (ImGui::SmallButton("Add final function")) addFinalFunction(state, edits);
    state.probe.item("functions.add_final");
    contextHelp(state,
                "Add a final function: an undistorted lattice around the attractor, applied before plotting; distort "
                "it to bend the whole picture");
  }
}

/// The bound of how much function `fi` of the IFS stretches distances, recomputed when the
/// geometry changes.
void drawContractivity(ModellerState& state, FunctionsPanelState& panel, int fi) {
  // Gröller & Wegenkittl 1994, §1.1: an IFS function must shrink distances.
  auto& contractivity = panel.contractivity;
  if (contractivity.revision != state.document.revisions().geometry || contractivity.function != fi) {
    contractivity.revision = state.document.revisions().geometry;
    contractivity.function = fi;
    try {
      contractivity.bound = estimateContractivity(*state.document.evaluatedGrid(std::size_t(fi))).bound;
      contractivity.valid = true;
    } catch (const std::exception&) {
      contractivity.valid = false;
    }
  }
  if (contractivity.valid) {
    const bool ok = contractivity.bound < 1.0;
    ImGui::TextColored(ok ? ImVec4(0.55f, 0.8f, 0.55f, 1.0f) : ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "Lipschitz bound %.3f%s",
                       contractivity.bound, ok ? "" : "  (not contractive)");
    contextHelp(state, "Upper bound of how much this function can stretch distances; below 1 the IFS converges");
  }
}

/// The active function's name, weight, colour, resolution, placement and contractivity.
void drawActiveFunction(ModellerState& state, EditQueue& edits, FunctionsPanelState& panel) {
  const FunctionRef activeRef = state.activeFunction;
  const bool finalActive = activeRef.isFinal();
  const int active = activeRef.index();  // meaningless while the final function is active
  const Function& f = state.function();
  ImGui::Spacing();
  ImGui::PushItemWidth(-ImGui::CalcTextSize(finalActive ? "Interpolation" : "Palette index").x -
                       ImGui::GetStyle().ItemInnerSpacing.x * 2);
  drawName(state, edits, activeRef, f);
  if (finalActive) {
    drawFinalSettings(state, edits, f);
    drawResolution(state, edits, activeRef, f);
    drawPlacement(state, edits, activeRef, f);
    drawVariationsSection(state, edits, panel, activeRef, f);
    ImGui::PopItemWidth();
    return;
  }
  const int fi = active;
  const std::string fpath = activeRef.path();

  // The function's own numbers: ranges, labels and help from its table (schema/settings_tables.h).
  const SettingTableOf<Function>& fields = functionTable();
  double weight = f.weight;
  keyButton(state, edits, fpath + ".weight", &weight);
  settingSlider(state, edits, fields.field("weight"), weight, fpath, {.probe = "function"});

  const SettingSpec& colorSpec = fields.field("color");
  float color[3] = {float(f.color.x), float(f.color.y), float(f.color.z)};
  bool changed = ImGui::ColorEdit3(colorSpec.label, color, ImGuiColorEditFlags_Float);
  gestureItem(edits, "Function color", changed, SetFunctionColor{activeRef, Vec3(color[0], color[1], color[2])});
  contextHelp(state, colorSpec.tooltip);

  settingSlider(state, edits, fields, fpath, "palette_index", f, {.probe = "function"});

  if (isSetKind(f.kind)) {
    // A set function has no grid: its set is edited in the set editor (the Operations panel's place).
    settingSlider(state, edits, fields, fpath, "color_speed", f, {.probe = "function"});
    ImGui::PopItemWidth();
    ImGui::TextWrapped("%s: its set is edited in the set editor below (in place of the operations).",
                       f.kind == FunctionKind::Median ? "A median function" : "A condensation function");
    return;
  }
  if (f.kind == FunctionKind::Matrix) {
    // A free-form IFS's function has no grid: its matrix and the control points are edited in
    // the Matrices window.
    ImGui::PopItemWidth();
    ImGui::TextWrapped("A %zu x %zu matrix on the control points' barycentric coordinates.", f.matrix.size(),
                       f.matrix.size());
    if (ImGui::Button("Edit matrices... (M)")) state.showMatrices = true;
    const double c = simplexContraction(f.matrix);
    ImGui::TextColored(c < 1.0 ? ImVec4(0.55f, 0.8f, 0.55f, 1.0f) : ImVec4(1.0f, 0.6f, 0.3f, 1.0f),
                       "Contracts the simplex by %.3f%s", c, c < 1.0 ? "" : "  (not contractive)");
    return;
  }
  drawResolution(state, edits, activeRef, f);
  drawPlacement(state, edits, activeRef, f);
  drawVariationsSection(state, edits, panel, activeRef, f);
  ImGui::PopItemWidth();
  drawContractivity(state, panel, fi);
}

}  // namespace

void drawFunctionsPanel(ModellerState& state, EditQueue& edits, FunctionsPanelState& panel) {
  state.clampIndices();
  drawFunctionButtons(state, edits);
  drawFunctionList(state, edits);
  drawActiveFunction(state, edits, panel);
}

}  // namespace gridifs::ui
