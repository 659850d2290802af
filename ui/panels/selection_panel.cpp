// Node selections (Gröller & Wegenkittl 1994, §4.4): index boxes combined with
// or/and/xor/minus, select all/none/invert, and the center of transformation for new ops.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "edit/node_picking.h"
#include "ui/base/widgets.h"
#include "ui/panels/panels.h"

namespace gridifs::ui {

void drawSelectionPanel(ModellerState& state, EditQueue& edits, SelectionPanelState& panel) {
  (void)edits;  // the selection is UI state (not saved), so it needs no undo step
  state.clampIndices();
  const Function& f = state.function();
  if (isSetKind(f.kind)) {
    ImGui::TextWrapped("%s has no grid: there are no nodes to select.", f.name.c_str());
    return;
  }
  const Index3 res = f.resolution;
  Selection& selection = state.selection();
  const auto& mask = state.selectionMask();
  const std::size_t total = mask.size();
  const std::size_t selected = std::size_t(std::count(mask.begin(), mask.end(), 1));

  ImGui::Text("%zu of %zu nodes selected", selected, total);
  // The function's name and resolution beside the count where they fit, below it otherwise.
  char where[96];
  std::snprintf(where, sizeof where, "in %s (%d×%d×%d)", f.name.c_str(), res[0], res[1], res[2]);
  if (ImGui::GetContentRegionAvail().x - ImGui::GetItemRectSize().x - ImGui::GetStyle().ItemSpacing.x >=
      ImGui::CalcTextSize(where).x)
    ImGui::SameLine();
  ImGui::TextDisabled("%s", where);
  if (ImGui::Button("All"))
    selection = {SelectionBox{{0, res[0] - 1}, {0, res[1] - 1}, {0, res[2] - 1}, SelectionOp::Or}};
  contextHelp(state, "Select every node (Ctrl+A)");
  ImGui::SameLine();
  if (ImGui::Button("None")) selection.clear();
  contextHelp(state, "Clear the selection: new operations then apply to the whole grid (Esc)");
  ImGui::SameLine();
  if (ImGui::Button("Invert")) {
    std::vector<unsigned char> inverted(mask.size());
    for (std::size_t n = 0; n < mask.size(); ++n) inverted[n] = mask[n] ? 0 : 1;
    Selection s = boxesFromMask(inverted, res);
    if (int(s.size()) > limits::kMaxSelectionBoxes)
      state.error("The inverted selection needs too many index boxes.");
    else
      selection = s;
  }
  contextHelp(state, "Select exactly the nodes that are not selected (Ctrl+I)");

  sectionTitle("Index box");
  // The box being entered: UI state kept across frames.
  auto& box = panel.boxEntry;
  // Three ranges on one line where the panel is wide enough, else one per line (a narrow
  // left column on a laptop screen would clip the third).
  const ImGuiStyle& style = ImGui::GetStyle();
  const float labels = 3.0f * (style.ItemInnerSpacing.x + ImGui::CalcTextSize("j").x) + 2.0f * style.ItemSpacing.x;
  const float oneLine = std::floor((ImGui::GetContentRegionAvail().x - labels) / 3.0f);
  const bool inOneLine = oneLine >= ImGui::GetFontSize() * 4.0f;
  ImGui::PushItemWidth(inOneLine ? std::min(oneLine, ImGui::GetFontSize() * 6.0f) : ImGui::GetFontSize() * 7.0f);
  const char* axes[] = {"i", "j", "k"};
  std::array<int, 2>* ranges[] = {&box.i, &box.j, &box.k};
  for (int a = 0; a < 3; ++a) {
    if (a > 0 && inOneLine) ImGui::SameLine();
    ImGui::DragInt2(axes[a], ranges[a]->data(), 0.1f, 0, res[std::size_t(a)] - 1);
    contextHelp(state, "Inclusive index range along this grid axis (first..last)");
  }
  ImGui::PopItemWidth();
  int op = int(box.op);
  static const char* ops[] = {"or", "and", "xor", "minus"};
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
  if (ImGui::Combo("##op", &op, ops, 4)) box.op = SelectionOp(op);
  contextHelp(state, "How the box combines with the boxes before it (left to right, from the empty set)");
  ImGui::SameLine();
  if (ImGui::Button("Add box")) {
    if (int(selection.size()) >= limits::kMaxSelectionBoxes)
      state.error("A selection has at most 256 boxes.");
    else
      selection.push_back(box);
  }
  state.probe.item("selection.addBox");
  ImGui::SameLine();
  if (ImGui::Button("Replace")) {
    SelectionBox b = box;
    b.op = SelectionOp::Or;
    selection = {b};
  }
  contextHelp(state, "Replace the selection with this box alone");

  if (!selection.empty() && ImGui::BeginTable("boxes", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY,
                                              ImVec2(0, std::min(6.0f, float(selection.size()) + 0.5f) *
                                                            ImGui::GetFrameHeightWithSpacing()))) {
    ImGui::TableSetupColumn("op", ImGuiTableColumnFlags_WidthFixed, ImGui::GetFontSize() * 3.5f);
    ImGui::TableSetupColumn("box", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("x", ImGuiTableColumnFlags_WidthFixed, ImGui::GetFrameHeight() * 1.2f);
    int remove = -1;
    for (std::size_t b = 0; b < selection.size(); ++b) {
      const SelectionBox& s = selection[b];
      ImGui::PushID(int(b));
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%s", b == 0 && s.op == SelectionOp::Or ? "" : selectionOpName(s.op));
      ImGui::TableNextColumn();
      ImGui::Text("i %d..%d   j %d..%d   k %d..%d", s.i[0], s.i[1], s.j[0], s.j[1], s.k[0], s.k[1]);
      ImGui::TableNextColumn();
      if (ImGui::SmallButton("x")) remove = int(b);
      ImGui::PopID();
    }
    ImGui::EndTable();
    if (remove >= 0) selection.erase(selection.begin() + remove);
  }

  sectionTitle("Center for new operations");
  int center = int(state.newOpCenter);
  ImGui::RadioButton("Grid", &center, int(Center::Kind::Grid));
  ImGui::SameLine();
  ImGui::RadioButton("Selection", &center, int(Center::Kind::Selection));
  ImGui::SameLine();
  ImGui::RadioButton("Point", &center, int(Center::Kind::Point));
  state.newOpCenter = Center::Kind(center);
  ImGui::SetNextItemWidth(-ImGui::CalcTextSize("Point").x - ImGui::GetStyle().ItemInnerSpacing.x * 2);
  dragVec3("Point", state.pointCenter, 0.005);
  contextHelp(state,
              "Alt+click in a grid view places this point (Gröller & Wegenkittl 1994, §4.3: interactive center)");
}

}  // namespace gridifs::ui
