#include "ui/shell/symmetry_menu.h"

#include <imgui.h>

#include <string>

#include "edit/flame_symmetry.h"

namespace gridifs::ui {

void drawSymmetryMenu(ModellerState& state, EditQueue& edits) {
  const bool open = ImGui::BeginMenu("Add symmetry");
  state.probe.item("menu.symmetry");
  if (!open) return;
  // flam3's convention (Draves & Reckase 2003, §7): n ≥ 2 rotations, n ≤ −1 a mirror plus |n| − 1 rotations.
  struct Choice {
    int n;
    const char* label;
  };
  static const Choice kChoices[] = {
      {2, "2-way rotation"},  {3, "3-way rotation"},  {4, "4-way rotation"},      {5, "5-way rotation"},
      {6, "6-way rotation"},  {8, "8-way rotation"},  {-1, "Bilateral (mirror)"}, {-2, "2-way dihedral"},
      {-3, "3-way dihedral"}, {-4, "4-way dihedral"}, {-5, "5-way dihedral"},     {-6, "Snowflake (6-way dihedral)"}};
  for (const Choice& c : kChoices) {
    if (c.n == -1) ImGui::Separator();
    const bool chosen = ImGui::MenuItem(c.label);
    state.probe.item("menu.symmetry." + std::to_string(c.n));
    if (chosen) {
      // About the preview's view axis, so the symmetry is what the artist sees in the preview.
      edits.commit(std::string("Add symmetry: ") + c.label, AddSymmetry{c.n});
    }
    if (ImGui::IsItemHovered())
      state.contextHelp =
          "Adds functions (weight = the others' sum, color speed 0) that make the attractor symmetric "
          "about the preview's view axis (Draves & Reckase 2003, §7)";
  }
  ImGui::EndMenu();
}

}  // namespace gridifs::ui
