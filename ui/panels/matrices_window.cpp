// The Matrices window: the transition matrix of a graph-directed IFS (which function may follow
// which; Thollot, Zair, Tosan & Vandorpe 1997, §3.2) and, in a free-form project, the control
// points and the active function's barycentric matrix (§3.1), with presets for both. Every
// change is one undo step through the edit queue; drags are one gesture.
#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "freeform/free_form.h"
#include "freeform/free_form_deformation.h"
#include "freeform/free_form_joints.h"
#include "freeform/free_form_presets.h"
#include "freeform/transition_matrix.h"
#include "model/final_function.h"
#include "schema/settings_tables.h"
#include "ui/base/widgets.h"
#include "ui/panels/panels.h"

namespace gridifs::ui {
namespace {

/// One cell of a matrix: drag sets the value (one gesture), a click without a drag toggles
/// between 0 and 1 when `toggles`. `set` makes the named edit that sets the cell to a value.
template <class SetCell>
void matrixCell(EditQueue& edits, const char* id, double value, double minimum, double maximum, bool toggles,
                const char* what, const SetCell& set) {
  float v = float(value);
  const bool zero = value == 0.0;
  if (zero) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  const bool changed =
      ImGui::DragFloat(id, &v, 0.01f, float(minimum), float(maximum), "%.3g", ImGuiSliderFlags_AlwaysClamp);
  if (zero) ImGui::PopStyleColor();
  const bool clicked = toggles && ImGui::IsItemDeactivated() && !ImGui::IsItemDeactivatedAfterEdit() &&
                       ImGui::GetIO().MouseDragMaxDistanceSqr[0] < 4.0f;
  gestureItem(edits, what, changed, set(double(v)));
  if (clicked) edits.commit(std::string("Toggle ") + what, set(zero ? 1.0 : 0.0));
}

void drawTransitions(ModellerState& state, EditQueue& edits) {
  const Project& project = state.document.project();
  const std::size_t n = project.functions.size();
  sectionTitle("Transitions (which function may follow which)");
  bool restricted = !project.transitions.empty();
  if (ImGui::Checkbox("Restrict transitions", &restricted)) {
    if (restricted)
      edits.commit("Restrict transitions", SetTransitionPreset{TransitionPreset::All});
    else
      edits.commit(RemoveTransitions{});
  }
  state.probe.item("matrices.restrict");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Row i weights the functions that may follow function i; 0 forbids that step");
  ImGui::SameLine();
  const struct {
    const char* label;
    TransitionPreset preset;
  } presets[] = {{"All", TransitionPreset::All},
                 {"No repeats", TransitionPreset::NoRepeats},
                 {"Cycle i to i+1", TransitionPreset::Cycle}};
  for (const auto& p : presets) {
    if (ImGui::SmallButton(p.label))
      edits.commit(std::string("Transitions: ") + p.label, SetTransitionPreset{p.preset});
    state.probe.item(std::string("matrices.transitions.") + p.label);
    ImGui::SameLine();
  }
  ImGui::NewLine();
  if (!restricted || project.transitions.size() != n) return;
  const float cell = ImGui::CalcTextSize("0.000").x + ImGui::GetStyle().FramePadding.x * 2;
  if (ImGui::BeginTable("transitions", int(n) + 1, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX,
                        ImVec2(0, 0))) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextDisabled("after \\ next");
    for (std::size_t j = 0; j < n; ++j) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(project.functions[j].name.c_str());
    }
    for (std::size_t i = 0; i < n; ++i) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(project.functions[i].name.c_str());
      for (std::size_t j = 0; j < n; ++j) {
        ImGui::TableNextColumn();
        ImGui::PushID(int(i * n + j));
        ImGui::SetNextItemWidth(cell);
        // The range the file reader and validation use (one description of a transition weight).
        const FieldInfo& weight = transitionWeightField();
        matrixCell(
            edits, "##t", project.transitions[i][j], weight.min, weight.max, true, "transition weight",
            [i, j, &weight](double v) {
              return SetParameter{"transitions[" + std::to_string(i) + "][" + std::to_string(j) + "]", v, weight.label};
            });
        state.probe.item("matrices.transition." + std::to_string(i) + "." + std::to_string(j));
        ImGui::PopID();
      }
    }
    ImGui::EndTable();
  }
}

