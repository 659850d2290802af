#pragma once
// The flame's 3D camera (the extension Apophysis 7X introduced and JWildfire and Fractorium
// write: cam_pitch, cam_yaw, cam_perspective, cam_zpos) as a project camera, both ways.
//
// The flame camera turns a point p of the flame's space into c = M(pitch, yaw) · (p − (0, 0, zpos)),
// M = yaw about z (stored with the opposite sign), then pitch about the turned x axis; divides by
// zr = 1 − perspective · c_z (the eye at c_z = 1/perspective, the plane c_z = 0 at the view's
// scale); then plots R(rotate) · ((c_x, c_y)/zr − center) · pixelsPerUnit about the image centre,
// with image rows going down with y. Seen from its eye, that picture is mirrored (x right, y down,
// the eye on the +z side), so a natively imported genome lives in X = (x, y, −z): planar genomes,
// which stay on z = 0, are unchanged, and the project camera, right-handed, sees exactly the
// flame camera's picture. flam3's `center` under a perspective camera slides the picture after
// the divide: the project camera's lens shift. Pure functions: thread-safe.
#include <array>

#include "model/project.h"

namespace gridifs {

/// A genome's camera, as the file stores it (angles: rotate in degrees, pitch and yaw in radians).
struct FlameCamera {
  double centerX = 0.0, centerY = 0.0;
  double pixelsPerUnit = 50.0;  // at the plane c_z = 0
  double rotate = 0.0;
  double pitch = 0.0, yaw = 0.0;
  double perspective = 0.0;  // 1 / the eye's distance; 0: orthographic
  double zpos = 0.0;
  /// Whether the camera leaves the flame plane (pitch, yaw or perspective set).
  bool threeD() const { return pitch != 0.0 || yaw != 0.0 || perspective != 0.0; }
};

/// The rows of M(pitch, yaw), radians as the file stores them: the flame camera's right, down and
/// towards-the-eye axes in the flame's space.
std::array<std::array<double, 3>, 3> flameCameraRows(double pitch, double yaw);

/// The project camera that sees what `flame` sees in an image `height` pixels tall, in X =
/// (x, y, −z). `reach` bounds the attractor's distance from (0, 0, zpos): an orthographic camera
/// stands beyond it. Throws FlameError when no project camera can hold the view (a negative
/// perspective, a view too small or too large).
Camera cameraFromFlame(const FlameCamera& flame, int height, double reach);

/// The flame camera of a flat project camera over a `height`-pixel image, and the move (x, y)
/// the genome's points need so that a perspective eye orbits the flame's z axis (zero when the
/// camera's target lies on it, as an imported camera's does). Throws FlameError for panoramic
/// and stereo cameras, which a flame camera cannot hold.
struct FlameCameraExport {
  FlameCamera camera;
  double moveX = 0.0, moveY = 0.0;
};
FlameCameraExport flameCameraFromProject(const Camera& camera, int height);

}  // namespace gridifs
