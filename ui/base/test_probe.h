#pragma once
// The probe of the GUI tests: rectangles of named widgets, written to a file (`--probe FILE`) so
// that xdotool can find a slider without guessing the layout. Panels record into the one probe
// of the modeller's state; it does nothing unless the modeller was started with `--probe`.
#include <imgui.h>

#include <map>
#include <string>

namespace gridifs::ui {

/// Rectangles of named widgets for the GUI tests.
struct UiProbe {
  bool enabled = false;
  std::map<std::string, ImVec4> rects;  // x, y, width, height in window coordinates
  /// Records the last submitted item under `name`.
  void item(const std::string& name);
  /// The same for a labelled widget, keeping only its frame (the current item width), not the label.
  void frame(const std::string& name);
  /// The current window's (or child window's) rectangle under `name`.
  void window(const std::string& name);
};

}  // namespace gridifs::ui
