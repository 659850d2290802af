#pragma once
// The modeller's look: a dark theme, a readable font at the monitor's content scale.
namespace gridifs::ui {

/// Styles ImGui and loads the UI font for `scale` (the monitor content scale). Call before the
/// first frame. Returns the font size used, in pixels.
float applyTheme(float scale);
/// The same for a new scale while the modeller runs (the window moved to a monitor with another
/// content scale): rebuilds the font atlas and its texture. Call between frames.
float rescaleTheme(float scale);

}  // namespace gridifs::ui
