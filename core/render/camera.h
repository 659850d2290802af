#pragma once
// The orbit camera shared by the chaos-game renderer and the GUI's IFS view (Gröller & Wegenkittl 1994, §3.1,
// §4.2: the user view orbits with the preview, so both must use the same matrices).
//
// Conventions (the paper leaves them open; these are the choices):
// - World space is right-handed with **+z up**. X = [-1, 1]^3 is the IFS space.
// - yaw (degrees) turns the eye about +z, measured from +x towards +y;
//   pitch (degrees) lifts the eye above the xy plane (positive: looking down), clamped to ±89.9°.
//   eye = target + distance · (cos pitch · cos yaw, cos pitch · sin yaw, sin pitch).
// - view() is an OpenGL-style look-at (the camera looks down -z of view space, +y of view space
//   is the projection of world +z). projection() is OpenGL-style (clip z in [-w, w]) so an
//   OpenGL view can use view() and projection() directly.
// - fov is the vertical field of view. Orthographic views show the same extent at the target as
//   the perspective view would: half height = distance · tan(fov / 2).
// - Pixel coordinates: x to the right, y **down** (row 0 is the top row, as image files store it);
//   pixel (i, j) covers [i, i+1) × [j, j+1). depth is the distance along the viewing direction
//   (view-space -z), in world units; smaller is nearer.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "model/project.h"

namespace gridifs {

/// A point projected to the image: pixel position and view depth (see conventions above).
struct ProjectedPoint {
  double x = 0.0, y = 0.0;  // pixels, y down
  double depth = 0.0;       // view-space distance along the viewing direction; > near when visible
  bool inFront = false;     // depth > near plane (behind-the-camera points are not drawable)
};

/// An immutable orbit camera for one image size. Value type; thread-safe (const).
class OrbitCamera {
 public:
  /// Throws ModelError when width/height < 1 or distance/fov are not usable
  /// (distance ≤ 0, fov outside (0, 179]).
  OrbitCamera(const Camera& camera, int width, int height);

  const Camera& settings() const { return camera_; }
  int width() const { return width_; }
  int height() const { return height_; }
  double aspect() const { return double(width_) / double(height_); }

  glm::dvec3 eye() const { return eye_; }
  /// World → view (OpenGL look-at, +z up).
  const glm::dmat4& view() const { return view_; }
  /// View → clip (OpenGL convention), perspective or orthographic per settings().ortho.
  const glm::dmat4& projection() const { return projection_; }
  glm::mat4 viewF() const { return glm::mat4(view_); }
  glm::mat4 projectionF() const { return glm::mat4(projection_); }

  double nearPlane() const { return near_; }
  double farPlane() const { return far_; }

  /// World point → pixel (x right, y down) and view depth.
  ProjectedPoint project(const glm::dvec3& point) const;

  /// The affine rows used by the renderer's hot loop: for a world point p (homogeneous 1),
  /// px = dot(rowX, p) / dot(rowW, p), py = dot(rowY, p) / dot(rowW, p), depth = dot(rowD, p).
  /// For orthographic cameras rowW = (0, 0, 0, 1).
  struct PixelRows {
    float rowX[4], rowY[4], rowW[4], rowD[4];
  };
  PixelRows pixelRows() const;

 private:
  Camera camera_;
  int width_ = 1, height_ = 1;
  glm::dvec3 eye_{0.0};
  glm::dmat4 view_{1.0}, projection_{1.0};
  double near_ = 0.01, far_ = 100.0;
};

/// The eye position of an orbit camera (see conventions). Pure.
glm::dvec3 orbitEye(const Camera& camera);

}  // namespace gridifs
