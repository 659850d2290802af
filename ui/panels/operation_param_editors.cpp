// The structured parameters of the operation table: calculator expressions and variables
// (Gröller & Wegenkittl 1994, §4.3), morph vectors (§2.6) and direct node moves.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <optional>

#include "model/calculator.h"
#include "ui/base/widgets.h"
#include "ui/panels/operation_editor.h"

namespace gridifs::ui {

void OpEditor::item(const std::string& label, bool changed) {
  gestureItem(edits, label, changed, SetOperation{function, index, op});
}

void OpEditor::commit(const std::string& label) { edits.commit(label, SetOperation{function, index, op}); }

namespace {

/// What is wrong with the typed expressions: which one, where (a byte offset, or -1) and why.
struct ExpressionProblem {
  std::size_t param = 0;
  int position = -1;
  std::string message;
};

std::optional<ExpressionProblem> diagnose(const std::vector<const ParamSpec*>& expressions, const OpParams& candidate) {
  // The calculator also knows where in the text the problem is.
  if (const auto* calc = std::get_if<CalculatorOp>(&candidate)) {
    if (auto d = checkCalculator(*calc)) return ExpressionProblem{std::size_t(d->expression), d->position, d->message};
    return std::nullopt;
  }
  try {
    validateOperationParams(candidate);
  } catch (const ModelError& error) {
    for (std::size_t i = 0; i < expressions.size(); ++i)
      if (error.path() == expressions[i]->key) return ExpressionProblem{i, -1, error.message()};
  }
  return std::nullopt;
}

}  // namespace

void drawExpressionParams(OpEditor& e, const OperationSpec& spec) {
  std::vector<const ParamSpec*> expressions;
  for (const ParamSpec& s : spec.params)
    if (s.type == ParamType::Expression) expressions.push_back(&s);
  auto& buffer = e.panel.expressionEdit;
  std::vector<std::string> current;
  for (const ParamSpec* s : expressions) current.push_back(s->value<std::string>(e.op.params));
  if (!(buffer.function == e.function) || buffer.op != e.index || buffer.base != current) {
    buffer.function = e.function;
    buffer.op = e.index;
    buffer.text = buffer.base = current;
  }
  OpParams candidate = e.op.params;
  auto typed = [&] {
    for (std::size_t i = 0; i < expressions.size(); ++i) expressions[i]->value<std::string>(candidate) = buffer.text[i];
  };
  typed();
  const auto problem = diagnose(expressions, candidate);
  for (std::size_t i = 0; i < expressions.size(); ++i) {
    const ParamSpec& s = *expressions[i];
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(s.label);
    ImGui::SameLine();
    const bool bad = problem && problem->param == i;
    if (bad) ImGui::PushStyleColor(ImGuiCol_FrameBg, ImVec4(0.45f, 0.12f, 0.10f, 1.0f));
    ImGui::SetNextItemWidth(-1);
    const float fieldX = ImGui::GetCursorPosX();
    const bool edited = ImGui::InputText((std::string("##") + s.key).c_str(), &buffer.text[i]);
    if (bad) ImGui::PopStyleColor();
    e.state.probe.item(std::string(spec.type) + "." + s.key);
    // Only valid expressions reach the document; what is typed stays in the field.
    typed();
    const bool valid = !diagnose(expressions, candidate);
    if (edited && valid) {
      e.op.params = candidate;
      buffer.base = buffer.text;
    }
    e.item(std::string(spec.title) + " expression", edited && valid);
    contextHelp(e.state, s.tooltip);
    if (bad) {
      // A caret under the offending character, then the message.
      const std::string& text = buffer.text[i];
      const std::size_t at = std::size_t(std::clamp(problem->position, 0, int(text.size())));
      ImGui::SetCursorPosX(fieldX + ImGui::GetStyle().FramePadding.x +
                           ImGui::CalcTextSize(text.substr(0, at).c_str()).x - ImGui::CalcTextSize("^").x * 0.5f);
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.35f, 1.0f));
      ImGui::TextUnformatted(problem->position >= 0 ? "^" : "");
      ImGui::SameLine();
      ImGui::TextWrapped("%s", problem->message.c_str());
      ImGui::PopStyleColor();
    }
  }
  ImGui::Spacing();
}

