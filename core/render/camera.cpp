#include "render/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace gridifs {
namespace {

double radians(double degrees) { return degrees * (M_PI / 180.0); }

double clampedPitch(double pitch) { return std::clamp(pitch, -89.9, 89.9); }

}  // namespace

glm::dvec3 orbitEye(const Camera& camera) {
  const double yaw = radians(camera.yaw), pitch = radians(clampedPitch(camera.pitch));
  return camera.target + camera.distance * glm::dvec3(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw),
                                                      std::sin(pitch));
}

OrbitCamera::OrbitCamera(const Camera& camera, int width, int height)
    : camera_(camera), width_(width), height_(height) {
  if (width < 1 || height < 1) throw ModelError("render", "image width and height must be at least 1 pixel");
  if (!(camera.distance > 0.0) || !std::isfinite(camera.distance))
    throw ModelError("camera.distance", "must be a positive number");
  if (!(camera.fov > 0.0 && camera.fov <= 179.0)) throw ModelError("camera.fov", "must be in (0, 179] degrees");
  eye_ = orbitEye(camera);
  view_ = glm::lookAt(eye_, camera.target, glm::dvec3(0.0, 0.0, 1.0));
  // X lies within √3 of the origin; keep it (and a margin for final functions) inside the
  // GL depth range. The CPU renderer only culls at the near plane.
  const double reach = glm::length(camera.target) + std::sqrt(3.0);
  near_ = std::max(1e-3, 0.01 * camera.distance);
  far_ = camera.distance + 2.0 * reach + 10.0;
  const double fovy = radians(camera.fov);
  if (camera.ortho) {
    const double halfH = camera.distance * std::tan(fovy * 0.5), halfW = halfH * aspect();
    projection_ = glm::ortho(-halfW, halfW, -halfH, halfH, near_, far_);
  } else {
    projection_ = glm::perspective(fovy, aspect(), near_, far_);
  }
}

ProjectedPoint OrbitCamera::project(const glm::dvec3& point) const {
  const glm::dvec4 v = view_ * glm::dvec4(point, 1.0);
  const glm::dvec4 c = projection_ * v;
  ProjectedPoint out;
  out.depth = -v.z;
  out.inFront = out.depth > near_;
  const double w = c.w != 0.0 ? c.w : 1e-300;
  out.x = (c.x / w * 0.5 + 0.5) * width_;
  out.y = (0.5 - c.y / w * 0.5) * height_;  // y down
  return out;
}

OrbitCamera::PixelRows OrbitCamera::pixelRows() const {
  // pixel = viewport · projection · view; viewport maps NDC x to (x/2 + 1/2)·W and y to
  // (1/2 − y/2)·H, i.e. rowX = (W/2)·clipX + (W/2)·clipW, rowY = −(H/2)·clipY + (H/2)·clipW.
  const glm::dmat4 m = projection_ * view_;
  auto row = [&](int r) { return glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
  const glm::dvec4 cx = row(0), cy = row(1), cw = row(3);
  const glm::dvec4 px = 0.5 * width_ * (cx + cw), py = 0.5 * height_ * (cw - cy);
  const glm::dvec4 d = -glm::dvec4(view_[0][2], view_[1][2], view_[2][2], view_[3][2]);
  PixelRows rows{};
  for (int i = 0; i < 4; ++i) {
    rows.rowX[i] = float(px[i]);
    rows.rowY[i] = float(py[i]);
    rows.rowW[i] = float(cw[i]);
    rows.rowD[i] = float(d[i]);
  }
  return rows;
}

}  // namespace gridifs