/// "Cubic Bezier curve", "Biquadratic uniform B-spline patch": the undo step's name.
std::string presetLabel(const char* label, FreeFormPreset preset, int degree) {
  static const char* const names[] = {"Linear", "Quadratic", "Cubic", "Quartic", "Quintic", "Sextic", "Septic"};
  if (preset == FreeFormPreset::Sierpinski) return label;
  std::string name = names[std::clamp(degree, 1, 7) - 1];
  const bool patch = preset != FreeFormPreset::BezierCurve && preset != FreeFormPreset::BSplineCurve;
  if (patch) name = "Bi" + std::string(1, char(std::tolower(name[0]))) + name.substr(1);
  if (preset == FreeFormPreset::SierpinskiPatch) return std::string(label) + " (" + name + ")";
  std::string rest = label;
  rest[0] = char(std::tolower(rest[0]));  // "Cubic uniform B-spline curve"
  if (rest.rfind("bezier", 0) == 0) rest[0] = 'B';
  return name + " " + rest;
}

void drawPresets(ModellerState& state, EditQueue& edits, MatricesWindowState& choice) {
  sectionTitle("Free-form presets (control points and matrices)");
  const FreeFormPreset presets[] = {FreeFormPreset::BezierCurve,  FreeFormPreset::BezierPatch,
                                    FreeFormPreset::BSplineCurve, FreeFormPreset::BSplinePatch,
                                    FreeFormPreset::Sierpinski,   FreeFormPreset::SierpinskiPatch};
  const char* labels[] = {"Bezier curve",
                          "Bezier patch",
                          "Uniform B-spline curve",
                          "Uniform B-spline patch",
                          "Sierpinski gasket (3 points)",
                          "Sierpinski gasket on a patch"};
  const float width = ImGui::GetFontSize() * 14;
  ImGui::SetNextItemWidth(width);
  ImGui::Combo("Preset", &choice.preset, labels, 6);
  state.probe.item("matrices.preset");
  const FreeFormPreset preset = presets[std::clamp(choice.preset, 0, 5)];
  if (preset != FreeFormPreset::Sierpinski) {
    ImGui::SetNextItemWidth(width);
    ImGui::SliderInt("Degree", &choice.degree, kMinPresetDegree, kMaxPresetDegree);
    state.probe.item("matrices.degree");
  }
  const bool bspline = preset == FreeFormPreset::BSplineCurve || preset == FreeFormPreset::BSplinePatch;
  if (!bspline) {
    ImGui::SetNextItemWidth(width);
    ImGui::SliderFloat("Split r", &choice.split, 0.05f, 0.95f, "%.2f");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Where de Casteljau subdivision cuts the curve in two");
    ImGui::SetNextItemWidth(width);
    ImGui::SliderFloat("Roughness", &choice.roughness, 0.0f, 0.5f, "%.2f");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Perturbs the subdivision matrices (rows still sum to 1): smooth shapes become fractal");
    ImGui::SetNextItemWidth(width);
    ImGui::InputInt("Seed", &choice.seed);
  }
  const bool replace = ImGui::Button("Replace the functions with this preset");
  state.probe.item("matrices.apply_preset");
  if (replace) {
    FreeFormPresetOptions options;
    options.degree = std::clamp(choice.degree, kMinPresetDegree, kMaxPresetDegree);
    options.split = choice.split;
    options.roughness = bspline ? 0.0 : choice.roughness;
    options.seed = std::uint64_t(std::max(choice.seed, 0));
    edits.commit("Preset: " + presetLabel(labels[choice.preset], preset, options.degree),
                 ApplyFreeFormPreset{preset, options});
    state.activeFunction = FunctionRef(0);
    state.activeOp = -1;
    choice.jointBaseline.reset();
  }
  if (state.document.project().space && ImGui::Button("Back to a grid IFS")) {
    edits.commit(BackToGridIfs{});
    state.activeFunction = FunctionRef(0);
    state.activeOp = -1;
  }
}

