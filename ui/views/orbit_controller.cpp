#include "ui/views/orbit_controller.h"

#include <algorithm>
#include <cmath>

namespace gridifs::ui {

namespace {
constexpr double kDegreesPerPixel = 0.4;
constexpr double kZoomPerStep = 0.87;
constexpr double kWheelRest = 0.6;  // seconds without a wheel step that end its undo step
}  // namespace

void OrbitController::begin(Motion motion, const Camera& camera, glm::dvec2 mouse) {
  motion_ = motion;
  startCamera_ = camera;
  start_ = mouse;
}

Camera OrbitController::dragged(glm::dvec2 mouse, ViewAxis axis, double viewHeight) const {
  const glm::dvec2 delta = mouse - start_;
  Camera cam = startCamera_;
  if (motion_ == Motion::Orbit) {
    cam.yaw = startCamera_.yaw - delta.x * kDegreesPerPixel;
    cam.pitch = std::clamp(startCamera_.pitch + delta.y * kDegreesPerPixel, -89.0, 89.0);
  } else if (motion_ == Motion::Pan) {
    const ViewCamera view{axis, startCamera_};
    cam.target = startCamera_.target - view.dragDelta(delta.x, delta.y, startCamera_.target, viewHeight);
  }
  return cam;
}

void OrbitController::dragProject(EditQueue& edits, glm::dvec2 mouse, ViewAxis axis, double viewHeight,
                                  bool firstMove) const {
  if (motion_ == Motion::None) return;
  if (firstMove) edits.begin(motion_ == Motion::Orbit ? "Orbit preview camera" : "Pan preview camera");
  const Camera cam = dragged(mouse, axis, viewHeight);
  edits.update(SetCamera{cam});
}

Camera OrbitController::zoomed(Camera camera, float wheel, double minDistance) {
  camera.distance = std::clamp(camera.distance * std::pow(kZoomPerStep, double(wheel)), minDistance, 500.0);
  return camera;
}

void OrbitController::zoomProject(const Camera& current, EditQueue& edits, float wheel, double now) {
  if (wheelUntil_ < 0.0) edits.begin("Zoom preview camera");
  const double distance = zoomed(current, wheel, 0.05).distance;
  edits.update(SetParameter{"camera.distance", distance, "Zoom preview camera"});
  wheelUntil_ = now + kWheelRest;
}

void OrbitController::settleWheel(EditQueue& edits, double now) {
  if (wheelUntil_ > 0.0 && (now < 0.0 || now > wheelUntil_)) {
    edits.end();
    wheelUntil_ = -1.0;
  }
}

}  // namespace gridifs::ui
