// The functions of the IFS (Gröller & Wegenkittl 1994, §4.5: each grid is positioned in the
// common initial grid by an affine placement).
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>

#include "model/contractivity.h"
#include "model/free_form.h"
#include "model/transition_matrix.h"
#include "ui/key_button.h"
#include "ui/panels.h"
#include "ui/widgets.h"

namespace gridifs::ui {
namespace {

std::string uniqueName(const Project& p, const std::string& base) {
  for (int n = 1;; ++n) {
    const std::string name = base + std::to_string(n);
    if (std::none_of(p.functions.begin(), p.functions.end(), [&](const Function& f) { return f.name == name; }))
      return name;
  }
}

/// Colors for new functions, spread around the hue circle.
Vec3 newFunctionColor(std::size_t index) {
  static const Vec3 palette[] = {{1.0, 0.6, 0.2}, {0.3, 0.7, 1.0}, {0.5, 0.95, 0.4}, {0.95, 0.35, 0.55},
                                 {0.95, 0.85, 0.3}, {0.6, 0.45, 1.0}, {0.3, 0.95, 0.85}, {1.0, 0.45, 0.3}};
  return palette[index % (sizeof palette / sizeof palette[0])];
}

}  // namespace

void addFunction(ModellerState& state, EditQueue& edits) {
  const Project& p = state.document.project();
  if (int(p.functions.size()) >= limits::kMaxFunctions) {
    state.error("An IFS has at most " + std::to_string(limits::kMaxFunctions) + " functions.");
    return;
  }
  Function f;
  f.name = uniqueName(p, "f");
  f.placement.scale = Vec3(0.5);
  f.color = newFunctionColor(p.functions.size());
  f.palette_index = p.functions.empty() ? 0.0 : std::min(1.0, double(p.functions.size()) / 4.0);
  if (p.space) {
    // A free-form IFS takes matrix functions: start with "halfway to the centroid of the control
    // points", a contraction the artist then edits in the Matrices window.
    const std::size_t m = p.space->control_points.size();
    f.kind = FunctionKind::Matrix;
    f.matrix.assign(m, std::vector<double>(m, 0.5 / double(m)));
    for (std::size_t i = 0; i < m; ++i) f.matrix[i][i] += 0.5;
  }
  const int index = int(p.functions.size());
  edits.commit("Add function", [f](Project& pr) { insertFunction(pr, pr.functions.size(), f); });
  edits.after([&state, index] {
    state.activeFunction = index;
    state.activeOp = -1;
    state.clampIndices();
  });
}

void drawFunctionsPanel(ModellerState& state, EditQueue& edits) {
  state.clampIndices();
  const Project& project = state.document.project();
  const int count = int(project.functions.size());
  const int active = state.activeFunction;

  if (ImGui::Button("Add")) addFunction(state, edits);
  contextHelp(state, "Add a function: a new undistorted 6x6x6 grid placed at half size");
  state.probe.item("functions.add");
  ImGui::SameLine();
  if (ImGui::Button("Duplicate") && count < limits::kMaxFunctions) {
    Function copy = project.functions[std::size_t(active)];
    copy.name = uniqueName(project, copy.name + "_");
    edits.commit("Duplicate function", [copy, active](Project& p) {
      insertFunction(p, std::size_t(active + 1), copy);
    });
    edits.after([&state, active] { state.activeFunction = active + 1; });
  }
  contextHelp(state, "Duplicate the active function with its whole operation stack");
  ImGui::SameLine();
  ImGui::BeginDisabled(count <= 1);
  if (ImGui::Button("Delete")) {
    edits.commit("Delete function", [active](Project& p) { eraseFunction(p, std::size_t(active)); });
    edits.after([&state] {
      state.activeOp = -1;
      state.clampIndices();
    });
  }
  ImGui::EndDisabled();
  contextHelp(state, "Delete the active function (an IFS keeps at least one)");
  ImGui::SameLine();
  ImGui::BeginDisabled(active == 0);
  if (ImGui::ArrowButton("##fup", ImGuiDir_Up)) {
    edits.commit("Move function up", [active](Project& p) { swapFunctions(p, std::size_t(active), std::size_t(active - 1)); });
    state.activeFunction = active - 1;
    std::swap(state.selections[std::size_t(active)], state.selections[std::size_t(active - 1)]);
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(active + 1 >= count);
  if (ImGui::ArrowButton("##fdown", ImGuiDir_Down)) {
    edits.commit("Move function down", [active](Project& p) { swapFunctions(p, std::size_t(active), std::size_t(active + 1)); });
    state.activeFunction = active + 1;
    std::swap(state.selections[std::size_t(active)], state.selections[std::size_t(active + 1)]);
  }
  ImGui::EndDisabled();

  // The list: mute, color, name, weight.
  const float rowHeight = ImGui::GetFrameHeightWithSpacing();
  const float listHeight = std::clamp(rowHeight * float(count) + 8.0f, rowHeight * 2.2f, rowHeight * 4.2f);
  if (ImGui::BeginTable("functions", 4,
                        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersOuter | ImGuiTableFlags_ScrollY,
                        ImVec2(0, listHeight))) {
    ImGui::TableSetupColumn("on", ImGuiTableColumnFlags_WidthFixed, ImGui::GetFrameHeight());
    ImGui::TableSetupColumn("color", ImGuiTableColumnFlags_WidthFixed, ImGui::GetFrameHeight());
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("weight", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("w 0.000").x);
    for (int i = 0; i < count; ++i) {
      const Function& f = project.functions[std::size_t(i)];
      ImGui::PushID(i);
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      bool on = !f.muted;
      if (ImGui::Checkbox("##on", &on))
        edits.commit(on ? "Unmute function" : "Mute function", [i, on](Project& p) { p.functions[std::size_t(i)].muted = !on; });
      contextHelp(state, "Muted functions stay in the file but leave the IFS");
      ImGui::TableNextColumn();
      ImGui::ColorButton("##c", ImVec4(float(f.color.x), float(f.color.y), float(f.color.z), 1.0f),
                         ImGuiColorEditFlags_NoTooltip, ImVec2(ImGui::GetFrameHeight(), ImGui::GetFrameHeight()));
      ImGui::TableNextColumn();
      const bool picked = ImGui::Selectable(f.name.c_str(), i == active, ImGuiSelectableFlags_SpanAllColumns);
      state.probe.item("functions.row." + std::to_string(i));
      if (picked) {
        if (i != active) state.activeOp = -1;
        state.activeFunction = i;
      }
      ImGui::TableNextColumn();
      ImGui::TextDisabled("w %.3g", f.weight);
      ImGui::PopID();
    }
    ImGui::EndTable();
  }

  const Function& f = project.functions[std::size_t(active)];
  const int fi = active;
  ImGui::Spacing();
  ImGui::PushItemWidth(-ImGui::CalcTextSize("Palette idx").x - ImGui::GetStyle().ItemInnerSpacing.x * 2);

  std::string name = f.name;
  bool changed = ImGui::InputText("Name", &name);
  gestureItem(edits, "Rename function", changed && !name.empty(), [fi, name](Project& p) { p.functions[std::size_t(fi)].name = name; });

  double weight = f.weight;
  const std::string fpath = "functions[" + std::to_string(fi) + "]";
  keyButton(state, edits, fpath + ".weight", &weight);
  changed = dragDouble("Weight", weight, 0.01, 0.0, 1000.0, "%.3f");
  gestureItem(edits, "Function weight", changed, [fi, weight](Project& p) { p.functions[std::size_t(fi)].weight = weight; });
  contextHelp(state, "Probability of choosing this function is proportional to its weight");

  float color[3] = {float(f.color.x), float(f.color.y), float(f.color.z)};
  changed = ImGui::ColorEdit3("Color", color, ImGuiColorEditFlags_Float);
  gestureItem(edits, "Function color", changed, [fi, color](Project& p) {
    p.functions[std::size_t(fi)].color = Vec3(color[0], color[1], color[2]);
  });

  double paletteIndex = f.palette_index;
  changed = sliderDouble("Palette idx", paletteIndex, 0.0, 1.0);
  gestureItem(edits, "Palette index", changed, [fi, paletteIndex](Project& p) { p.functions[std::size_t(fi)].palette_index = paletteIndex; });
  contextHelp(state, "Structural color coordinate c_i for flame-style coloring (Draves & Reckase 2003, §5)");

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
  int resolution[3] = {f.resolution[0], f.resolution[1], f.resolution[2]};
  changed = ImGui::DragInt3("Resolution", resolution, 0.1f, limits::kMinResolution, limits::kMaxResolution);
  for (int& r : resolution) r = std::clamp(r, limits::kMinResolution, limits::kMaxResolution);
  gestureItem(edits, "Grid resolution", changed, [fi, resolution](Project& p) {
    p.functions[std::size_t(fi)].resolution = {resolution[0], resolution[1], resolution[2]};
  });
  contextHelp(state, "Nodes per axis (2..128); the stack is re-evaluated on the new grid");

  if (ImGui::CollapsingHeader("Placement", ImGuiTreeNodeFlags_DefaultOpen)) {
    Placement pl = f.placement;
    keyButton(state, edits, fpath + ".placement.translate", &pl.translate.x, 3);
    changed = dragVec3("Translate", pl.translate, 0.005);
    state.probe.frame("function.translate");
    gestureItem(edits, "Move placement", changed, [fi, pl](Project& p) { p.functions[std::size_t(fi)].placement = pl; });
    contextHelp(state, "Where the grid sits in the common initial grid; also: drag it in the IFS view");
    keyButton(state, edits, fpath + ".placement.rotate", &pl.rotate.x, 3);
    changed = dragVec3("Rotate", pl.rotate, 0.5, -360.0, 360.0, "%.1f°");
    gestureItem(edits, "Rotate placement", changed, [fi, pl](Project& p) { p.functions[std::size_t(fi)].placement = pl; });
    keyButton(state, edits, fpath + ".placement.scale", &pl.scale.x, 3);
    changed = dragVec3("Scale", pl.scale, 0.005, -4.0, 4.0);
    state.probe.frame("function.scale");
    gestureItem(edits, "Scale placement", changed, [fi, pl](Project& p) { p.functions[std::size_t(fi)].placement = pl; });
  }
  ImGui::PopItemWidth();

  // Contractivity (Gröller & Wegenkittl 1994, §1.1): an IFS function must shrink distances.
  auto& contractivity = state.contractivity;
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

}  // namespace gridifs::ui
