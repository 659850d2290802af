// Every parameter of the active operation, edited live (Gröller & Wegenkittl 1994, §2 and
// §4.3). Each slider drag is one undo step: the Document gesture begins on IsItemActivated
// and commits on deactivation; while dragging, the preview restarts every frame.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>

#include "model/calculator.h"
#include "edit/node_picking.h"
#include "ui/panels.h"
#include "ui/widgets.h"

namespace gridifs::ui {
namespace {

/// Context for one op editor: where the op lives and how to hand the edited copy over.
struct OpEditor {
  ModellerState& state;
  EditQueue& edits;
  int function, index;
  Operation op;  // the local copy widgets edit

  void item(const std::string& label, bool changed) {
    const int f = function, o = index;
    const Operation copy = op;
    gestureItem(edits, label, changed, [f, o, copy](Project& p) { p.functions[std::size_t(f)].ops[std::size_t(o)] = copy; });
  }
};

const char* kAxes[] = {"x", "y", "z"};
const char* kProfiles[] = {"linear", "sine", "ping-pong"};

bool axisCombo(const char* label, Axis& axis) {
  int a = int(axis);
  if (!ImGui::Combo(label, &a, kAxes, 3)) return false;
  axis = Axis(a);
  return true;
}

bool profileCombo(const char* label, Profile& profile) {
  int p = int(profile);
  if (!ImGui::Combo(label, &p, kProfiles, 3)) return false;
  profile = Profile(p);
  return true;
}

template <class Op>
void profileOp(OpEditor& e, Op& p, const char* name, double kRange, const char* kHelp) {
  const std::string n = name;
  bool c = axisCombo("Axis", p.axis);
  e.item(n + " axis", c);
  c = profileCombo("Profile", p.profile);
  e.item(n + " profile", c);
  e.state.contextHelp = ImGui::IsItemHovered() ? "linear: k·t · sine: k·sin(ω·t) · ping-pong: k·tri(ω·t) (Gröller & Wegenkittl 1994, figure 13)"
                                               : e.state.contextHelp;
  c = sliderDouble("k", p.k, -kRange, kRange);
  e.state.probe.item(n + ".k");
  e.item(n + " k", c);
  contextHelp(e.state, kHelp);
  ImGui::BeginDisabled(p.profile == Profile::Linear);
  c = sliderDouble("omega", p.omega, 0.0, 4.0 * M_PI);
  e.item(n + " omega", c);
  contextHelp(e.state, "Frequency ω of the sine and ping-pong profiles along the axis");
  ImGui::EndDisabled();
}

void calculatorEditor(OpEditor& e, CalculatorOp& calc) {
  auto& buffer = e.state.calculatorEdit;
  const std::array<std::string, 3> current{calc.x, calc.y, calc.z};
  if (buffer.function != e.function || buffer.op != e.index || buffer.base != current) {
    buffer.function = e.function;
    buffer.op = e.index;
    buffer.text = buffer.base = current;
  }
  CalculatorOp candidate = calc;
  candidate.x = buffer.text[0];
  candidate.y = buffer.text[1];
  candidate.z = buffer.text[2];
  const auto diagnostic = checkCalculator(candidate);
  static const char* labels[] = {"x =", "y =", "z ="};
  static const char* ids[] = {"##cx", "##cy", "##cz"};
  for (int i = 0; i < 3; ++i) {
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(labels[i]);
    ImGui::SameLine();
    const bool bad = diagnostic && diagnostic->expression == i;
    if (bad) ImGui::PushStyleColor(ImGuiCol_FrameBg, ImVec4(0.45f, 0.12f, 0.10f, 1.0f));
    ImGui::SetNextItemWidth(-1);
    const float fieldX = ImGui::GetCursorPosX();
    const bool typed = ImGui::InputText(ids[i], &buffer.text[std::size_t(i)]);
    if (bad) ImGui::PopStyleColor();
    e.state.probe.item(std::string("calculator.") + kAxes[i]);
    // Only valid expressions reach the document; what is typed stays in the field.
    candidate.x = buffer.text[0];
    candidate.y = buffer.text[1];
    candidate.z = buffer.text[2];
    const bool valid = !checkCalculator(candidate);
    if (typed && valid) {
      calc = candidate;
      buffer.base = {candidate.x, candidate.y, candidate.z};
    }
    e.item("Calculator expression", typed && valid);
    contextHelp(e.state, "Variables x y z (node), cx cy cz (center), i j k (indices), v1 v2 v3; sin cos tan asin "
                         "acos atan sinh cosh tanh log exp sqrt abs min max pow rand(), pi, e");
    if (bad) {
      // A caret under the offending character, then the message.
      const std::string& text = buffer.text[std::size_t(i)];
      const std::size_t at = std::size_t(std::clamp(diagnostic->position, 0, int(text.size())));
      ImGui::SetCursorPosX(fieldX + ImGui::GetStyle().FramePadding.x + ImGui::CalcTextSize(text.substr(0, at).c_str()).x -
                           ImGui::CalcTextSize("^").x * 0.5f);
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.35f, 1.0f));
      ImGui::TextUnformatted(diagnostic->position >= 0 ? "^" : "");
      ImGui::SameLine();
      ImGui::TextWrapped("%s", diagnostic->message.c_str());
      ImGui::PopStyleColor();
    }
  }
  ImGui::Spacing();
  for (int v = 0; v < 3; ++v) {
    ImGui::PushID(v);
    CalculatorVar& var = calc.vars[std::size_t(v)];
    const float w = ImGui::GetContentRegionAvail().x;
    const float rangeWidth = ImGui::CalcTextSize("-000.00").x + ImGui::GetStyle().FramePadding.x * 2;
    ImGui::SetNextItemWidth(rangeWidth);
    bool c = dragDouble("##min", var.min, 0.01, -1e6, 1e6, "%.2f");
    e.item("Calculator range", c);
    contextHelp(e.state, "Lower end of the slider's range");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(std::max(40.0f, w - 2 * rangeWidth - ImGui::CalcTextSize("v1").x - 4 * ImGui::GetStyle().ItemSpacing.x));
    const double lo = std::min(var.min, var.max), hi = std::max(var.min, var.max);
    char label[8];
    std::snprintf(label, sizeof label, "##v%d", v + 1);
    c = sliderDouble(label, var.value, lo, hi == lo ? lo + 1.0 : hi);
    e.state.probe.item("calculator.v" + std::to_string(v + 1));
    e.item("Calculator v" + std::to_string(v + 1), c);
    contextHelp(e.state, "A user variable of the expressions (Gröller & Wegenkittl 1994, §4.3); its range is editable on both sides");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(rangeWidth);
    c = dragDouble("##max", var.max, 0.01, -1e6, 1e6, "%.2f");
    e.item("Calculator range", c);
    contextHelp(e.state, "Upper end of the slider's range");
    ImGui::SameLine();
    ImGui::Text("v%d", v + 1);
    ImGui::PopID();
  }
  int seed = int(calc.seed % 1000000);
  const bool c = ImGui::InputInt("rand() seed", &seed);
  if (c) calc.seed = std::uint64_t(std::max(0, seed));
  e.item("Calculator seed", c);
}

