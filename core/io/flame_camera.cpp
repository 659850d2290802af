#include "io/flame_camera.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "io/flame_genome.h"
#include "render/camera.h"
#include "schema/settings_tables.h"

namespace gridifs {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegrees = 180.0 / kPi;

/// X = (x, y, −z): the flame's space mirrored so that its camera is right-handed.
glm::dvec3 mirrored(const glm::dvec3& v) { return {v.x, v.y, -v.z}; }

glm::dvec3 row(const std::array<std::array<double, 3>, 3>& m, int i) {
  return {m[std::size_t(i)][0], m[std::size_t(i)][1], m[std::size_t(i)][2]};
}

/// The picture's right and down axes in the flame's space: the camera's, turned by `rotate`
/// (points are plotted at R(rotate)·(x', y') with x right and y down).
void pictureAxes(const FlameCamera& f, glm::dvec3& right, glm::dvec3& down, glm::dvec3& back) {
  const auto m = flameCameraRows(f.pitch, f.yaw);
  const double t = f.rotate * kPi / 180.0, c = std::cos(t), s = std::sin(t);
  right = c * row(m, 0) - s * row(m, 1);
  down = s * row(m, 0) + c * row(m, 1);
  back = row(m, 2);
}

}  // namespace

std::array<std::array<double, 3>, 3> flameCameraRows(double pitch, double yaw) {
  const double cy = std::cos(-yaw), sy = std::sin(-yaw), cp = std::cos(pitch), sp = std::sin(pitch);
  return {{{cy, -sy, 0.0}, {cp * sy, cp * cy, -sp}, {sp * sy, sp * cy, cp}}};
}

Camera cameraFromFlame(const FlameCamera& flame, int height, double reach) {
  if (flame.perspective < 0.0)
    throw FlameError("a negative cam_perspective puts the flame's eye behind its picture, which no camera can hold");
  if (!(flame.pixelsPerUnit > 0.0) || height < 1)
    throw FlameError("the genome's view is too small or too large to frame");
  glm::dvec3 right, down, back;
  pictureAxes(flame, right, down, back);
  // In X the camera's right, up and back axes (right × up = back: right-handed).
  const glm::dvec3 r = mirrored(right), b = mirrored(back);
  Camera cam;
  cam.pitch = std::clamp(std::asin(std::clamp(b.z, -1.0, 1.0)) * kDegrees, -90.0, 90.0);
  const bool vertical = std::hypot(b.x, b.y) < 1e-12;
  // Looking straight up or down the yaw alone turns the picture (the orbit camera's right axis is
  // (−sin yaw, cos yaw, 0) there); otherwise it points the eye and roll turns the picture.
  cam.yaw = (vertical ? std::atan2(-r.x, r.y) : std::atan2(b.y, b.x)) * kDegrees;
  const double yaw = cam.yaw / kDegrees;
  const glm::dvec3 right0(-std::sin(yaw), std::cos(yaw), 0.0), up0 = glm::cross(b, right0);
  cam.roll = vertical ? 0.0 : std::atan2(glm::dot(r, up0), glm::dot(r, right0)) * kDegrees;
  if (std::fabs(cam.roll) < 1e-12) cam.roll = 0.0;

  const glm::dvec3 pivot(0.0, 0.0, -flame.zpos);  // (0, 0, zpos) in X
  const double halfH = 0.5 * height / flame.pixelsPerUnit;
  if (flame.perspective > 0.0) {
    // The eye at 1/perspective from the plane c_z = 0, which it shows at the view's scale; the
    // centre slides the picture after the divide: a lens shift in the turned picture's axes.
    cam.projection = CameraProjection::Perspective;
    cam.distance = 1.0 / flame.perspective;
    cam.target = pivot;
    cam.fov = 2.0 * std::atan(halfH / cam.distance) * kDegrees;
    const double t = flame.rotate * kPi / 180.0, c = std::cos(t), s = std::sin(t);
    const double sx = c * flame.centerX - s * flame.centerY, sy = s * flame.centerX + c * flame.centerY;
    cam.shift_x = sx * flame.pixelsPerUnit / height;
    cam.shift_y = -sy * flame.pixelsPerUnit / height;
  } else {
    // Orthographic: the centre is where the view's axis meets the plane c_z = 0, and the eye
    // stands beyond the attractor.
    const auto m = flameCameraRows(flame.pitch, flame.yaw);
    cam.projection = CameraProjection::Orthographic;
    cam.target = pivot + flame.centerX * mirrored(row(m, 0)) + flame.centerY * mirrored(row(m, 1));
    cam.distance = std::clamp(2.0 * reach + halfH, 2.0 * halfH, 100.0 * halfH);
    cam.fov = 2.0 * std::atan(halfH / cam.distance) * kDegrees;
  }
  if (!(cam.distance >= 1e-3 && cam.distance <= 1e4) || !(cam.fov >= 1.0 && cam.fov <= kMaxFlatFov) ||
      !(std::fabs(cam.shift_x) <= 100.0 && std::fabs(cam.shift_y) <= 100.0) || !(glm::length(cam.target) <= 1e4))
    throw FlameError("the genome's view is too small or too large to frame");
  return cam;
}

FlameCameraExport flameCameraFromProject(const Camera& camera, int height) {
  if (camera.panoramic()) throw FlameError("a flame camera is flat: it has no fisheye or equirectangular projection");
  if (camera.stereo) throw FlameError("a flame camera has one eye: it cannot hold a stereo pair");
  const OrbitCamera orbit(camera, 1, std::max(1, height));
  const glm::dmat4& v = orbit.view();
  const glm::dvec3 r(v[0][0], v[1][0], v[2][0]), b(v[0][2], v[1][2], v[2][2]);
  // The picture's right axis and the back axis towards the eye, in the flame's space.
  const glm::dvec3 right = mirrored(r), back = mirrored(b);
  FlameCameraExport out;
  FlameCamera& f = out.camera;
  f.pitch = std::acos(std::clamp(back.z, -1.0, 1.0));
  const double sp = std::sin(f.pitch);
  f.yaw = sp > 1e-12 ? -std::atan2(back.x, back.y) : 0.0;
  const auto m = flameCameraRows(f.pitch, f.yaw);
  f.rotate = std::atan2(-glm::dot(right, row(m, 1)), glm::dot(right, row(m, 0))) * kDegrees;
  if (std::fabs(f.rotate) < 1e-12) f.rotate = 0.0;
  if (std::fabs(f.yaw) < 1e-15) f.yaw = 0.0;
  const double halfH = camera.distance * std::tan(camera.fov * kPi / 360.0);
  f.pixelsPerUnit = 0.5 * height / halfH;
  const glm::dvec3 target = mirrored(camera.target);
  if (camera.orthographic()) {
    // Any point of the view's axis will do: the one at c_z = 0 with zpos 0.
    f.centerX = glm::dot(target, row(m, 0));
    f.centerY = glm::dot(target, row(m, 1));
    return out;
  }
  // The target becomes the flame camera's pivot (0, 0, zpos): the genome moves by −target.xy.
  out.moveX = -target.x;
  out.moveY = -target.y;
  f.zpos = target.z;
  f.perspective = 1.0 / camera.distance;
  // The lens shift, in the turned picture's axes, back into the unturned plane.
  const double sx = camera.shift_x * height / f.pixelsPerUnit, sy = -camera.shift_y * height / f.pixelsPerUnit;
  const double t = f.rotate * kPi / 180.0, c = std::cos(t), s = std::sin(t);
  f.centerX = c * sx + s * sy;
  f.centerY = -s * sx + c * sy;
  return out;
}

}  // namespace gridifs
