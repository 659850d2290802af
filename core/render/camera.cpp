#include "render/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

namespace gridifs {
namespace {

double radians(double degrees) { return degrees * (M_PI / 180.0); }

double clampedPitch(double pitch) { return std::clamp(pitch, -90.0, 90.0); }

/// World → view for an eye at `eye` turned by yaw and pitch (degrees), +z up. Within ±89.9° of
/// pitch it is OpenGL's look-at; steeper it is the look-at's limit, whose right axis
/// (−sin yaw, cos yaw, 0) does not depend on the pitch, so a view straight up or down is exact
/// and yaw turns it. Roll then turns the camera about its viewing axis.
glm::dmat4 orbitView(const Camera& camera, const glm::dvec3& eye) {
  glm::dmat4 view;
  if (std::abs(camera.pitch) <= 89.9) {
    view = glm::lookAt(eye, camera.target, glm::dvec3(0.0, 0.0, 1.0));
  } else {
    const double yaw = radians(camera.yaw), pitch = radians(clampedPitch(camera.pitch));
    const glm::dvec3 back(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch));
    const glm::dvec3 right(-std::sin(yaw), std::cos(yaw), 0.0), up = glm::cross(back, right);
    view = glm::dmat4(1.0);
    for (int c = 0; c < 3; ++c) {  // rows: right, up, back (glm's m[column][row])
      view[c][0] = right[c];
      view[c][1] = up[c];
      view[c][2] = back[c];
    }
    view[3] = glm::dvec4(-glm::dot(right, eye), -glm::dot(up, eye), -glm::dot(back, eye), 1.0);
  }
  if (camera.roll == 0.0) return view;
  // The camera's axes turn counter-clockwise by roll, so view coordinates turn by −roll.
  const double c = std::cos(radians(camera.roll)), s = std::sin(radians(camera.roll));
  glm::dmat4 turn(1.0);
  turn[0][0] = c;
  turn[1][0] = s;
  turn[0][1] = -s;
  turn[1][1] = c;
  return turn * view;
}

/// The lens shift as an offset of normalized device coordinates for an eye `eyeAspect` wide.
glm::dvec2 lensShiftNdc(const Camera& camera, double eyeAspect) {
  return {-2.0 * camera.shift_x / eyeAspect, -2.0 * camera.shift_y};
}

/// The rotation by `angle` about the unit axis `axis` (Rodrigues).
glm::dmat3 turnAbout(const glm::dvec3& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  const double x = axis.x, y = axis.y, z = axis.z;
  // glm is column major: m[column][row].
  glm::dmat3 m;
  m[0] = glm::dvec3(t * x * x + c, t * x * y + s * z, t * x * z - s * y);
  m[1] = glm::dvec3(t * x * y - s * z, t * y * y + c, t * y * z + s * x);
  m[2] = glm::dvec3(t * x * z + s * y, t * y * z - s * x, t * z * z + c);
  return m;
}

/// How far a parallel stereo eye of `sign` (−1 left, +1 right, 0 mono) sits from the centre along
/// view x.
double parallelEyeShift(const Camera& camera, double sign) {
  return camera.stereo ? 0.5 * camera.stereo->eye_separation * sign : 0.0;
}

}  // namespace