void morphEditor(OpEditor& e, MorphOp& morph) {
  bool c = sliderDouble("Strength", morph.strength, -2.0, 2.0);
  e.item("Morph strength", c);
  contextHelp(e.state, "1: every start point lands exactly on its end point (Gröller & Wegenkittl 1994, §2.6)");
  bool& asDirection = e.state.morphAsDirection;
  ImGui::Checkbox("Enter end as direction", &asDirection);
  int remove = -1;
  for (std::size_t i = 0; i < morph.pairs.size(); ++i) {
    ImGui::PushID(int(i));
    ImGui::Separator();
    ImGui::TextDisabled("Vector %zu", i + 1);
    ImGui::SameLine(ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("Remove").x);
    if (ImGui::SmallButton("Remove")) remove = int(i);
    MorphPair& pair = morph.pairs[i];
    c = dragVec3("Start", pair.from, 0.005);
    e.item("Morph start", c);
    contextHelp(e.state, "Start point P_i (absolute); drag the white dot in a grid view");
    if (asDirection) {
      Vec3 dir = pair.to - pair.from;
      c = dragVec3("Direction", dir, 0.005);
      if (c) pair.to = pair.from + dir;
    } else {
      c = dragVec3("End", pair.to, 0.005);
    }
    e.item("Morph end", c);
    contextHelp(e.state, "End point Q_i (absolute); drag the yellow dot in a grid view");
    ImGui::PopID();
  }
  if (remove >= 0 && morph.pairs.size() > 1) {
    morph.pairs.erase(morph.pairs.begin() + remove);
    const int f = e.function, o = e.index;
    const Operation copy = e.op;
    e.edits.commit("Remove morph vector", [f, o, copy](Project& p) { p.functions[std::size_t(f)].ops[std::size_t(o)] = copy; });
  }
  ImGui::BeginDisabled(int(morph.pairs.size()) >= limits::kMaxMorphPairs);
  if (ImGui::Button("Add vector")) {
    MorphPair pair;
    pair.from = e.state.pointCenter + Vec3(0.1 * double(morph.pairs.size() + 1), 0.0, 0.0);
    pair.to = pair.from + Vec3(0.0, 0.0, 0.2);
    morph.pairs.push_back(pair);
    const int f = e.function, o = e.index;
    const Operation copy = e.op;
    e.edits.commit("Add morph vector", [f, o, copy](Project& p) { p.functions[std::size_t(f)].ops[std::size_t(o)] = copy; });
  }
  ImGui::EndDisabled();
  contextHelp(e.state, "Add a start → end vector at the placed center point (InterIFS used up to eight)");
}

