#pragma once
// The orbit camera shared by the chaos-game renderer and the GUI's IFS view (Gröller & Wegenkittl 1994, §3.1,
// §4.2: the user view orbits with the preview, so both must use the same matrices).
//
// Conventions (the paper leaves them open; these are the choices):
// - World space is right-handed with **+z up**. X = [-1, 1]^3 is the IFS space.
// - yaw (degrees) turns the eye about +z, measured from +x towards +y;
//   pitch (degrees) lifts the eye above the xy plane (positive: looking down), clamped to ±90°
//   (straight down or up, the view's right axis is (−sin yaw, cos yaw, 0), so yaw turns it).
//   eye = target + distance · (cos pitch · cos yaw, cos pitch · sin yaw, sin pitch).
// - roll (degrees) turns the camera about its viewing axis, counter-clockwise as it sees;
//   shift_x and shift_y (frame heights) slide a flat camera's picture right and up without
//   turning it (an off-axis frustum; flam3's `center` under a perspective camera).
// - view() is an OpenGL-style look-at (the camera looks down -z of view space, +y of view space
//   is the projection of world +z). projection() is OpenGL-style (clip z in [-w, w]) so an
//   OpenGL view can use view() and projection() directly.
// - fov is the vertical field of view. Orthographic views show the same extent at the target as
//   the perspective view would: half height = distance · tan(fov / 2).
// - Panoramic projections, in the view frame above (x right, y up, looking down −z; image y
//   down), for a direction at angle θ from the view axis:
//   fisheye (equidistant): azimuth φ from image right, counter-clockwise, lands at radius
//   r = θ / (fov/2) · min(W, H)/2 from the image centre, so a 180° fisheye's image is the
//   inscribed circle (a dome master); equirectangular: longitude λ = atan2(x, −z) (positive to
//   the right) at x = W/2 · (1 + λ/(fov/2)), latitude β = atan2(y, √(x² + z²)) at
//   y = H/2 · (1 − β/(vfov/2)), vfov = fov · H/W. Their depth is the distance from the eye.
// - Stereo frames hold two eyes (top-bottom or side-by-side, the left eye first), each projected
//   into its half of the frame. Panoramic cameras use omni-directional stereo: the eye sits on a
//   circle of radius eye_separation/2 about the world's vertical axis through the eye, where the
//   ray to the point touches the circle, and every direction is turned by asin(radius /
//   convergence) so points at the convergence distance appear at the same place in both eyes.
//   Perspective cameras use parallel eyes ±eye_separation/2 along view x, each image shifted so
//   the convergence distance has no parallax (off-axis frusta).
// - Pixel coordinates: x to the right, y **down** (row 0 is the top row, as image files store it);
//   pixel (i, j) covers [i, i+1) × [j, j+1). depth is the distance along the viewing direction
//   (view-space -z), in world units; smaller is nearer.
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "model/project.h"

namespace gridifs {

/// Where one eye's image lies in the frame (the whole frame without stereo).
struct EyeRegion {
  int x = 0, y = 0, width = 1, height = 1;
};

/// A ray through a pixel, in world space: the point the pixel sees at depth d (as project()
/// measures depth) is origin + step · d. step is a unit vector for panoramic cameras and has unit
/// length along the view axis for flat ones.
struct PixelRay {
  glm::dvec3 origin{0.0}, step{0.0, 0.0, -1.0};
  bool valid = false;  // false outside a fisheye's circle and outside every eye
};

/// A point projected to the image: pixel position and view depth (see conventions above).
struct ProjectedPoint {
  double x = 0.0, y = 0.0;  // pixels, y down
  double depth = 0.0;       // view-space distance along the viewing direction; > near when visible
  bool inFront = false;     // depth > near plane (behind-the-camera points are not drawable)
};

/// An immutable orbit camera for one image size. Value type; thread-safe (const).
class OrbitCamera {
 public:
  /// The frame is width × height, both eyes together in stereo. Throws ModelError when width/height
  /// < 1 or distance/fov are not usable (distance ≤ 0, fov outside (0, 179] for flat cameras or
  /// (0, 360] for panoramic ones).
  OrbitCamera(const Camera& camera, int width, int height);

  const Camera& settings() const { return camera_; }
  int width() const { return width_; }
  int height() const { return height_; }
  double aspect() const { return double(width_) / double(height_); }

  glm::dvec3 eye() const { return eye_; }
  /// World → view (OpenGL look-at, +z up).
  const glm::dmat4& view() const { return view_; }
  /// View → clip (OpenGL convention), perspective or orthographic per settings().projection; for
  /// panoramic cameras a perspective view of at most 120° (for OpenGL views that need a matrix).
  const glm::dmat4& projection() const { return projection_; }
  glm::mat4 viewF() const { return glm::mat4(view_); }
  glm::mat4 projectionF() const { return glm::mat4(projection_); }