const char* projectionName(CameraProjection projection) {
  switch (projection) {
    case CameraProjection::Perspective:
      return "perspective";
    case CameraProjection::Orthographic:
      return "orthographic";
    case CameraProjection::Fisheye:
      return "fisheye";
    case CameraProjection::Equirectangular:
      return "equirectangular";
  }
  return "perspective";
}

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
  const double widest = camera.panoramic() ? 360.0 : 179.0;
  if (!(camera.fov > 0.0 && camera.fov <= widest))
    throw ModelError("camera.fov", camera.panoramic() ? "must be in (0, 360] degrees" : "must be in (0, 179] degrees");
  eyes_ = camera.stereo ? 2 : 1;
  region_[0] = region_[1] = EyeRegion{0, 0, width, height};
  if (camera.stereo) {
    const bool sideBySide = camera.stereo->layout == StereoLayout::SideBySide;
    // A frame one pixel across still has an eye of one pixel (the second one falls outside it).
    const int w = sideBySide ? std::max(1, width / 2) : width, h = sideBySide ? height : std::max(1, height / 2);
    region_[0] = EyeRegion{0, 0, w, h};
    region_[1] = EyeRegion{sideBySide ? w : 0, sideBySide ? 0 : h, w, h};
    radius_ = 0.5 * camera.stereo->eye_separation;
  }
  eye_ = orbitEye(camera);
  view_ = orbitView(camera, eye_);
  up_ = glm::dvec3(view_ * glm::dvec4(0.0, 0.0, 1.0, 0.0));
  // X lies within √3 of the origin; keep it (and a margin for final functions) inside the
  // GL depth range. The CPU renderer only culls at the near plane.
  const double reach = glm::length(camera.target) + std::sqrt(3.0);
  near_ = std::max(1e-3, 0.01 * camera.distance);
  far_ = camera.distance + 2.0 * reach + 10.0;
  const double eyeAspect = double(region_[0].width) / double(region_[0].height);
  if (camera.panoramic()) {
    const EyeRegion& r = region_[0];
    const double halfFov = radians(camera.fov) * 0.5;
    pixelsPerRadian_ = camera.projection == CameraProjection::Fisheye ? 0.5 * std::min(r.width, r.height) / halfFov
                                                                      : 0.5 * r.width / halfFov;
    projection_ = glm::perspective(radians(std::min(camera.fov, 120.0)), eyeAspect, near_, far_);
    if (camera.stereo && camera.stereo->convergence > radius_) {
      // The left eye sees a point at the convergence distance asin(radius / convergence) to the
      // right of straight ahead: its directions turn left by that much (anticlockwise seen from
      // above), the right eye's right.
      const double angle = std::asin(radius_ / camera.stereo->convergence);
      turn_[0] = turnAbout(up_, angle);
      turn_[1] = turnAbout(up_, -angle);
    }
    return;
  }
  const double fovy = radians(camera.fov);
  if (camera.orthographic()) {
    const double halfH = camera.distance * std::tan(fovy * 0.5), halfW = halfH * eyeAspect;
    projection_ = glm::ortho(-halfW, halfW, -halfH, halfH, near_, far_);
  } else {
    projection_ = glm::perspective(fovy, eyeAspect, near_, far_);
  }
  // A lens shift slides the picture: clip x and y gain the offset times clip w.
  const glm::dvec2 offset = lensShiftNdc(camera, eyeAspect);
  for (int c = 0; c < 4; ++c) {
    projection_[c][0] += offset.x * projection_[c][3];
    projection_[c][1] += offset.y * projection_[c][3];
  }
}

glm::dvec3 OrbitCamera::panoramicEyeView(const glm::dvec3& v, int eye, bool& outsideCircle) const {
  outsideCircle = true;
  if (eyes_ == 1) return v;
  // The eye E on the circle of radius r about the vertical axis whose ray to the point touches
  // the circle: E·(P − E) = 0 and |E| = r, on the eye's side. With P_h the point's horizontal
  // part (length d) and t = √(d² − r²): E = (r²/d²)·P_h + s·(r·t/d²)·(P_h × up).
  const double r = radius_, s = eyeSign(eye);
  const glm::dvec3 horizontal = v - glm::dot(v, up_) * up_;
  const double d2 = glm::dot(horizontal, horizontal);
  if (!(d2 > r * r)) {
    outsideCircle = false;
    return v;
  }
  const double t = std::sqrt(d2 - r * r);
  const glm::dvec3 e = (r * r / d2) * horizontal + (s * r * t / d2) * glm::cross(horizontal, up_);
  return turn_[eye] * (v - e);
}

