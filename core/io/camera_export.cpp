#include "io/camera_export.h"

#include <cmath>
#include <cstdio>

#include "render/camera.h"

namespace gridifs {
namespace {

/// %.17g: every double written exactly.
std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string frameNumber(double frame) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", frame);
  return text;
}

/// The camera-to-world matrix of `camera` (column major, glm's m[column][row]).
glm::dmat4 cameraToWorld(const Camera& camera, int width, int height) {
  return glm::inverse(OrbitCamera(camera, width, height).view());
}

/// The vertical field of view of the flat camera that stands in for `camera`, in degrees.
double verticalFov(const Camera& camera, int width, int height) {
  if (!camera.panoramic()) return camera.fov;
  const EyeRegion eye = OrbitCamera(camera, width, height).eyeRegion(0);
  const double eyeAspect = double(eye.width) / double(eye.height);
  // The equirectangular vertical extent, or the fisheye circle's, capped where a flat lens ends.
  const double vertical = camera.projection == CameraProjection::Equirectangular ? camera.fov / eyeAspect : camera.fov;
  return std::min(vertical, 120.0);
}

std::string usdMatrix(const glm::dmat4& m) {
  // USD's matrix4d is row-vector order: its rows are glm's columns.
  std::string text = "(";
  for (int row = 0; row < 4; ++row) {
    text += row ? ", (" : "(";
    for (int col = 0; col < 4; ++col) text += (col ? ", " : "") + number(m[row][col]);
    text += ")";
  }
  return text + ")";
}

}  // namespace

std::string cameraUsda(const std::vector<CameraSample>& samples, int width, int height, double fps) {
  if (samples.empty()) return "";
  const Camera& first = samples.front().camera;
  const OrbitCamera orbit(first, width, height);
  const EyeRegion eye = orbit.eyeRegion(0);
  const double aspect = double(eye.width) / double(eye.height);
  const bool animated = samples.size() > 1;
  std::string out = "#usda 1.0\n(\n    defaultPrim = \"camera\"\n    doc = \"GridIFS camera\"\n";
  out += "    metersPerUnit = 1\n    upAxis = \"Z\"\n";
  if (animated) {
    out += "    startTimeCode = " + frameNumber(samples.front().frame) + "\n";
    out += "    endTimeCode = " + frameNumber(samples.back().frame) + "\n";
    out += "    timeCodesPerSecond = " + number(fps) + "\n";
  }
  out += ")\n\ndef Camera \"camera\"\n{\n";
  // Focal length fixed at 50 (tenths of a unit); the aperture carries the field of view.
  constexpr double kFocal = 50.0;
  auto apertureOf = [&](const Camera& c) {
    if (c.orthographic()) return 10.0 * 2.0 * c.distance * std::tan(c.fov * M_PI / 360.0);  // tenths of a unit
    return 2.0 * kFocal * std::tan(verticalFov(c, width, height) * M_PI / 360.0);
  };
  out += std::string("    token projection = \"") + (first.orthographic() ? "orthographic" : "perspective") + "\"\n";
  out += "    float focalLength = " + number(kFocal) + "\n";
  out += "    float2 clippingRange = (" + number(orbit.nearPlane()) + ", " + number(orbit.farPlane()) + ")\n";
  if (first.panoramic()) {
    out += std::string("    custom string gridifs:projection = \"") + projectionName(first.projection) + "\"\n";
    out += "    custom float gridifs:fov = " + number(first.fov) + "\n";
  }
  auto sampled = [&](const std::string& declaration, auto valueOf) {
    if (!animated) {
      out += "    " + declaration + " = " + valueOf(first) + "\n";
      return;
    }
    out += "    " + declaration + ".timeSamples = {\n";
    for (const CameraSample& s : samples) out += "        " + frameNumber(s.frame) + ": " + valueOf(s.camera) + ",\n";
    out += "    }\n";
  };
  sampled("float verticalAperture", [&](const Camera& c) { return number(apertureOf(c)); });
  sampled("float horizontalAperture", [&](const Camera& c) { return number(apertureOf(c) * aspect); });
  // A lens shift moves the film: USD's aperture offsets, in the aperture's units.
  bool shifted = false;
  for (const CameraSample& s : samples) shifted |= s.camera.shift_x != 0.0 || s.camera.shift_y != 0.0;
  if (shifted) {
    sampled("float horizontalApertureOffset", [&](const Camera& c) { return number(apertureOf(c) * c.shift_x); });
    sampled("float verticalApertureOffset", [&](const Camera& c) { return number(apertureOf(c) * c.shift_y); });
  }
  sampled("matrix4d xformOp:transform", [&](const Camera& c) { return usdMatrix(cameraToWorld(c, width, height)); });
  out += "    uniform token[] xformOpOrder = [\"xformOp:transform\"]\n}\n";
  return out;
}

std::string cameraChan(const std::vector<CameraSample>& samples, int width, int height) {
  std::string out;
  for (const CameraSample& s : samples) {
    const glm::dmat4 m = cameraToWorld(s.camera, width, height);
    // Into the +y-up world: (x, y, z) → (x, z, −y), applied to the position and the rotation.
    const glm::dmat3 toYUp(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0));  // columns
    const glm::dmat3 r = toYUp * glm::dmat3(m);
    const glm::dvec3 t = toYUp * glm::dvec3(m[3]);
    // R = Ry(b) · Rx(a) · Rz(c): R[1][2] = −sin a, R[0][2] = sin b cos a, R[2][2] = cos b cos a,
    // R[1][0] = cos a sin c, R[1][1] = cos a cos c (math indices; glm's r[column][row]).
    const double a = std::asin(std::clamp(-r[2][1], -1.0, 1.0));
    const double b = std::atan2(r[2][0], r[2][2]);
    const double c = std::atan2(r[0][1], r[1][1]);
    const double degrees = 180.0 / M_PI;
    out += frameNumber(s.frame) + " " + number(t.x) + " " + number(t.y) + " " + number(t.z) + " " +
           number(a * degrees) + " " + number(b * degrees) + " " + number(c * degrees) + " " +
           number(verticalFov(s.camera, width, height)) + "\n";
  }
  return out;
}

}  // namespace gridifs