/// F̂ (Thollot et al. 1997, §5.5): this grid IFS's functions as matrices on a control net.
void drawControlNet(ModellerState& state, EditQueue& edits, MatricesWindowState& choice) {
  sectionTitle("Map this IFS onto a control net");
  const float width = ImGui::GetFontSize() * 14;
  const char* shapes[] = {"Flat (move the points to deform)", "Elliptic paraboloid", "Hyperbolic paraboloid"};
  ImGui::SetNextItemWidth(width);
  ImGui::Combo("Net", &choice.netShape, shapes, 3);
  ImGui::SetNextItemWidth(width);
  ImGui::SliderInt("Net degree", &choice.netDegree, 1, kMaxPlanarNetDegree);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Total degree of the net: a triangle's (n+1)(n+2)/2 points, a tetrahedron's up to degree 5");
  if (choice.netShape != 0) {
    ImGui::SetNextItemWidth(width);
    ImGui::SliderFloat("Height", &choice.netHeight, -2.0f, 2.0f, "%.2f");
  }
  const bool map = ImGui::Button("Map onto the net");
  state.probe.item("matrices.map_onto_net");
  if (map) {
    MapOntoControlNet edit;
    edit.options.degree = choice.netDegree;
    edit.options.shape = ControlNetShape(std::clamp(choice.netShape, 0, 2));
    edit.options.height = choice.netHeight;
    try {
      // Tried first so that a project the net cannot take says why here, next to the button.
      const ControlNetResult result = mapOntoControlNet(state.document.project(), edit.options);
      choice.netMessage = result.notes.empty() ? std::string() : result.notes.front();
      edits.commit(edit);
      state.activeFunction = FunctionRef(0);
      state.activeOp = -1;
      choice.jointBaseline.reset();
    } catch (const ModelError& e) {
      choice.netMessage = e.what();
    }
  }
  if (!choice.netMessage.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "%s", choice.netMessage.c_str());
    ImGui::PopTextWrapPos();
  }
}

void drawControlPoints(ModellerState& state, EditQueue& edits) {
  const Project& project = state.document.project();
  const auto& points = project.space->control_points;
  sectionTitle("Control points");
  ImGui::BeginDisabled(points.size() >= std::size_t(limits::kMaxControlPoints));
  if (ImGui::SmallButton("Add control point")) edits.commit(AddControlPoint{});
  ImGui::EndDisabled();
  state.probe.item("matrices.add_point");
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(
        "A Bezier curve is degree-elevated (same curve); otherwise the new point has a zero column "
        "and the mean row, so nothing moves until you edit its column");
  if (ImGui::BeginChild("points",
                        ImVec2(0, std::min(float(points.size()) + 0.5f, 6.5f) * ImGui::GetFrameHeightWithSpacing()))) {
    for (std::size_t j = 0; j < points.size(); ++j) {
      ImGui::PushID(int(j));
      float v[3] = {float(points[j].x), float(points[j].y), float(points[j].z)};
      char label[32];
      std::snprintf(label, sizeof label, "p%zu", j);
      const FieldInfo& point = controlPointField();
      const bool changed =
          ImGui::DragFloat3(label, v, float(point.speed), float(point.sliderMin), float(point.sliderMax), point.format);
      gestureItem(edits, "Move control point", changed, MoveControlPoint{j, Vec3{v[0], v[1], v[2]}});
      state.probe.item("matrices.point." + std::to_string(j));
      ImGui::SameLine();
      ImGui::BeginDisabled(points.size() <= std::size_t(limits::kMinControlPoints));
      if (ImGui::SmallButton("x")) edits.commit(RemoveControlPoint{j});
      ImGui::EndDisabled();
      state.probe.item("matrices.remove_point." + std::to_string(j));
      if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("Remove this point; every matrix loses its row and column");
      ImGui::PopID();
    }
  }
  ImGui::EndChild();
}

/// The joints a hand edit broke (Thollot et al. 1997, §5.3.2), against the project as it was
/// before the first edit that broke one: a gasket, whose pieces never joined, never warns.
bool sameShape(const Project& a, const Project& b) {
  return a.functions.size() == b.functions.size() && a.space && b.space &&
         a.space->control_points.size() == b.space->control_points.size();
}

void drawJointWarnings(ModellerState& state, MatricesWindowState& window) {
  const Project& project = state.document.project();
  if (window.jointBaseline && !sameShape(*window.jointBaseline, project)) window.jointBaseline.reset();
  if (!window.jointBaseline) return;
  if (window.jointRevision != state.document.revision()) {
    window.jointRevision = state.document.revision();
    window.jointWarnings.clear();
    for (const FreeFormJoint& j : brokenJoints(*window.jointBaseline, project))
      window.jointWarnings.push_back(describeJoint(project, j));
  }
  ImGui::PushTextWrapPos(0.0f);
  for (const std::string& w : window.jointWarnings) ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "%s", w.c_str());
  ImGui::PopTextWrapPos();
  state.probe.item("matrices.joint_warnings");
}

