#pragma once
// Where the modeller window opens: the first time sized to the monitor's work area, later where
// the artist left it (position, size, maximized), corrected for the monitors present now so that
// a window never reopens off-screen. Pure geometry and a small JSON file; no GLFW here
// (ui/shell/app_window.cpp asks GLFW for the monitors and applies the result).
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gridifs::ui {

/// A rectangle in screen coordinates (x to the right, y down).
struct ScreenRect {
  int x = 0, y = 0, width = 0, height = 0;
  bool operator==(const ScreenRect&) const = default;
};

/// The window's normal (not maximized) client rectangle, whether it was maximized, and the size
/// of the client area the panels were laid out for (so a changed size rescales them).
struct WindowGeometry {
  ScreenRect normal;
  bool maximized = false;
  int layoutWidth = 0, layoutHeight = 0;  // 0: unknown
  bool operator==(const WindowGeometry&) const = default;
};

/// The window manager's decorations around the client area (glfwGetWindowFrameSize).
struct FrameInsets {
  int left = 0, top = 0, right = 0, bottom = 0;
};

/// The largest first window: 1600×1000 at most (times `scale` where screen coordinates are
/// pixels and the UI is scaled up, so that it holds as much as on a standard screen), never larger
/// than the work area less the decorations, centred in it.
ScreenRect firstWindowRect(const ScreenRect& workArea, const FrameInsets& frame = {}, float scale = 1.0f);

/// The index of the work area `window` overlaps most; 0 (the primary monitor) when it overlaps none.
std::size_t workAreaFor(const ScreenRect& window, const std::vector<ScreenRect>& workAreas);

/// Moves and shrinks `wanted` so that, with its decorations, it lies inside one work area: the one
/// it overlaps most, or the first (primary) one when it overlaps none. Empty `workAreas`: unchanged.
ScreenRect fitToWorkAreas(const ScreenRect& wanted, const std::vector<ScreenRect>& workAreas,
                          const FrameInsets& frame = {});

/// Reads the saved geometry; a missing, unreadable, corrupt or implausible file gives nullopt
/// (never throws).
std::optional<WindowGeometry> loadWindowGeometry(const std::filesystem::path& file);
/// Writes the geometry atomically (temporary file + rename). Returns false when it could not.
bool saveWindowGeometry(const std::filesystem::path& file, const WindowGeometry& geometry);

}  // namespace gridifs::ui