ProjectedPoint OrbitCamera::project(const glm::dvec3& point, int eye) const {
  eye = eyes_ == 2 ? std::clamp(eye, 0, 1) : 0;
  const EyeRegion& region = region_[eye];
  ProjectedPoint out;
  if (panoramic()) {
    bool outsideCircle = true;
    const glm::dvec3 v = panoramicEyeView(glm::dvec3(view_ * glm::dvec4(point, 1.0)), eye, outsideCircle);
    out.depth = glm::length(v);
    const double cx = region.x + 0.5 * region.width, cy = region.y + 0.5 * region.height;
    if (camera_.projection == CameraProjection::Fisheye) {
      const double h = std::hypot(v.x, v.y), theta = std::atan2(h, -v.z), rho = theta * pixelsPerRadian_;
      out.x = cx + (h > 0.0 ? rho * v.x / h : 0.0);
      out.y = cy - (h > 0.0 ? rho * v.y / h : 0.0);
      out.inFront = outsideCircle && out.depth > near_ && theta <= radians(camera_.fov) * 0.5;
    } else {
      const double longitude = std::atan2(v.x, -v.z), latitude = std::atan2(v.y, std::hypot(v.x, v.z));
      out.x = cx + longitude * pixelsPerRadian_;
      out.y = cy - latitude * pixelsPerRadian_;
      out.inFront = outsideCircle && out.depth > near_;
    }
    return out;
  }
  glm::dvec4 v = view_ * glm::dvec4(point, 1.0);
  const double shift = parallelEyeShift(camera_, eyeSign(eye));
  v.x -= shift;
  const glm::dvec4 c = projection_ * v;
  out.depth = -v.z;
  out.inFront = out.depth > near_;
  const double w = c.w != 0.0 ? c.w : 1e-300;
  double ndcX = c.x / w;
  if (eyes_ == 2) ndcX += projection_[0][0] * shift / camera_.stereo->convergence;  // off-axis: no parallax there
  out.x = region.x + (ndcX * 0.5 + 0.5) * region.width;
  out.y = region.y + (0.5 - c.y / w * 0.5) * region.height;  // y down
  return out;
}

PixelRay OrbitCamera::rayThrough(double x, double y) const {
  PixelRay ray;
  int eye = 0;
  if (eyes_ == 2) {
    const EyeRegion& right = region_[1];
    if (x >= right.x && y >= right.y && (right.x > 0 || right.y > 0)) eye = 1;
  }
  const EyeRegion& region = region_[eye];
  if (x < region.x || y < region.y || x > region.x + region.width || y > region.y + region.height) return ray;
  const glm::dmat3 viewToWorld = glm::transpose(glm::dmat3(view_));
  glm::dvec3 origin(0.0), step(0.0, 0.0, -1.0);
  if (panoramic()) {
    const double dx = x - (region.x + 0.5 * region.width), dy = (region.y + 0.5 * region.height) - y;
    glm::dvec3 direction;
    if (camera_.projection == CameraProjection::Fisheye) {
      const double theta = std::hypot(dx, dy) / pixelsPerRadian_;
      if (theta > radians(camera_.fov) * 0.5) return ray;
      const double phi = std::atan2(dy, dx);
      direction = glm::dvec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), -std::cos(theta));
    } else {
      const double longitude = dx / pixelsPerRadian_, latitude = dy / pixelsPerRadian_;
      if (std::abs(latitude) > 0.5 * M_PI) return ray;  // beyond a pole: an image taller than 180°
      direction = glm::dvec3(std::cos(latitude) * std::sin(longitude), std::sin(latitude),
                             -std::cos(latitude) * std::cos(longitude));
    }
    step = glm::transpose(turn_[eye]) * direction;
    if (eyes_ == 2) {
      const glm::dvec3 horizontal = step - glm::dot(step, up_) * up_;
      const double length = glm::length(horizontal);
      if (length > 1e-12) origin = eyeSign(eye) * radius_ * glm::cross(horizontal, up_) / length;
    }
  } else {
    const glm::dvec2 offset = lensShiftNdc(camera_, double(region.width) / double(region.height));
    const double ndcX = (x - region.x) / region.width * 2.0 - 1.0 - offset.x,
                 ndcY = 1.0 - (y - region.y) / region.height * 2.0 - offset.y;
    const double shift = parallelEyeShift(camera_, eyeSign(eye));
    const double lensX = eyes_ == 2 ? ndcX - projection_[0][0] * shift / camera_.stereo->convergence : ndcX;
    if (camera_.orthographic()) {
      origin = glm::dvec3(lensX / projection_[0][0], ndcY / projection_[1][1], 0.0);
    } else {
      step = glm::dvec3(lensX / projection_[0][0], ndcY / projection_[1][1], -1.0);
      origin = glm::dvec3(shift, 0.0, 0.0);
    }
  }
  ray.origin = eye_ + viewToWorld * origin;
  ray.step = viewToWorld * step;
  ray.valid = true;
  return ray;
}

