#include "edit/flame_symmetry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/trigonometric.hpp>

namespace gridifs {
namespace {

/// Rodrigues' rotation by `radians` about unit `axis`.
glm::dmat3 rotationAbout(const Vec3& axis, double radians) {
  const double c = std::cos(radians), s = std::sin(radians), t = 1.0 - c;
  const double x = axis.x, y = axis.y, z = axis.z;
  // glm is column-major: m[col][row].
  glm::dmat3 m;
  m[0] = {t * x * x + c, t * x * y + s * z, t * x * z - s * y};
  m[1] = {t * x * y - s * z, t * y * y + c, t * y * z + s * x};
  m[2] = {t * x * z + s * y, t * y * z - s * x, t * z * z + c};
  return m;
}

}  // namespace

SymmetryFrame symmetryFrameForView(const Camera& camera) {
  // OrbitCamera: eye = target + distance·(cos p cos y, cos p sin y, sin p), +z up.
  const double yaw = glm::radians(camera.yaw), pitch = glm::radians(std::clamp(camera.pitch, -89.9, 89.9));
  const Vec3 toEye{std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch)};
  SymmetryFrame f;
  f.center = camera.target;
  f.axis = -toEye;  // viewing direction
  Vec3 right = glm::cross(f.axis, Vec3{0.0, 0.0, 1.0});
  if (glm::length(right) < 1e-9) right = Vec3{1.0, 0.0, 0.0};
  f.mirror = glm::normalize(right);
  return f;
}

Function affineFunction(const std::string& name, const glm::dmat3& m, const Vec3& t, double weight) {
  Function f;
  f.name = name;
  f.resolution = {2, 2, 2};
  f.weight = weight;
  f.color_speed = 0.0;  // Draves & Reckase 2003, §7: symmetry functions leave the color coordinate alone
  f.palette_index = 0.0;
  f.color = {1.0, 1.0, 1.0};
  NodesOp nodes;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const Vec3 u{i ? 1.0 : -1.0, j ? 1.0 : -1.0, k ? 1.0 : -1.0};
        nodes.moves.push_back({{i, j, k}, m * u + t - u});
      }
  Operation op;
  op.params = nodes;
  f.ops.push_back(op);
  return f;
}

std::vector<Function> symmetryFunctions(const Project& project, int symmetry, const SymmetryFrame& frame) {
  if (symmetry > 32 || symmetry < -32) throw ModelError("symmetry", "expected a symmetry between -32 and 32");
  if (!(glm::length(frame.axis) > 1e-9) || !(glm::length(frame.mirror) > 1e-9))
    throw ModelError("symmetry", "the symmetry axis is degenerate");
  const Vec3 axis = glm::normalize(frame.axis);
  double total = 0.0;
  for (const Function& f : project.functions)
    if (!f.muted) total += f.weight;
  if (!(total > 0.0)) total = 1.0;
  std::vector<Function> out;
  if (symmetry == 0 || symmetry == 1) return out;
  // p ↦ c + M(p − c) = M·p + (c − M·c)
  auto about = [&](const glm::dmat3& m) { return frame.center - m * frame.center; };
  if (symmetry < 0) {
    // Mirror across the plane through the axis that contains the image's vertical direction.
    Vec3 n = frame.mirror - glm::dot(frame.mirror, axis) * axis;
    n = glm::normalize(n);
    const glm::dmat3 mirror = glm::dmat3(1.0) - 2.0 * glm::outerProduct(n, n);
    out.push_back(affineFunction("sym mirror", mirror, about(mirror), total));
  }
  const int n = symmetry < 0 ? -symmetry : symmetry;
  for (int k = 1; k < n; ++k) {
    const double degrees = 360.0 * k / n;
    const glm::dmat3 r = rotationAbout(axis, glm::radians(degrees));
    char name[48];
    std::snprintf(name, sizeof name, "sym rot %g", degrees);
    out.push_back(affineFunction(name, r, about(r), total));
  }
  return out;
}

void addSymmetry(Project& project, int symmetry, const SymmetryFrame& frame) {
  std::vector<Function> added = symmetryFunctions(project, symmetry, frame);
  if (project.functions.size() + added.size() > std::size_t(limits::kMaxFunctions))
    throw ModelError("functions",
                     "adding the symmetry would exceed " + std::to_string(limits::kMaxFunctions) + " functions");
  for (Function& f : added) project.functions.push_back(std::move(f));
}

}  // namespace gridifs
