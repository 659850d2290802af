#include "volume/set_voxelizer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "base/errors.h"
#include "mesh/mesh_io.h"
#include "model/stack_evaluator.h"
#include "render/image_file.h"
#include "schema/validation.h"
#include "volume/vdb_io.h"

namespace gridifs {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw ModelError(path, message); }

/// Voxels of the primitive: only the lattice box around it is visited.
std::vector<std::uint32_t> primitiveVoxels(const CondensationSet& set, const VoxelLattice& lattice) {
  const Vec3 half = primitiveHalfExtent(set);
  Index3 lo, hi;
  for (int d = 0; d < 3; ++d) {
    lo[d] = std::max(0, int(std::floor(lattice.toLattice(set.center[d] - half[d]))));
    hi[d] = std::min(lattice.n - 1, int(std::ceil(lattice.toLattice(set.center[d] + half[d]))));
  }
  std::vector<std::uint32_t> out;
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i)
        if (primitiveContains(set, lattice.centre(i, j, k))) out.push_back(lattice.index(i, j, k));
  return out;
}

std::vector<std::uint32_t> meshVoxels(const CondensationSet& set, const VoxelLattice& lattice,
                                      const std::filesystem::path& file, const std::string& jsonPath) {
  IfsMesh mesh;
  try {
    mesh = readMeshFile(file);
  } catch (const ModelError& e) {
    fail(jsonPath + ".mesh", e.message());
  }
  if (mesh.n_faces() == 0) fail(jsonPath + ".mesh", "the mesh " + file.string() + " has no faces");
  vdb_io::FaceLists faces;
  faces.points.reserve(3 * mesh.n_vertices());
  for (auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    const Vec3 q = applyPlacement(set.placement, Vec3{p[0], p[1], p[2]});
    faces.points.insert(faces.points.end(), {float(q.x), float(q.y), float(q.z)});
  }
  bool closed = true;
  for (auto f : mesh.faces()) {
    std::vector<std::uint32_t> ids;
    for (auto v : mesh.fv_range(f)) ids.push_back(std::uint32_t(v.idx()));
    if (ids.size() == 4)
      faces.quads.insert(faces.quads.end(), ids.begin(), ids.end());
    else
      for (std::size_t t = 1; t + 1 < ids.size(); ++t)
        faces.triangles.insert(faces.triangles.end(), {ids[0], ids[t], ids[t + 1]});
  }
  for (auto h : mesh.halfedges()) closed &= !mesh.is_boundary(h);
  const bool solid = set.fill == SetFill::Solid;
  if (solid && !closed)
    fail(jsonPath + ".fill",
         "the mesh " + file.string() +
             " is not closed (it has boundary edges), so it has no inside; use \"fill\": \"surface\"");
  // Solid: the voxels inside the mesh's level set; surface: the voxels whose centre is within
  // half a voxel diagonal of the surface.
  const float halfDiagonal = float(0.5 * std::sqrt(3.0) * lattice.voxelSize());
  return vdb_io::meshVoxels(faces, lattice, solid, halfDiagonal, jsonPath);
}

std::vector<std::uint32_t> vdbVoxels(const CondensationSet& set, const VoxelLattice& lattice,
                                     const std::filesystem::path& file, const std::string& jsonPath) {
  return vdb_io::gridVoxels(file, set.grid, lattice, float(set.threshold), jsonPath);
}

/// A drawing as a set (Sokolov & Gentil draw their condensation sets in 2D, §3.2 and figures 6–12):
/// the image fitted into [-1, 1]² keeping its aspect ratio, a slab of the set's thickness about
/// z = 0, placed like a mesh; a voxel belongs to the set when its centre, taken back through the
/// placement, lies in the slab over a pixel darker than the threshold (lighter when inverted).
std::vector<std::uint32_t> imageVoxels(const CondensationSet& set, const VoxelLattice& lattice,
                                       const std::filesystem::path& file, const std::string& jsonPath) {
  GreyImage image;
  try {
    image = readGreyImage(file);
  } catch (const IoError& e) {
    fail(jsonPath + ".image", e.what());
  }
  const Vec3 origin = applyPlacement(set.placement, Vec3{0.0});
  glm::dmat3 forward;
  for (int d = 0; d < 3; ++d) {
    Vec3 e{0.0};
    e[d] = 1.0;
    forward[d] = applyPlacement(set.placement, e) - origin;
  }
  const glm::dmat3 back = glm::inverse(forward);
  const double scale = 2.0 / std::max(image.width, image.height);  // X units per pixel
  // At least half a voxel either side of z = 0, so that a drawing thinner than the lattice (the
  // editor's 32³ outline of a 0.05 slab) still has its two middle layers instead of none.
  const double halfW = 0.5 * image.width * scale, halfH = 0.5 * image.height * scale,
               halfT = std::max(0.5 * set.thickness, 0.5 * lattice.voxelSize());
  Index3 lo{lattice.n - 1, lattice.n - 1, lattice.n - 1}, hi{0, 0, 0};
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 q{(corner & 1) ? halfW : -halfW, (corner & 2) ? halfH : -halfH, (corner & 4) ? halfT : -halfT};
    const Vec3 p = origin + forward * q;
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], std::max(0, int(std::floor(lattice.toLattice(p[d])))));
      hi[d] = std::max(hi[d], std::min(lattice.n - 1, int(std::ceil(lattice.toLattice(p[d])))));
    }
  }
  std::vector<std::uint32_t> out;
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) {
        const Vec3 q = back * (lattice.centre(i, j, k) - origin);
        if (!(std::abs(q.z) <= halfT)) continue;
        const double px = std::floor((q.x + halfW) / scale), py = std::floor((halfH - q.y) / scale);
        if (!(px >= 0.0 && px < image.width && py >= 0.0 && py < image.height)) continue;
        float grey = image.grey[std::size_t(py) * std::size_t(image.width) + std::size_t(px)];
        if (set.invert) grey = 1.0f - grey;
        if (grey < set.threshold) out.push_back(lattice.index(i, j, k));
      }
  return out;
}

}  // namespace

VoxelSet voxelizeSet(const CondensationSet& set, const VoxelLattice& lattice,
                     const std::filesystem::path& projectFolder, const std::string& jsonPath) {
  checkCondensationSet(set, jsonPath);
  VoxelSet out{lattice, {}};
  const std::filesystem::path file = projectFolder / set.path;
  switch (set.shape) {
    case SetShape::Sphere:
    case SetShape::Box:
    case SetShape::Torus:
      out.voxels = primitiveVoxels(set, lattice);
      break;
    case SetShape::Mesh:
      out.voxels = meshVoxels(set, lattice, file, jsonPath);
      break;
    case SetShape::Vdb:
      out.voxels = vdbVoxels(set, lattice, file, jsonPath);
      break;
    case SetShape::Image:
      out.voxels = imageVoxels(set, lattice, file, jsonPath);
      if (out.voxels.empty()) {
        char threshold[32];
        std::snprintf(threshold, sizeof threshold, "%g", set.threshold);
        fail(jsonPath + ".threshold", "the drawing " + file.string() + " has no pixel darker than the threshold " +
                                          threshold + (set.invert ? " once inverted" : "") +
                                          " inside X at resolution " + std::to_string(lattice.n));
      }
      break;
  }
  normalizeVoxels(out.voxels);
  if (out.voxels.empty())
    fail(jsonPath, std::string("the ") + setShapeName(set.shape) + " set has no voxel inside X at resolution " +
                       std::to_string(lattice.n) + " (it lies outside [-1, 1]³ or is thinner than a voxel)");
  return out;
}

}  // namespace gridifs