  double nearPlane() const { return near_; }
  double farPlane() const { return far_; }

  /// 2 for a stereo camera, else 1.
  int eyes() const { return eyes_; }
  /// Eye 0 (the left one in stereo) or 1: its part of the frame.
  EyeRegion eyeRegion(int eye) const { return region_[eye]; }
  /// Pixels per radian of a panoramic camera (fisheye radius, equirectangular x and y).
  double pixelsPerRadian() const { return pixelsPerRadian_; }
  /// The eye separation's half for panoramic stereo (the circle's radius), else 0.
  double stereoRadius() const { return panoramic() ? radius_ : 0.0; }
  bool panoramic() const { return camera_.panoramic(); }

  /// World point → frame pixel (x right, y down) and depth, seen by `eye`. A panoramic point is
  /// drawable (inFront) when it is farther than the near plane, inside a fisheye's circle and, in
  /// omni-directional stereo, outside the eyes' circle.
  ProjectedPoint project(const glm::dvec3& point, int eye = 0) const;
  /// The ray of frame pixel position (x, y): the inverse of project() (pixel centres at +0.5).
  PixelRay rayThrough(double x, double y) const;

  /// The affine rows used by the renderer's hot loop: for a world point p (homogeneous 1),
  /// px = dot(rowX, p) / dot(rowW, p), py = dot(rowY, p) / dot(rowW, p), depth = dot(rowD, p),
  /// in frame pixels for `eye`. For orthographic cameras rowW = (0, 0, 0, 1). Panoramic cameras
  /// have no such rows: their rowX, rowY and rowW are the view rows x, y and z (world → view)
  /// and rowD the view depth along the axis (what a lens focuses on).
  struct PixelRows {
    float rowX[4], rowY[4], rowW[4], rowD[4];
  };
  PixelRows pixelRows(int eye = 0) const;

  /// Panoramic stereo: the turn of `eye`'s directions about the vertical axis (view space, row
  /// major) and the vertical axis in view space.
  const glm::dmat3& eyeTurn(int eye) const { return turn_[eye]; }
  glm::dvec3 viewUp() const { return up_; }
  /// -1 for the left eye, +1 for the right one, 0 without stereo.
  double eyeSign(int eye) const { return eyes_ == 2 ? (eye == 0 ? -1.0 : 1.0) : 0.0; }
  /// World → eye view space of a panoramic camera's eye (the circle offset and turn applied).
  glm::dvec3 panoramicEyeView(const glm::dvec3& view, int eye, bool& outsideCircle) const;

 private:
  Camera camera_;
  int width_ = 1, height_ = 1;
  glm::dvec3 eye_{0.0};
  glm::dmat4 view_{1.0}, projection_{1.0};
  double near_ = 0.01, far_ = 100.0;
  int eyes_ = 1;
  EyeRegion region_[2];
  double radius_ = 0.0;           // half the eye separation
  double pixelsPerRadian_ = 1.0;  // panoramic
  glm::dvec3 up_{0.0, 1.0, 0.0};  // world +z in view space
  glm::dmat3 turn_[2] = {glm::dmat3(1.0), glm::dmat3(1.0)};
};

/// OpenEXR's standard camera attributes for compositing (OpenEXR's "Recommended standard
/// optional attributes"), 16 values each in Imath's row-vector order (p' = p · M): worldToCamera
/// maps the world to the camera's left-handed space (x right, y up, +z the viewing direction);
/// worldToNDC maps it, after the homogeneous divide, to (0, 0) at the image's top-left corner and
/// (1, 1) at its bottom-right one. A panoramic camera has no such matrix: worldToNDC is empty.
/// Stereo frames carry the left eye's.
struct ExrCameraMatrices {
  std::vector<float> worldToCamera, worldToNDC;
};
ExrCameraMatrices exrCameraMatrices(const OrbitCamera& camera);

/// The world position that pixel (x, y)'s centre sees at `depth` (for the EXR's P pass); NaN
/// where the pixel sees nothing (outside a fisheye's circle).
glm::dvec3 pixelWorldPosition(const OrbitCamera& camera, int x, int y, double depth);

/// The projection's name in the file ("fisheye").
const char* projectionName(CameraProjection projection);

/// The eye position of an orbit camera (see conventions). Pure.
glm::dvec3 orbitEye(const Camera& camera);

}  // namespace gridifs