void centerAndSelection(OpEditor& e) {
  if (ImGui::CollapsingHeader("Center and selection", ImGuiTreeNodeFlags_DefaultOpen)) {
    const bool absolute = std::holds_alternative<MagnetOp>(e.op.params) || std::holds_alternative<MorphOp>(e.op.params);
    ImGui::BeginDisabled(absolute);
    int kind = int(e.op.center.kind);
    static const char* kinds[] = {"grid center", "selection center", "point"};
    bool c = ImGui::Combo("Center", &kind, kinds, 3);
    if (c) {
      e.op.center.kind = Center::Kind(kind);
      if (e.op.center.kind == Center::Kind::Point) e.op.center.point = e.state.pointCenter;
    }
    e.item("Operation center", c);
    contextHelp(e.state, absolute ? "Magnet and morph work in absolute coordinates" : "Center of transformation (Gröller & Wegenkittl 1994, §4.3)");
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
    if (e.op.selection.empty()) ImGui::TextDisabled("Applies to all nodes");
    else ImGui::TextDisabled("Applies to %zu node%s (%zu box%s)", selected, selected == 1 ? "" : "s", e.op.selection.size(),
                             e.op.selection.size() == 1 ? "" : "es");
    if (ImGui::Button("Use current selection")) {
      const Selection s = e.state.selection();
      const int f = e.function, o = e.index;
      e.edits.commit("Set operation selection", [f, o, s](Project& p) { p.functions[std::size_t(f)].ops[std::size_t(o)].selection = s; });
    }
    contextHelp(e.state, "Apply this operation to the nodes selected now (all nodes when nothing is selected)");
    ImGui::SameLine();
    if (ImGui::Button("Select its nodes")) e.state.selection() = e.op.selection;
    contextHelp(e.state, "Make this operation's selection the current selection");
  }
}

}  // namespace

