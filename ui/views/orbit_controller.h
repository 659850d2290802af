#pragma once
// Orbit, pan and zoom of a Camera with the mouse, one implementation for the preview and the
// grid views. On the project camera each gesture is one undo step: a drag from its first motion
// to the release, and a run of wheel steps until the wheel rests for 0.6 s or a button is pressed.
// A view's own camera (the axis views) is changed directly, without undo.
#include <glm/vec2.hpp>

#include "edit/view_camera.h"
#include "ui/base/edit_queue.h"

namespace gridifs::ui {

class OrbitController {
 public:
  enum class Motion { None, Orbit, Pan };

  /// Starts orbiting or panning `camera` with the mouse at `mouse` (view pixels, y down).
  void begin(Motion motion, const Camera& camera, glm::dvec2 mouse);
  Motion motion() const { return motion_; }
  void end() { motion_ = Motion::None; }
  /// The camera for the mouse at `mouse`: 0.4° of yaw and pitch per pixel (pitch within ±89°),
  /// or a pan that keeps the target under the mouse in the view plane of `axis`.
  Camera dragged(glm::dvec2 mouse, ViewAxis axis, double viewHeight) const;
  /// The same for the project camera: the drag's undo step begins at `firstMove`.
  void dragProject(EditQueue& edits, glm::dvec2 mouse, ViewAxis axis, double viewHeight, bool firstMove) const;

  /// `camera` after `wheel` steps: the distance × 0.87 per step, within [minDistance, 500].
  static Camera zoomed(Camera camera, float wheel, double minDistance);
  /// Zooms the project camera; successive steps extend one undo step.
  void zoomProject(const Camera& current, EditQueue& edits, float wheel, double now);
  /// Ends the wheel's undo step once the wheel has rested (call every frame) or at once (`now` < 0).
  void settleWheel(EditQueue& edits, double now);

 private:
  Motion motion_ = Motion::None;
  glm::dvec2 start_{0.0};
  Camera startCamera_;
  double wheelUntil_ = -1.0;
};

}  // namespace gridifs::ui
