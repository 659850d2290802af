#pragma once
// The modeller's GLFW window: opened where the artist left it last time (or, the first time,
// sized to the work area of the monitor it opens on), its normal geometry followed while it runs
// and saved on exit, and the content scale of the monitor it is on (HiDPI).
#include <filesystem>

#include "ui/shell/modeller_options.h"
#include "ui/shell/window_geometry.h"

struct GLFWwindow;

namespace gridifs::ui {

class AppWindow {
 public:
  /// Opens an OpenGL 3.3 core window (glfwInit must have succeeded). `geometryFile` holds the
  /// last session's geometry; a missing or bad file means "first start". --size overrides the size
  /// (and maximizing). window() is null when no window could be created.
  AppWindow(const ModellerOptions& options, std::filesystem::path geometryFile);
  ~AppWindow();
  AppWindow(const AppWindow&) = delete;
  AppWindow& operator=(const AppWindow&) = delete;

  GLFWwindow* window() const { return window_; }
  /// Call once per frame: remembers the normal (not maximized, not minimized) geometry.
  void track();
  /// Writes the geometry with the panel layout's size; false when it could not be written.
  bool save(int layoutWidth, int layoutHeight);
  /// The content scale of the monitor the window is on (1 on a standard-DPI screen).
  float contentScale() const;
  /// The work area of the monitor the window overlaps most.
  ScreenRect workArea() const;
  /// What the saved file said about the layout size (0 when nothing was saved).
  int savedLayoutWidth() const { return saved_ ? saved_->layoutWidth : 0; }
  int savedLayoutHeight() const { return saved_ ? saved_->layoutHeight : 0; }

 private:
  GLFWwindow* window_ = nullptr;
  std::filesystem::path geometryFile_;
  std::optional<WindowGeometry> saved_;
  ScreenRect normal_;
};

}  // namespace gridifs::ui