void drawOperationPanel(ModellerState& state, EditQueue& edits) {
  state.clampIndices();
  const Operation* current = state.op();
  if (!current) {
    ImGui::TextDisabled("Pick an operation in the stack, or add one.");
    return;
  }
  OpEditor e{state, edits, state.activeFunction, state.activeOp, *current};
  ImGui::PushItemWidth(-ImGui::CalcTextSize("Strength__").x);
  std::visit(
      [&](auto& p) {
        using T = std::decay_t<decltype(p)>;
        ImGui::PushID(int(state.activeOp));
        if constexpr (std::is_same_v<T, TranslateOp>) {
          ImGui::TextUnformatted("Translate");
          const bool c = dragVec3("Offset", p.offset, 0.005);
          state.probe.item("translate.offset");
          e.item("Translate", c);
        } else if constexpr (std::is_same_v<T, RotateOp>) {
          ImGui::TextUnformatted("Rotate (R = Rz·Ry·Rx, degrees)");
          const bool c = dragVec3("Angles", p.angles, 0.5, -360.0, 360.0, "%.1f°");
          e.item("Rotate", c);
        } else if constexpr (std::is_same_v<T, ScaleOp>) {
          ImGui::TextUnformatted("Scale");
          const bool c = dragVec3("Factors", p.factors, 0.005, -10.0, 10.0);
          e.item("Scale", c);
        } else if constexpr (std::is_same_v<T, TaperOp>) {
          ImGui::TextUnformatted("Taper (Gröller & Wegenkittl 1994, §2.2)");
          profileOp(e, p, "taper", 3.0, "Taper strength: the cross-section scales by f(t) = 1 + k·profile(t)");
        } else if constexpr (std::is_same_v<T, TwistOp>) {
          ImGui::TextUnformatted("Twist (Gröller & Wegenkittl 1994, §2.3)");
          profileOp(e, p, "twist", 2.0 * M_PI, "Twist rate in radians per unit along the axis");
        } else if constexpr (std::is_same_v<T, BendOp>) {
          ImGui::TextUnformatted("Bend (Gröller & Wegenkittl 1994, §2.4, Barr)");
          bool c = axisCombo("Axis", p.axis);
          e.item("Bend axis", c);
          c = axisCombo("Toward", p.toward);
          e.item("Bend toward", c);
          if (p.toward == p.axis) ImGui::TextColored(ImVec4(1, 0.5f, 0.3f, 1), "Toward must differ from the axis.");
          c = sliderDouble("k", p.k, -3.0, 3.0);
          state.probe.item("bend.k");
          e.item("Bend k", c);
          contextHelp(state, "Curvature: the bend radius is 1/k; 0 leaves the grid straight");
        } else if constexpr (std::is_same_v<T, MagnetOp>) {
          ImGui::TextUnformatted("Magnet (Gröller & Wegenkittl 1994, §2.5)");
          bool c = sliderDouble("Distance", p.dmax, 0.0, 3.0);
          e.item("Magnet distance", c);
          contextHelp(state, "Range d_max: nodes farther from the magnet do not move");
          c = sliderDouble("Strength", p.strength, -1.0, 1.0);
          state.probe.item("magnet.strength");
          e.item("Magnet strength", c);
          contextHelp(state, "Pull toward the magnet (negative pushes away)");
          c = sliderDouble("Decrease", p.falloff, 0.0, 8.0);
          e.item("Magnet decrease", c);
          contextHelp(state, "Falloff exponent p of ((d_max - d)/d_max)^p");
          c = dragVec3("Point", p.point, 0.005);
          e.item("Magnet point", c);
          contextHelp(state, "The magnet's position; drag the magenta dot in a grid view");
          if (ImGui::Button("Move to center point")) {
            p.point = state.pointCenter;
            const int f = e.function, o = e.index;
            const Operation copy = e.op;
            edits.commit("Place magnet", [f, o, copy](Project& pr) { pr.functions[std::size_t(f)].ops[std::size_t(o)] = copy; });
          }
          contextHelp(state, "Put the magnet at the center point placed with Alt+click");
        } else if constexpr (std::is_same_v<T, MorphOp>) {
          ImGui::TextUnformatted("Point morph (Gröller & Wegenkittl 1994, §2.6)");
          morphEditor(e, p);
        } else if constexpr (std::is_same_v<T, CalculatorOp>) {
          ImGui::TextUnformatted("Universal calculator (Gröller & Wegenkittl 1994, §4.3)");
          calculatorEditor(e, p);
        } else if constexpr (std::is_same_v<T, NodesOp>) {
          ImGui::Text("Direct node moves: %zu", p.moves.size());
          ImGui::TextDisabled("Drag selected nodes in a grid view to add moves.");
          if (ImGui::BeginTable("moves", 2, ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg,
                                ImVec2(0, ImGui::GetTextLineHeightWithSpacing() * 6))) {
            for (std::size_t m = 0; m < std::min<std::size_t>(p.moves.size(), 200); ++m) {
              const NodeMove& mv = p.moves[m];
              ImGui::TableNextRow();
              ImGui::TableNextColumn();
              ImGui::Text("(%d, %d, %d)", mv.index[0], mv.index[1], mv.index[2]);
              ImGui::TableNextColumn();
              ImGui::TextDisabled("%+.3f %+.3f %+.3f", mv.displacement.x, mv.displacement.y, mv.displacement.z);
            }
            ImGui::EndTable();
          }
        }
        ImGui::PopID();
      },
      e.op.params);
  ImGui::PopItemWidth();
  ImGui::Spacing();
  centerAndSelection(e);
}

}  // namespace gridifs::ui