OrbitCamera::PixelRows OrbitCamera::pixelRows(int eye) const {
  eye = eyes_ == 2 ? std::clamp(eye, 0, 1) : 0;
  PixelRows rows{};
  const glm::dvec4 d = -glm::dvec4(view_[0][2], view_[1][2], view_[2][2], view_[3][2]);
  if (panoramic()) {
    for (int i = 0; i < 4; ++i) {
      rows.rowX[i] = float(view_[i][0]);
      rows.rowY[i] = float(view_[i][1]);
      rows.rowW[i] = float(view_[i][2]);
      rows.rowD[i] = float(d[i]);
    }
    return rows;
  }
  // pixel = viewport · projection · view; viewport maps NDC x to (x/2 + 1/2)·W and y to
  // (1/2 − y/2)·H, i.e. rowX = (W/2)·clipX + (W/2)·clipW, rowY = −(H/2)·clipY + (H/2)·clipW.
  // A stereo eye moves along view x by ±separation/2 and its image shifts so that the
  // convergence distance has no parallax; its region's corner is added as corner · clipW.
  glm::dmat4 view = view_;
  double shift = 0.0;
  if (eyes_ == 2) {
    shift = parallelEyeShift(camera_, eyeSign(eye));
    view[3][0] -= shift;
  }
  const glm::dmat4 m = projection_ * view;
  auto row = [&](int r) { return glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
  glm::dvec4 cx = row(0);
  const glm::dvec4 cy = row(1), cw = row(3);
  if (eyes_ == 2) cx += projection_[0][0] * shift / camera_.stereo->convergence * cw;
  const EyeRegion& r = region_[eye];
  const glm::dvec4 px = 0.5 * r.width * (cx + cw) + double(r.x) * cw,
                   py = 0.5 * r.height * (cw - cy) + double(r.y) * cw;
  for (int i = 0; i < 4; ++i) {
    rows.rowX[i] = float(px[i]);
    rows.rowY[i] = float(py[i]);
    rows.rowW[i] = float(cw[i]);
    rows.rowD[i] = float(d[i]);
  }
  return rows;
}

ExrCameraMatrices exrCameraMatrices(const OrbitCamera& camera) {
  ExrCameraMatrices out;
  // Column-vector matrices, stored transposed: Imath multiplies row vectors.
  auto rowVectorOrder = [](const glm::dmat4& m) {
    std::vector<float> v(16);
    for (int row = 0; row < 4; ++row)
      for (int col = 0; col < 4; ++col) v[std::size_t(4 * row + col)] = float(m[row][col]);  // m[column][row]
    return v;
  };
  glm::dmat4 flipZ(1.0);
  flipZ[2][2] = -1.0;  // right-handed, looking down −z → left-handed, looking down +z
  out.worldToCamera = rowVectorOrder(flipZ * camera.view());
  if (camera.panoramic()) return out;
  // The pixel rows (x·w, y·w, w) of the left eye over the frame's size give NDC after the divide.
  const OrbitCamera::PixelRows rows = camera.pixelRows(0);
  glm::dmat4 ndc(0.0);
  for (int c = 0; c < 4; ++c) {
    ndc[c][0] = rows.rowX[c] / double(camera.width());
    ndc[c][1] = rows.rowY[c] / double(camera.height());
    ndc[c][2] = rows.rowD[c];
    ndc[c][3] = rows.rowW[c];
  }
  out.worldToNDC = rowVectorOrder(ndc);
  return out;
}

glm::dvec3 pixelWorldPosition(const OrbitCamera& camera, int x, int y, double depth) {
  const PixelRay ray = camera.rayThrough(x + 0.5, y + 0.5);
  if (!ray.valid) return glm::dvec3(std::numeric_limits<double>::quiet_NaN());
  return ray.origin + ray.step * depth;
}

}  // namespace gridifs
