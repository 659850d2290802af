#pragma once
// Small ImGui helpers shared by the panels: double-precision sliders and drags, a hover
// hint that feeds the status line's context help, and the test probe hook.
#include <imgui.h>

#include <map>
#include <string>

#include "base/types.h"

namespace gridifs::ui {

class ModellerState;

bool sliderDouble(const char* label, double& value, double min, double max, const char* format = "%.3f");
bool dragDouble(const char* label, double& value, double speed, double min = 0.0, double max = 0.0,
                const char* format = "%.3f");
bool dragVec3(const char* label, Vec3& value, double speed, double min = 0.0, double max = 0.0,
              const char* format = "%.3f");
/// Sets the status line's context help while the last item is hovered (Gröller & Wegenkittl 1994, §4.2).
void contextHelp(ModellerState& state, const char* text);
/// A small section heading followed by a separator line.
void sectionTitle(const char* text);
/// A right-aligned "(?)" with a tooltip.
void helpMarker(const char* text);

/// Rectangles of named widgets, written to a file for the GUI tests (`--probe FILE`), so that
/// xdotool can find a slider without guessing the layout.
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
