#include "volume/set_voxelizer.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetUtil.h>
#include <openvdb/tools/MeshToVolume.h>

#include <algorithm>
#include <cmath>
#include <mutex>

#include "mesh/mesh_io.h"
#include "model/stack_evaluator.h"
#include "volume/vdb_support.h"

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

/// Adds the lattice voxels of the active values of `mask` (voxels and tiles) that `keep` accepts.
template <class Grid, class Keep>
void collectActive(const Grid& grid, const VoxelLattice& lattice, Keep keep, std::vector<std::uint32_t>& out) {
  const openvdb::CoordBBox box(openvdb::Coord(0), openvdb::Coord(lattice.n - 1));
  for (auto it = grid.cbeginValueOn(); it; ++it) {
    if (!keep(*it)) continue;
    openvdb::CoordBBox b = it.getBoundingBox();
    b.intersect(box);
    if (b.empty()) continue;
    for (int k = b.min().z(); k <= b.max().z(); ++k)
      for (int j = b.min().y(); j <= b.max().y(); ++j)
        for (int i = b.min().x(); i <= b.max().x(); ++i) out.push_back(lattice.index(i, j, k));
  }
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
  std::vector<openvdb::Vec3s> points;
  points.reserve(mesh.n_vertices());
  for (auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    const Vec3 q = applyPlacement(set.placement, Vec3{p[0], p[1], p[2]});
    points.emplace_back(float(q.x), float(q.y), float(q.z));
  }
  bool closed = true;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  for (auto f : mesh.faces()) {
    std::vector<unsigned> ids;
    for (auto v : mesh.fv_range(f)) ids.push_back(unsigned(v.idx()));
    if (ids.size() == 4)
      quads.emplace_back(ids[0], ids[1], ids[2], ids[3]);
    else
      for (std::size_t t = 1; t + 1 < ids.size(); ++t) triangles.emplace_back(ids[0], ids[t], ids[t + 1]);
  }
  for (auto h : mesh.halfedges()) closed &= !mesh.is_boundary(h);
  // Index (i, j, k) of the grid is voxel (i, j, k) of the lattice: voxel size 2/N, centre of
  // voxel 0 at −1 + 1/N.
  const openvdb::math::Transform::Ptr xform = latticeTransform(lattice);
  std::vector<std::uint32_t> out;
  if (set.fill == SetFill::Solid) {
    if (!closed)
      fail(jsonPath + ".fill",
           "the mesh " + file.string() +
               " is not closed (it has boundary edges), so it has no inside; use \"fill\": \"surface\"");
    const auto sdf = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*xform, points, triangles, quads, 2.0f);
    const auto interior = openvdb::tools::sdfInteriorMask(*sdf);
    collectActive(
        *interior, lattice, [](bool on) { return on; }, out);
  } else {
    const float halfDiagonal = float(0.5 * std::sqrt(3.0) * lattice.voxelSize());
    const auto udf =
        openvdb::tools::meshToUnsignedDistanceField<openvdb::FloatGrid>(*xform, points, triangles, quads, 2.0f);
    collectActive(
        *udf, lattice, [&](float d) { return d <= halfDiagonal; }, out);
  }
  return out;
}

std::vector<std::uint32_t> vdbVoxels(const CondensationSet& set, const VoxelLattice& lattice,
                                     const std::filesystem::path& file, const std::string& jsonPath) {
  const openvdb::FloatGrid::Ptr grid = readFloatGrid(file, set.grid, jsonPath);
  // Visit the source's active values at or above the threshold, and sample the grid at the
  // centres of the lattice voxels they cover.
  const openvdb::CoordBBox lattBox(openvdb::Coord(0), openvdb::Coord(lattice.n - 1));
  const auto latt = latticeTransform(lattice);
  openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> sampler(*grid);
  std::vector<std::uint32_t> out;
  const float threshold = float(set.threshold);
  for (auto it = grid->cbeginValueOn(); it; ++it) {
    const openvdb::CoordBBox b = it.getBoundingBox();
    const openvdb::BBoxd world =
        grid->transform().indexToWorld(openvdb::BBoxd(b.min().asVec3d() - 0.5, b.max().asVec3d() + 0.5));
    const openvdb::BBoxd idx = latt->worldToIndex(world);
    openvdb::CoordBBox cover(openvdb::Coord::floor(idx.min()), openvdb::Coord::ceil(idx.max()));
    cover.intersect(lattBox);
    if (cover.empty()) continue;
    for (int k = cover.min().z(); k <= cover.max().z(); ++k)
      for (int j = cover.min().y(); j <= cover.max().y(); ++j)
        for (int i = cover.min().x(); i <= cover.max().x(); ++i) {
          const Vec3 c = lattice.centre(i, j, k);
          if (sampler.wsSample(openvdb::Vec3d(c.x, c.y, c.z)) >= threshold) out.push_back(lattice.index(i, j, k));
        }
  }
  return out;
}

}  // namespace

VoxelSet voxelizeSet(const CondensationSet& set, const VoxelLattice& lattice,
                     const std::filesystem::path& projectFolder, const std::string& jsonPath) {
  initializeOpenVdb();
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
  }
  normalizeVoxels(out.voxels);
  if (out.voxels.empty())
    fail(jsonPath, std::string("the ") + setShapeName(set.shape) + " set has no voxel inside X at resolution " +
                       std::to_string(lattice.n) + " (it lies outside [-1, 1]³ or is thinner than a voxel)");
  return out;
}

}  // namespace gridifs
