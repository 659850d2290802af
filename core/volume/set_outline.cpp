#include "volume/set_outline.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <unordered_set>

#include "mesh/mesh_io.h"
#include "model/stack_evaluator.h"
#include "schema/validation.h"
#include "volume/set_voxelizer.h"

namespace gridifs {
namespace {

void segment(LineSegments& out, const Vec3& a, const Vec3& b) {
  out.push_back(a);
  out.push_back(b);
}

/// A circle about `centre` in the plane spanned by the unit vectors `u` and `v`.
void circle(LineSegments& out, const Vec3& centre, double radius, const Vec3& u, const Vec3& v, int segments) {
  auto at = [&](int s) {
    const double a = 2.0 * M_PI * double(s) / double(segments);
    return centre + radius * (std::cos(a) * u + std::sin(a) * v);
  };
  for (int s = 0; s < segments; ++s) segment(out, at(s), at(s + 1));
}

/// Two unit vectors that make a right-handed orthonormal frame with the unit vector `a`.
void perpendiculars(const Vec3& a, Vec3& u, Vec3& v) {
  const Vec3 helper = std::abs(a.x) < 0.9 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
  u = glm::normalize(glm::cross(a, helper));
  v = glm::cross(a, u);
}

/// Keeps every k-th segment of `all` so that at most `most` remain.
LineSegments thinned(LineSegments all, std::size_t most) {
  const std::size_t count = all.size() / 2;
  if (most == 0 || count <= most) return all;
  const std::size_t stride = (count + most - 1) / most;
  LineSegments out;
  out.reserve(2 * (count / stride + 1));
  for (std::size_t s = 0; s < count; s += stride) segment(out, all[2 * s], all[2 * s + 1]);
  return out;
}

}  // namespace

LineSegments primitiveOutline(const CondensationSet& set, int segmentsPerLoop) {
  LineSegments out;
  const int n = std::max(segmentsPerLoop, 3);
  const Vec3 ex{1.0, 0.0, 0.0}, ey{0.0, 1.0, 0.0}, ez{0.0, 0.0, 1.0};
  switch (set.shape) {
    case SetShape::Sphere:
      circle(out, set.center, set.radius, ex, ey, n);
      circle(out, set.center, set.radius, ey, ez, n);
      circle(out, set.center, set.radius, ez, ex, n);
      break;
    case SetShape::Box: {
      const Vec3 h = 0.5 * set.size;
      // Along each axis, the four edges at the corners of the other two axes' extent.
      for (int axis = 0; axis < 3; ++axis)
        for (int s1 = -1; s1 <= 1; s1 += 2)
          for (int s2 = -1; s2 <= 1; s2 += 2) {
            Vec3 a{0.0}, b{0.0};
            a[axis] = -h[axis];
            b[axis] = h[axis];
            const int d1 = (axis + 1) % 3, d2 = (axis + 2) % 3;
            a[d1] = b[d1] = s1 * h[d1];
            a[d2] = b[d2] = s2 * h[d2];
            segment(out, set.center + a, set.center + b);
          }
      break;
    }
    case SetShape::Torus: {
      const Vec3 a = glm::normalize(set.axis);
      Vec3 u, v;
      perpendiculars(a, u, v);
      circle(out, set.center, set.major + set.minor, u, v, n);
      circle(out, set.center, set.major - set.minor, u, v, n);
      circle(out, set.center + set.minor * a, set.major, u, v, n);
      circle(out, set.center - set.minor * a, set.major, u, v, n);
      constexpr int kTubeLoops = 8;
      for (int k = 0; k < kTubeLoops; ++k) {
        const double phi = 2.0 * M_PI * k / kTubeLoops;
        const Vec3 radial = std::cos(phi) * u + std::sin(phi) * v;
        circle(out, set.center + set.major * radial, set.minor, radial, a, std::max(n / 2, 8));
      }
      break;
    }
    case SetShape::Mesh:
    case SetShape::Vdb:
    case SetShape::Image:
      break;
  }
  return out;
}

LineSegments meshOutline(const IfsMesh& mesh, const Placement& placement, std::size_t maxSegments) {
  const std::size_t edges = mesh.n_edges();
  const std::size_t stride = maxSegments == 0 || edges <= maxSegments ? 1 : (edges + maxSegments - 1) / maxSegments;
  LineSegments out;
  out.reserve(2 * (edges / stride + 1));
  for (std::size_t e = 0; e < edges; e += stride) {
    const auto h = mesh.halfedge_handle(mesh.edge_handle(int(e)), 0);
    const auto& p = mesh.point(mesh.from_vertex_handle(h));
    const auto& q = mesh.point(mesh.to_vertex_handle(h));
    segment(out, applyPlacement(placement, Vec3{p[0], p[1], p[2]}), applyPlacement(placement, Vec3{q[0], q[1], q[2]}));
  }
  return out;
}

LineSegments voxelOutline(const VoxelSet& voxels, std::size_t maxSegments) {
  const VoxelLattice& lattice = voxels.lattice;
  const int n = lattice.n;
  std::vector<unsigned char> inside(lattice.voxelCount(), 0);
  for (std::uint32_t v : voxels.voxels)
    if (v < inside.size()) inside[v] = 1;
  auto in = [&](int i, int j, int k) {
    return i >= 0 && j >= 0 && k >= 0 && i < n && j < n && k < n && inside[lattice.index(i, j, k)];
  };
  // Lattice corners are (i, j, k) in 0..n; an edge is its lower corner and its axis.
  const std::uint64_t m = std::uint64_t(n) + 1;
  auto cornerId = [&](const Index3& c) {
    return std::uint64_t(c[0]) + m * (std::uint64_t(c[1]) + m * std::uint64_t(c[2]));
  };
  std::unordered_set<std::uint64_t> edges;
  std::vector<std::uint64_t> order;  // first-seen order, so the drawing is the same every time
  auto addEdge = [&](const Index3& lower, int axis) {
    const std::uint64_t id = cornerId(lower) * 3 + std::uint64_t(axis);
    if (edges.insert(id).second) order.push_back(id);
  };
  for (std::uint32_t v : voxels.voxels) {
    const Index3 c = lattice.coordinates(v);
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side <= 1; ++side) {
        Index3 nb = c;
        nb[axis] += side ? 1 : -1;
        if (in(nb[0], nb[1], nb[2])) continue;
        // The face on this side: its four edges run along the two other axes.
        const int d1 = (axis + 1) % 3, d2 = (axis + 2) % 3;
        Index3 base = c;
        base[axis] += side;
        for (int o = 0; o <= 1; ++o) {
          Index3 a = base;
          a[d2] += o;
          addEdge(a, d1);
          Index3 b = base;
          b[d1] += o;
          addEdge(b, d2);
        }
      }
  }
  LineSegments all;
  all.reserve(2 * order.size());
  const double size = lattice.voxelSize();
  for (std::uint64_t id : order) {
    const int axis = int(id % 3);
    std::uint64_t corner = id / 3;
    const Index3 c{int(corner % m), int((corner / m) % m), int(corner / (m * m))};
    const Vec3 a{-1.0 + size * c[0], -1.0 + size * c[1], -1.0 + size * c[2]};
    Vec3 b = a;
    b[axis] += size;
    segment(all, a, b);
  }
  return thinned(std::move(all), maxSegments);
}

LineSegments setOutline(const CondensationSet& set, const std::filesystem::path& projectFolder,
                        const std::string& jsonPath, int resolution, std::size_t maxSegments) {
  checkCondensationSet(set, jsonPath);
  switch (set.shape) {
    case SetShape::Sphere:
    case SetShape::Box:
    case SetShape::Torus:
      return primitiveOutline(set);
    case SetShape::Mesh: {
      // Voxelized first: the drawing of a mesh that the iteration cannot use would mislead.
      voxelizeSet(set, VoxelLattice{resolution}, projectFolder, jsonPath);
      return meshOutline(readMeshFile(projectFolder / set.path), set.placement, maxSegments);
    }
    case SetShape::Vdb:
    case SetShape::Image:
      return voxelOutline(voxelizeSet(set, VoxelLattice{resolution}, projectFolder, jsonPath), maxSegments);
  }
  return {};
}

}  // namespace gridifs