/// A matrix cell is about to be edited: the joints are judged against the project as it is now,
/// unless an earlier edit already broke one (then against the project before that edit).
void startMatrixEdit(const Project& project, MatricesWindowState& window) {
  if (!window.jointBaseline || !sameShape(*window.jointBaseline, project) ||
      brokenJoints(*window.jointBaseline, project).empty())
    window.jointBaseline = project;
  window.jointRevision = 0;
}

void drawFunctionMatrix(ModellerState& state, EditQueue& edits, MatricesWindowState& window) {
  const Project& project = state.document.project();
  if (state.activeFunction.isFinal()) return;  // the final function is a lattice, never a matrix
  const std::size_t fi = std::size_t(std::clamp(state.activeFunction.index(), 0, int(project.functions.size()) - 1));
  const Function& f = project.functions[fi];
  if (f.kind != FunctionKind::Matrix) return;
  const std::size_t m = f.matrix.size();
  sectionTitle(("Matrix of " + f.name + " (coordinates <- coordinates x matrix; rows sum to 1)").c_str());
  const float cell = ImGui::CalcTextSize("-0.000").x + ImGui::GetStyle().FramePadding.x * 2;
  if (ImGui::BeginTable("matrix", int(m) + 1, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX)) {
    for (std::size_t i = 0; i < m; ++i) {
      ImGui::TableNextRow();
      for (std::size_t j = 0; j < m; ++j) {
        ImGui::TableNextColumn();
        ImGui::PushID(int(i * m + j));
        ImGui::SetNextItemWidth(cell);
        // The edited entry is balanced by the row's diagonal (or last) entry, so the row keeps
        // summing to 1 and every intermediate state of a drag is valid.
        matrixCell(edits, "##m", f.matrix[i][j], barycentricEntryField().min, barycentricEntryField().max, false,
                   "matrix entry", [fi = int(fi), i, j](double v) {
                     return SetMatrixEntry{fi, i, j, v};
                   });
        if (ImGui::IsItemActivated()) startMatrixEdit(project, window);
        state.probe.item("matrices.entry." + std::to_string(i) + "." + std::to_string(j));
        ImGui::PopID();
      }
      ImGui::TableNextColumn();
      double sum = 0.0;
      for (double v : f.matrix[i]) sum += v;
      ImGui::TextDisabled("sum %.6g", sum);
    }
    ImGui::EndTable();
  }
  ImGui::TextDisabled("Dragging an entry balances the row on its diagonal entry (the next one on the diagonal).");
  const double c = simplexContraction(f.matrix);
  if (c >= 1.0)
    ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "Not a contraction of the simplex (%.3g).", c);
  else
    ImGui::TextDisabled("Contracts the simplex by %.3g.", c);
  drawJointWarnings(state, window);
}

}  // namespace

void drawMatricesWindow(ModellerState& state, EditQueue& edits, MatricesWindowState& window) {
  if (!state.showMatrices) return;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + vp->WorkSize.x * 0.5f, vp->WorkPos.y + vp->WorkSize.y * 0.5f),
                          ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(std::min(ImGui::GetFontSize() * 40, vp->WorkSize.x * 0.95f),
                                  std::min(ImGui::GetFontSize() * 38, vp->WorkSize.y * 0.9f)),
                           ImGuiCond_Appearing);
  if (!ImGui::Begin("Matrices", &state.showMatrices, ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  state.probe.window("window.matrices");
  // A floating window over the tiled panels: in front when it opens, or it may open behind one.
  if (ImGui::IsWindowAppearing()) ImGui::SetWindowFocus();
  drawPresets(state, edits, window);
  ImGui::Spacing();
  if (!state.document.project().space) {
    drawControlNet(state, edits, window);
    ImGui::Spacing();
  }
  drawTransitions(state, edits);
  ImGui::Spacing();
  if (state.document.project().space) {
    drawControlPoints(state, edits);
    drawFunctionMatrix(state, edits, window);
  }
  ImGui::End();
}

}  // namespace gridifs::ui
