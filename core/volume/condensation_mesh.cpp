#include "volume/condensation_mesh.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "mesh/base_mesh.h"
#include "mesh/mesh_io.h"
#include "model/stack_evaluator.h"
#include "schema/validation.h"
#include "volume/set_voxelizer.h"
#include "volume/vdb_io.h"
#include "volume/voxel_set_mesh.h"

namespace gridifs {
namespace {

IfsMesh::Point toPoint(const Vec3& p) { return IfsMesh::Point(float(p.x), float(p.y), float(p.z)); }

IfsMesh sphereMesh(const CondensationSet& set) {
  IfsMesh mesh = makeUvSphere(kSphereSegments, kSphereRings);
  for (auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    mesh.point(v) = toPoint(set.center + set.radius * Vec3{p[0], p[1], p[2]});
  }
  return mesh;
}

IfsMesh boxMesh(const CondensationSet& set) {
  IfsMesh mesh;
  IfsMesh::VertexHandle corner[8];
  for (int c = 0; c < 8; ++c) {
    const Vec3 sign{(c & 1) ? 1.0 : -1.0, (c & 2) ? 1.0 : -1.0, (c & 4) ? 1.0 : -1.0};
    corner[c] = mesh.add_vertex(toPoint(set.center + 0.5 * set.size * sign));
  }
  // Each side as two triangles, counter-clockwise seen from outside.
  const int sides[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& s : sides) {
    mesh.add_face(corner[s[0]], corner[s[1]], corner[s[2]]);
    mesh.add_face(corner[s[0]], corner[s[2]], corner[s[3]]);
  }
  return mesh;
}

IfsMesh torusMesh(const CondensationSet& set) {
  // An orthonormal frame (u, w, a) around the axis a.
  const Vec3 a = glm::normalize(set.axis);
  const Vec3 helper = std::abs(a.x) < 0.9 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
  const Vec3 u = glm::normalize(glm::cross(helper, a)), w = glm::cross(a, u);
  IfsMesh mesh;
  const int M = kTorusMajorSegments, m = kTorusMinorSegments;
  std::vector<IfsMesh::VertexHandle> vs(std::size_t(M * m));
  for (int i = 0; i < M; ++i) {
    const double phi = 2.0 * M_PI * i / M;
    const Vec3 radial = std::cos(phi) * u + std::sin(phi) * w;
    for (int j = 0; j < m; ++j) {
      const double theta = 2.0 * M_PI * j / m;
      const Vec3 p = set.center + (set.major + set.minor * std::cos(theta)) * radial + set.minor * std::sin(theta) * a;
      vs[std::size_t(i * m + j)] = mesh.add_vertex(toPoint(p));
    }
  }
  auto at = [&](int i, int j) { return vs[std::size_t((i % M) * m + (j % m))]; };
  // (φ, θ) → p has ∂p/∂φ × ∂p/∂θ pointing away from the tube's centre line: outward.
  for (int i = 0; i < M; ++i)
    for (int j = 0; j < m; ++j) mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  return mesh;
}

IfsMesh fileMesh(const CondensationSet& set, const std::filesystem::path& file, const std::string& jsonPath) {
  IfsMesh mesh;
  try {
    mesh = readMeshFile(file);
  } catch (const ModelError& e) {
    throw ModelError(jsonPath + ".mesh", e.message());
  }
  if (mesh.n_faces() == 0) throw ModelError(jsonPath + ".mesh", "the mesh " + file.string() + " has no faces");
  for (auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    const Vec3 q = applyPlacement(set.placement, Vec3{p[0], p[1], p[2]});
    if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z))
      throw ModelError(jsonPath + ".mesh", "the mesh " + file.string() + " has a vertex that is not finite");
    mesh.point(v) = toPoint(q);
  }
  return mesh;
}

IfsMesh vdbMesh(const CondensationSet& set, const std::filesystem::path& file, const std::string& jsonPath) {
  const vdb_io::FaceLists faces = vdb_io::gridIsoSurface(file, set.grid, float(set.threshold), jsonPath);
  const auto& points = faces.points;
  const auto& triangles = faces.triangles;
  const auto& quads = faces.quads;
  if (triangles.empty() && quads.empty())
    throw ModelError(jsonPath + ".threshold", "the grid \"" + set.grid + "\" of " + file.string() +
                                                  " has no iso-surface at the threshold " +
                                                  std::to_string(set.threshold));
  IfsMesh mesh;
  std::vector<IfsMesh::VertexHandle> vs;
  vs.reserve(points.size() / 3);
  for (std::size_t p = 0; p + 2 < points.size(); p += 3)
    vs.push_back(mesh.add_vertex(IfsMesh::Point(points[p], points[p + 1], points[p + 2])));
  // volumeToMesh orients faces for a level set (inside below the iso-value); the set is the
  // region at or above the threshold, so the winding is reversed to face out of it.
  for (std::size_t q = 0; q + 3 < quads.size(); q += 4)
    mesh.add_face(vs[quads[q + 3]], vs[quads[q + 2]], vs[quads[q + 1]], vs[quads[q]]);
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3)
    mesh.add_face(vs[triangles[t + 2]], vs[triangles[t + 1]], vs[triangles[t]]);
  return mesh;
}

}  // namespace

IfsMesh condensationSetMesh(const CondensationSet& set, const std::filesystem::path& projectFolder,
                            const std::string& jsonPath) {
  checkCondensationSet(set, jsonPath);
  switch (set.shape) {
    case SetShape::Sphere:
      return sphereMesh(set);
    case SetShape::Box:
      return boxMesh(set);
    case SetShape::Torus:
      return torusMesh(set);
    case SetShape::Mesh:
      return fileMesh(set, projectFolder / set.path, jsonPath);
    case SetShape::Vdb:
      return vdbMesh(set, projectFolder / set.path, jsonPath);
    case SetShape::Image:
      return voxelSetMesh(voxelizeSet(set, VoxelLattice{kImageMeshResolution}, projectFolder, jsonPath));
  }
  return sphereMesh(set);
}

void loadCondensationMeshes(DeterministicIfs& ifs, const Project& project, const std::filesystem::path& projectFolder) {
  for (DeterministicCondensation& c : ifs.condensations) {
    const std::string path = "functions[" + std::to_string(c.functionIndex) + "].set";
    c.mesh = std::make_shared<const IfsMesh>(
        condensationSetMesh(project.functions[c.functionIndex].set, projectFolder, path));
  }
}

}  // namespace gridifs
