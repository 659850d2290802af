#pragma once
// What the menu bar and the keyboard shortcuts can ask the application to do.
#include <functional>

#include "ui/base/edit_queue.h"
#include "ui/base/modeller_state.h"
#include "ui/shell/project_files.h"

namespace gridifs::ui {

class ExportDialog;

struct AppCommands {
  ModellerState& state;
  EditQueue& edits;
  ProjectFiles& files;
  std::function<void()> frameViews;   // F: frame the hovered view, or all of them
  std::function<void()> resetLayout;  // put every window back where it starts
  ExportDialog* exporter = nullptr;   // File > Export mesh / points (ui/dialogs/export_dialog.h)
};

/// menu_bar.cpp: File, Edit, Function, Operation, Select, View, Help (room for Export).
/// Returns the menu bar's height.
float drawMenuBar(AppCommands& app);
/// menu_bar.cpp: the keyboard shortcuts listed in the Help window.
void handleShortcuts(AppCommands& app);
/// status_bar.cpp: points, points/s, function count, context help and the last message.
void drawStatusBar(ModellerState& state, float height);

}  // namespace gridifs::ui
