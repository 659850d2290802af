#pragma once
// The view of a directional light for shadow maps (Williams 1978, "Casting curved shadows on
// curved surfaces"): an orthographic projection along the light that covers a bounding sphere of
// everything the chaos game can plot, so that the same samples that fill the camera's z-buffer
// also fill one depth buffer per shadowed light.
//
// Conventions: `direction` points from the scene towards the light (unit). Texel (u, v): u to the
// light view's right, v down, size × size texels over the sphere's diameter. Light depth =
// radius − dot(p − center, direction): 0 at the light's side of the sphere, 2·radius at the far
// side, smaller is nearer the light.
//
// Thread-safety: immutable value type.
#include <glm/vec3.hpp>

#include "base/types.h"

namespace gridifs {

struct CompiledIfs;

struct BoundingSphere {
  glm::dvec3 center{0.0};
  double radius = 1.0;
};

// Declared before LightView, whose defaulted comparison needs it.
inline bool operator==(const BoundingSphere& a, const BoundingSphere& b) {
  return a.center == b.center && a.radius == b.radius;
}

/// A sphere holding every point the chaos game can plot for `ifs`: each function maps into the
/// convex hull of its distorted nodes (trilinear interpolation is a convex combination), so the
/// attractor lies in the union of those hulls — or, with a final function, in the final
/// function's hull. Pure.
BoundingSphere attractorBounds(const CompiledIfs& ifs);

class LightView {
 public:
  LightView() = default;
  /// Throws ModelError when `direction` is zero or not finite, or size is outside [16, 8192].
  LightView(const Vec3& direction, const BoundingSphere& bounds, int size);

  const glm::dvec3& direction() const { return direction_; }
  const glm::dvec3& right() const { return right_; }
  const glm::dvec3& up() const { return up_; }
  const BoundingSphere& bounds() const { return bounds_; }
  int size() const { return size_; }
  /// World units per texel.
  double texelSize() const { return 2.0 * bounds_.radius / double(size_); }
  /// World point → (u, v, light depth) as in the conventions above.
  glm::dvec3 project(const glm::dvec3& point) const;

  /// Affine rows for the hot loop: u = dot(rowU, (p, 1)), v = dot(rowV, (p, 1)), depth = dot(rowD, (p, 1)).
  struct Rows {
    float rowU[4], rowV[4], rowD[4];
  };
  Rows rows() const;

  bool operator==(const LightView&) const = default;

  /// A view as stored (a render part): the axes exactly as another LightView had them.
  static LightView restore(const glm::dvec3& direction, const glm::dvec3& right, const glm::dvec3& up,
                           const BoundingSphere& bounds, int size) {
    LightView v;
    v.direction_ = direction;
    v.right_ = right;
    v.up_ = up;
    v.bounds_ = bounds;
    v.size_ = size;
    return v;
  }

 private:
  glm::dvec3 direction_{0.0, 0.0, 1.0}, right_{1.0, 0.0, 0.0}, up_{0.0, 1.0, 0.0};
  BoundingSphere bounds_;
  int size_ = 16;
};

}  // namespace gridifs
