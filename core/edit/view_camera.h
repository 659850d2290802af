#pragma once
// The cameras of the modeller's grid views (Gröller & Wegenkittl 1994, §4.2: top, side and front views and a
// user view that orbits), headless so that picking and dragging can be tested without a display.
// Conventions follow core/camera.h: +z up, pixels with y down, OpenGL-style matrices.
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "model/project.h"

namespace gridifs {

/// Which way a view looks: axis-aligned orthographic views or the orbiting user view.
enum class ViewAxis { Top, Side, Front, User };
const char* viewAxisName(ViewAxis axis);

/// A view camera for an image of width × height pixels. Value type; thread-safe (const).
/// Top looks down -z (screen right = +x, up = +y); Front looks along +y (right = +x, up = +z);
/// Side looks along -x (right = +y, up = +z); User uses `orbit` exactly as OrbitCamera does.
/// For the axis views `orbit.target` is the view center and the visible half height is
/// orbit.distance · tan(fov / 2), as for an orthographic OrbitCamera.
struct ViewCamera {
  ViewAxis axis = ViewAxis::User;
  Camera orbit;

  /// World → view and view → clip for an image of the given size (both ≥ 1).
  glm::dmat4 view() const;
  glm::dmat4 projection(double width, double height) const;
  glm::dmat4 viewProjection(double width, double height) const { return projection(width, height) * view(); }
  /// Unit world vectors along the screen's right and up directions.
  glm::dvec3 right() const;
  glm::dvec3 up() const;
  /// World distance per pixel at the depth of `atPoint` (the same for all points in ortho views).
  double worldPerPixel(const glm::dvec3& atPoint, double height) const;
  /// A world displacement in the view plane for a mouse motion of (dx, dy) pixels (y down).
  glm::dvec3 dragDelta(double dx, double dy, const glm::dvec3& atPoint, double height) const;
  /// Centers and zooms the view so that the box [lo, hi] fills about 80% of the image.
  void frame(const glm::dvec3& lo, const glm::dvec3& hi, double width, double height);
  bool perspective() const { return axis == ViewAxis::User && !orbit.orthographic(); }
};

/// Projects a world point to pixels (x right, y down) with a view-projection matrix;
/// returns false when the point is behind the camera.
bool projectToPixel(const glm::dmat4& viewProjection, double width, double height, const glm::dvec3& point,
                    glm::dvec2& pixel);

}  // namespace gridifs
