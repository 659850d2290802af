#pragma once
// Shared fixtures for the deterministic-algorithm tests (Gröller & Wegenkittl 1994, §3.2): affine IFSs built from
// 2×2×2 grids (trilinear interpolation of an affine map is exact), and mesh measurements.
#include <unistd.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <string>

#include "mesh/ifs_mesh.h"
#include "model/project.h"

namespace gridifs::test_support {

/// The four corners of a regular tetrahedron inscribed in X = [-1, 1]^3.
inline const std::array<Vec3, 4>& tetrahedronCorners() {
  static const std::array<Vec3, 4> corners{Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
  return corners;
}

/// An affine function p ↦ T + R·(S·p) as a 2×2×2 grid, with a color.
inline Function affineFunction(const std::string& name, Vec3 translate, Vec3 rotateDegrees, Vec3 scale, Vec3 color,
                               double colorSpeed = 0.5) {
  Function f;
  f.name = name;
  f.resolution = {2, 2, 2};
  f.placement.translate = translate;
  f.placement.rotate = rotateDegrees;
  f.placement.scale = scale;
  f.color = color;
  f.color_speed = colorSpeed;
  return f;
}

/// The Sierpinski tetrahedron: f_i(p) = p/2 + v_i/2 toward the corners v_i.
inline Project sierpinskiProject() {
  Project p;
  const Vec3 colors[4] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
  for (int i = 0; i < 4; ++i)
    p.functions.push_back(affineFunction("corner" + std::to_string(i), 0.5 * tetrahedronCorners()[std::size_t(i)],
                                         Vec3(0.0), Vec3(0.5), colors[i]));
  return p;
}

/// R = Rz·Ry·Rx (x first), angles in degrees, written out independently of core.
inline Vec3 rotateXyz(Vec3 q, Vec3 degrees) {
  const Vec3 a = degrees * (M_PI / 180.0);
  q = {q.x, std::cos(a.x) * q.y - std::sin(a.x) * q.z, std::sin(a.x) * q.y + std::cos(a.x) * q.z};
  q = {std::cos(a.y) * q.x + std::sin(a.y) * q.z, q.y, -std::sin(a.y) * q.x + std::cos(a.y) * q.z};
  q = {std::cos(a.z) * q.x - std::sin(a.z) * q.y, std::sin(a.z) * q.x + std::cos(a.z) * q.y, q.z};
  return q;
}

/// The analytic map of an affine function (valid where its argument lies in X).
inline Vec3 applyAffine(const Function& f, Vec3 p) {
  return f.placement.translate + rotateXyz(f.placement.scale * p, f.placement.rotate);
}

inline Vec3 toVec(const IfsMesh::Point& p) { return {p[0], p[1], p[2]}; }

/// Volume enclosed by a closed, outward-oriented mesh (divergence theorem over fan triangles).
inline double signedVolume(const IfsMesh& mesh) {
  double volume = 0.0;
  for (auto fh : mesh.faces()) {
    std::vector<Vec3> corners;
    for (auto vh : mesh.fv_range(fh)) corners.push_back(toVec(mesh.point(vh)));
    for (std::size_t i = 1; i + 1 < corners.size(); ++i)
      volume += glm::dot(corners[0], glm::cross(corners[i], corners[i + 1])) / 6.0;
  }
  return volume;
}

inline void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

/// A regular tetrahedron as an OFF file (4 triangles, closed, outward).
inline std::string tetrahedronOff() {
  return "OFF\n4 4 0\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n";
}

/// A square pyramid as an OBJ file (a quad and 4 triangles, closed).
inline std::string pyramidObj() {
  return "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv 0 0 1\n"
         "f 1 4 3 2\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n";
}

/// A fresh folder under the system temp dir, removed at scope exit.
struct TempFolder {
  std::filesystem::path path;
  explicit TempFolder(const std::string& name) {
    path = std::filesystem::temp_directory_path() / ("gridifs-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempFolder() { std::filesystem::remove_all(path); }
  std::filesystem::path operator/(const std::string& file) const { return path / file; }
};

}  // namespace gridifs::test_support
