#include "edit/view_camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "render/camera.h"

namespace gridifs {
namespace {

double halfHeightOf(const Camera& c) { return c.distance * std::tan(glm::radians(c.fov) * 0.5); }

struct Basis {
  glm::dvec3 forward, up;
};

Basis axisBasis(ViewAxis axis) {
  switch (axis) {
    case ViewAxis::Top:
      return {{0, 0, -1}, {0, 1, 0}};
    case ViewAxis::Front:
      return {{0, 1, 0}, {0, 0, 1}};
    case ViewAxis::Side:
      return {{-1, 0, 0}, {0, 0, 1}};
    case ViewAxis::User:
      break;
  }
  return {{0, 0, -1}, {0, 1, 0}};
}

}  // namespace

const char* viewAxisName(ViewAxis axis) {
  switch (axis) {
    case ViewAxis::Top:
      return "Top";
    case ViewAxis::Side:
      return "Side";
    case ViewAxis::Front:
      return "Front";
    case ViewAxis::User:
      return "User";
  }
  return "User";
}

glm::dmat4 ViewCamera::view() const {
  // The user view uses OrbitCamera itself so that it matches the preview pixel for pixel.
  if (axis == ViewAxis::User) return OrbitCamera(orbit, 1, 1).view();
  const Basis b = axisBasis(axis);
  // Far enough back that the whole bi-unit cube (and generous distortions) is in front.
  const glm::dvec3 eye = orbit.target - b.forward * 50.0;
  return glm::lookAt(eye, orbit.target, b.up);
}

glm::dmat4 ViewCamera::projection(double width, double height) const {
  if (axis == ViewAxis::User)
    return OrbitCamera(orbit, std::max(1, int(std::lround(width))), std::max(1, int(std::lround(height)))).projection();
  const double aspect = std::max(width, 1.0) / std::max(height, 1.0);
  const double h = halfHeightOf(orbit);
  return glm::ortho(-h * aspect, h * aspect, -h, h, 0.0, 150.0);
}

glm::dvec3 ViewCamera::right() const {
  const glm::dmat4 v = view();
  return {v[0][0], v[1][0], v[2][0]};
}

glm::dvec3 ViewCamera::up() const {
  const glm::dmat4 v = view();
  return {v[0][1], v[1][1], v[2][1]};
}

double ViewCamera::worldPerPixel(const glm::dvec3& atPoint, double height) const {
  height = std::max(height, 1.0);
  if (!perspective()) return 2.0 * halfHeightOf(orbit) / height;
  const glm::dvec4 p = view() * glm::dvec4(atPoint, 1.0);
  const double depth = std::max(-p.z, 1e-3);
  return 2.0 * depth * std::tan(glm::radians(orbit.fov) * 0.5) / height;
}

glm::dvec3 ViewCamera::dragDelta(double dx, double dy, const glm::dvec3& atPoint, double height) const {
  const double s = worldPerPixel(atPoint, height);
  return right() * (dx * s) - up() * (dy * s);
}

void ViewCamera::frame(const glm::dvec3& lo, const glm::dvec3& hi, double width, double height) {
  orbit.target = (lo + hi) * 0.5;
  const double aspect = std::max(width, 1.0) / std::max(height, 1.0);
  // Extent of the box across the screen's right and up directions.
  const glm::dvec3 half = (hi - lo) * 0.5;
  const glm::dvec3 r = right(), u = up();
  const double ex = std::abs(r.x) * half.x + std::abs(r.y) * half.y + std::abs(r.z) * half.z;
  const double ey = std::abs(u.x) * half.x + std::abs(u.y) * half.y + std::abs(u.z) * half.z;
  if (perspective()) {
    // Fit the bounding sphere (any orbit angle) inside the narrower field of view.
    const double radius = std::max(glm::length(half), 1e-3);
    const double halfFov = glm::radians(orbit.fov) * 0.5;
    const double narrow = aspect < 1.0 ? std::atan(std::tan(halfFov) * aspect) : halfFov;
    orbit.distance = radius / std::sin(narrow) * 0.95;
    return;
  }
  double needed = std::max({ey, ex / aspect, 1e-3}) / 0.8;
  if (axis == ViewAxis::User) needed = std::max(needed, glm::length(half) / 0.8);  // any orbit angle
  orbit.distance = needed / std::tan(glm::radians(orbit.fov) * 0.5);
}

bool projectToPixel(const glm::dmat4& viewProjection, double width, double height, const glm::dvec3& point,
                    glm::dvec2& pixel) {
  const glm::dvec4 c = viewProjection * glm::dvec4(point, 1.0);
  if (c.w <= 1e-9) return false;
  pixel.x = (c.x / c.w * 0.5 + 0.5) * width;
  pixel.y = (0.5 - c.y / c.w * 0.5) * height;
  return true;
}

}  // namespace gridifs
