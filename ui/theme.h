#pragma once
// The modeller's look: a dark theme, a readable font at the monitor's content scale.
namespace gridifs::ui {

/// Styles ImGui and loads the UI font for `scale` (the monitor content scale). Call before the
/// first frame. Returns the font size used, in pixels.
float applyTheme(float scale);

}  // namespace gridifs::ui
