// The shortcuts window: a Help window listing every keyboard shortcut (and the final function's controls).
#include <imgui.h>

#include <algorithm>

#include "ui/panels/panels.h"

namespace gridifs::ui {

void drawHelpWindow(ModellerState& state) {
  if (!state.showHelp) return;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + vp->WorkSize.x * 0.5f, vp->WorkPos.y + vp->WorkSize.y * 0.5f),
                          ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  // Never taller or wider than the window: on a small screen the table scrolls instead.
  ImGui::SetNextWindowSize(ImVec2(std::min(ImGui::GetFontSize() * 36, vp->WorkSize.x * 0.95f),
                                  std::min(ImGui::GetFontSize() * 34, vp->WorkSize.y * 0.9f)),
                           ImGuiCond_Appearing);
  if (!ImGui::Begin("Help: shortcuts", &state.showHelp, ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  struct Row {
    const char* keys;
    const char* what;
  };
  static const Row keyboard[] = {
      {"Ctrl+N", "New project"},
      {"Ctrl+O", "Open a project"},
      {"Ctrl+S", "Save"},
      {"Ctrl+Shift+S", "Save as"},
      {"Ctrl+Z", "Undo (one step per edit or drag; the last 500 steps, at most 256 MiB, are kept)"},
      {"Ctrl+Shift+Z, Ctrl+Y", "Redo"},
      {"Delete", "Delete the active operation"},
      {"F", "Frame the hovered view (all views when none is hovered)"},
      {"E", "Explore: variants, random worlds and breeding as live thumbnails"},
      {"1 2 3 4", "Top / side / front / user grid view alone; again: all four"},
      {"Ctrl+A, Esc, Ctrl+I", "Select all nodes / none / invert"},
      {"Space", "Pause or resume the preview"},
      {"Alt+A", "Play or pause the animation (the timeline under the preview)"},
      {"Left, Right", "One frame back / forward (Shift: to the first / last frame)"},
      {"F1", "This window"},
      {"M", "The Matrices window: transitions, control points, free-form matrices and presets"},
      {"T", "The Construction tree window: leaves (project files, parts) combined by matrix operations"},
      {"Ctrl+Q", "Quit (asks before losing unsaved work)"},
  };
  static const Row mouse[] = {
      {"Click a node", "Select it (Shift: add, Ctrl: remove)"},
      {"Drag on empty space", "Box-select nodes (Shift: add, Ctrl: remove)"},
      {"Drag a selected node", "Move the selection (records a 'nodes' operation)"},
      {"Drag a handle", "Move the magnet, a morph start/end or the center point"},
      {"Alt+click", "Place the center point of transformation"},
      {"Right-drag", "Orbit the user views; pan the top/side/front views"},
      {"Middle-drag, Shift+right-drag", "Pan"},
      {"Wheel", "Zoom"},
      {"Drag a grid in the IFS view", "Move the function's placement"},
      {"Click the violet lattice in the IFS view",
       "Make the final function active: its grid, operations, selection and "
       "node drags then work as for any function"},
      {"Drag in the preview", "Orbit the preview camera (same as the IFS user view)"},
      {"Drag the timeline", "Scrub through the animation; the preview follows (not an undo step)"},
      {"Click a diamond", "Set a key at the current time, or remove the key there; editing a keyed value keys it"},
  };
  auto table = [](const char* id, const Row* rows, std::size_t n) {
    if (ImGui::BeginTable(id, 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
      ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed, ImGui::GetFontSize() * 13);
      ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthStretch);
      for (std::size_t i = 0; i < n; ++i) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(rows[i].keys);
        ImGui::TableNextColumn();
        ImGui::TextWrapped("%s", rows[i].what);
      }
      ImGui::EndTable();
    }
  };
  ImGui::TextDisabled("Keyboard");
  table("keys", keyboard, sizeof keyboard / sizeof keyboard[0]);
  ImGui::Spacing();
  ImGui::TextDisabled("Mouse in the grid views");
  table("mouse", mouse, sizeof mouse / sizeof mouse[0]);
  static const Row window[] = {
      {"View > Reset layout", "Every panel back to the default layout for this window size"},
      {"Resizing the window", "The panels stretch with it; size, place and maximized state are remembered on quit"},
      {"gridifs --size WxH", "Open at that size instead of the remembered one"},
      {"gridifs --ui-scale S", "Text and controls at scale S instead of the monitor's (HiDPI) scale"},
  };
  static const Row finalFunction[] = {
      {"Functions › Add final function",
       "A lattice applied to every point before it is plotted, around the attractor; "
       "undistorted it changes nothing (also in the Function menu)"},
      {"The violet Final row",
       "Edit it like a function: operations, selection, node drags, mute; weight and "
       "transitions do not apply"},
      {"Interpolation", "Trilinear cells, or a smooth Bézier free-form deformation (at most 8 nodes per axis)"},
      {"Functions › Delete (final row active), Remove final function", "Remove it (Ctrl+Z brings it back)"},
  };
  ImGui::Spacing();
  ImGui::TextDisabled("The final function");
  table("final", finalFunction, sizeof finalFunction / sizeof finalFunction[0]);
  ImGui::Spacing();
  ImGui::TextDisabled("Window");
  table("window", window, sizeof window / sizeof window[0]);
  ImGui::End();
}

}  // namespace gridifs::ui