void drawCalculatorVars(OpEditor& e, const OperationSpec& spec, const ParamSpec& param) {
  auto& vars = param.value<std::array<CalculatorVar, 3>>(e.op.params);
  const std::string title = spec.title;
  for (int v = 0; v < 3; ++v) {
    ImGui::PushID(v);
    CalculatorVar& var = vars[std::size_t(v)];
    const std::string name = param.label + std::to_string(v + 1);
    const float w = ImGui::GetContentRegionAvail().x;
    const float rangeWidth = ImGui::CalcTextSize("-000.00").x + ImGui::GetStyle().FramePadding.x * 2;
    // The range ends never cross, so the variable stays valid while they are dragged.
    ImGui::SetNextItemWidth(rangeWidth);
    bool c = dragDouble("##min", var.min, param.speed, -limits::kMaxCoordinate, var.max, param.format);
    e.item(title + " range", c);
    contextHelp(e.state, "Lower end of the slider's range");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(std::max(
        40.0f, w - 2 * rangeWidth - ImGui::CalcTextSize(name.c_str()).x - 4 * ImGui::GetStyle().ItemSpacing.x));
    c = sliderDouble(("##" + name).c_str(), var.value, var.min, var.max == var.min ? var.min + 1.0 : var.max);
    e.state.probe.item(std::string(spec.type) + "." + name);
    e.item(title + " " + name, c);
    contextHelp(e.state, param.tooltip);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(rangeWidth);
    c = dragDouble("##max", var.max, param.speed, var.min, limits::kMaxCoordinate, param.format);
    e.item(title + " range", c);
    contextHelp(e.state, "Upper end of the slider's range");
    ImGui::SameLine();
    ImGui::TextUnformatted(name.c_str());
    ImGui::PopID();
  }
}

void drawMorphPairs(OpEditor& e, const OperationSpec& spec, const ParamSpec& param) {
  auto& pairs = param.value<std::vector<MorphPair>>(e.op.params);
  const std::string title = spec.title;
  bool& asDirection = e.panel.morphAsDirection;
  ImGui::Checkbox("Enter end as direction", &asDirection);
  int remove = -1;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    ImGui::PushID(int(i));
    ImGui::Separator();
    ImGui::TextDisabled("%s %zu", param.label, i + 1);
    ImGui::SameLine(ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("Remove").x);
    if (ImGui::SmallButton("Remove")) remove = int(i);
    MorphPair& pair = pairs[i];
    bool c = dragVec3("Start", pair.from, param.speed);
    e.item(title + " start", c);
    contextHelp(e.state, "Start point P_i (absolute); drag the white dot in a grid view");
    if (asDirection) {
      Vec3 dir = pair.to - pair.from;
      c = dragVec3("Direction", dir, param.speed);
      if (c) pair.to = pair.from + dir;
    } else {
      c = dragVec3("End", pair.to, param.speed);
    }
    e.item(title + " end", c);
    contextHelp(e.state, "End point Q_i (absolute); drag the yellow dot in a grid view");
    ImGui::PopID();
  }
  if (remove >= 0 && pairs.size() > 1) {
    pairs.erase(pairs.begin() + remove);
    e.commit("Remove morph vector");
  }
  ImGui::BeginDisabled(int(pairs.size()) >= limits::kMaxMorphPairs);
  if (ImGui::Button("Add vector")) {
    MorphPair pair;
    pair.from = e.state.pointCenter + Vec3(0.1 * double(pairs.size() + 1), 0.0, 0.0);
    pair.to = pair.from + Vec3(0.0, 0.0, 0.2);
    pairs.push_back(pair);
    e.commit("Add morph vector");
  }
  ImGui::EndDisabled();
  contextHelp(e.state, "Add a start → end vector at the placed center point (InterIFS used up to eight)");
  ImGui::Separator();
}

void drawNodeMoves(OpEditor& e, const ParamSpec& param) {
  const auto& moves = param.value<std::vector<NodeMove>>(e.op.params);
  ImGui::Text("%s: %zu", param.label, moves.size());
  ImGui::TextDisabled("%s.", param.tooltip);
  if (ImGui::BeginTable("moves", 2, ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg,
                        ImVec2(0, ImGui::GetTextLineHeightWithSpacing() * 6))) {
    for (std::size_t m = 0; m < std::min<std::size_t>(moves.size(), 200); ++m) {
      const NodeMove& mv = moves[m];
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::Text("(%d, %d, %d)", mv.index[0], mv.index[1], mv.index[2]);
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%+.3f %+.3f %+.3f", mv.displacement.x, mv.displacement.y, mv.displacement.z);
    }
    ImGui::EndTable();
  }
}

}  // namespace gridifs::ui
