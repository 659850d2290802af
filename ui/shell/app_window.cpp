#include "ui/shell/app_window.h"

#include <GLFW/glfw3.h>

#include <algorithm>

namespace gridifs::ui {
namespace {

std::vector<ScreenRect> monitorWorkAreas() {
  int count = 0;
  GLFWmonitor** monitors = glfwGetMonitors(&count);
  std::vector<ScreenRect> areas;
  // glfwGetMonitors lists the primary monitor first: fitToWorkAreas falls back to it.
  for (int m = 0; m < count; ++m) {
    ScreenRect r;
    glfwGetMonitorWorkarea(monitors[m], &r.x, &r.y, &r.width, &r.height);
    if (r.width > 0 && r.height > 0) areas.push_back(r);
  }
  return areas;
}

FrameInsets frameInsets(GLFWwindow* window) {
  FrameInsets f;
  glfwGetWindowFrameSize(window, &f.left, &f.top, &f.right, &f.bottom);
  // A window manager that reports nonsense must not shrink the window to nothing.
  auto sane = [](int v) { return std::clamp(v, 0, 200); };
  return {sane(f.left), sane(f.top), sane(f.right), sane(f.bottom)};
}

}  // namespace

AppWindow::AppWindow(const ModellerOptions& options, std::filesystem::path geometryFile)
    : geometryFile_(std::move(geometryFile)) {
  saved_ = loadWindowGeometry(geometryFile_);
  const std::vector<ScreenRect> areas = monitorWorkAreas();
  const ScreenRect primary = areas.empty() ? ScreenRect{0, 0, 1600, 1000} : areas.front();

  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  // Placed (and sized from the work area, which is already in screen coordinates) before it is
  // shown, so the window manager maps it where it belongs. No GLFW_SCALE_TO_MONITOR: it would
  // multiply a size that already fits the monitor by the content scale.
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  // The scale the UI will have: --ui-scale, else the primary monitor's content scale.
  float monitorScale = 1.0f, unused = 1.0f;
  if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) glfwGetMonitorContentScale(monitor, &monitorScale, &unused);
  float uiScale = options.uiScale > 0.0f ? options.uiScale : monitorScale;
  ScreenRect rect = saved_ ? saved_->normal : firstWindowRect(primary, {}, uiScale);
  if (options.width > 0 && options.height > 0) {
    rect.width = options.width;
    rect.height = options.height;
    if (!saved_)
      rect = {primary.x + std::max(0, (primary.width - rect.width) / 2),
              primary.y + std::max(0, (primary.height - rect.height) / 2), rect.width, rect.height};
  }
  window_ = glfwCreateWindow(rect.width, rect.height, "GridIFS", nullptr, nullptr);
  if (!window_) return;
  const FrameInsets frame = frameInsets(window_);
  // Where the framebuffer is larger than the window (macOS, Wayland) screen coordinates are
  // already scaled: the 1600×1000 cap needs no scaling there.
  int fbWidth = 0, fbHeight = 0;
  glfwGetFramebufferSize(window_, &fbWidth, &fbHeight);
  if (fbWidth > rect.width + 1) uiScale = 1.0f;
  if (options.width > 0 && options.height > 0) {
    // An explicit size is kept even where it exceeds the monitor (captures larger than the screen).
    const ScreenRect fitted = fitToWorkAreas(rect, areas, frame);
    if (fitted.width == rect.width && fitted.height == rect.height) {
      rect = fitted;
    } else if (!areas.empty()) {  // too large for any monitor: from the top left of the nearest
      const ScreenRect& area = areas[workAreaFor(rect, areas)];
      rect.x = area.x + frame.left;
      rect.y = area.y + frame.top;
    }
  } else {
    rect = saved_ ? fitToWorkAreas(rect, areas, frame) : firstWindowRect(primary, frame, uiScale);
    glfwSetWindowSize(window_, rect.width, rect.height);
  }
  glfwSetWindowPos(window_, rect.x, rect.y);
  normal_ = rect;
  glfwShowWindow(window_);
  if (saved_ && saved_->maximized && options.width <= 0) glfwMaximizeWindow(window_);
}

AppWindow::~AppWindow() {
  if (window_) glfwDestroyWindow(window_);
}

void AppWindow::track() {
  if (glfwGetWindowAttrib(window_, GLFW_MAXIMIZED) || glfwGetWindowAttrib(window_, GLFW_ICONIFIED)) return;
  ScreenRect r;
  glfwGetWindowPos(window_, &r.x, &r.y);
  glfwGetWindowSize(window_, &r.width, &r.height);
  if (r.width > 0 && r.height > 0) normal_ = r;
}

bool AppWindow::save(int layoutWidth, int layoutHeight) {
  track();
  WindowGeometry g;
  g.normal = normal_;
  g.maximized = glfwGetWindowAttrib(window_, GLFW_MAXIMIZED) != 0;
  g.layoutWidth = layoutWidth;
  g.layoutHeight = layoutHeight;
  return saveWindowGeometry(geometryFile_, g);
}

float AppWindow::contentScale() const {
  float x = 1.0f, y = 1.0f;
  glfwGetWindowContentScale(window_, &x, &y);
  return std::max(x, y);
}

ScreenRect AppWindow::workArea() const {
  ScreenRect r;
  glfwGetWindowPos(window_, &r.x, &r.y);
  glfwGetWindowSize(window_, &r.width, &r.height);
  const std::vector<ScreenRect> areas = monitorWorkAreas();
  return areas.empty() ? ScreenRect{} : areas[workAreaFor(r, areas)];
}

}  // namespace gridifs::ui
