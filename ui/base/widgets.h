#pragma once
// Small ImGui helpers shared by the panels: double-precision sliders and drags, a hover
// hint that feeds the status line's context help, section titles and help markers.
#include <imgui.h>

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

}  // namespace gridifs::ui
