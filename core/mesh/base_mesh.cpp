#include "mesh/base_mesh.h"

#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "base/types.h"
#include "mesh/mesh_io.h"

namespace gridifs {
namespace {

constexpr std::uint64_t kSaturated = std::numeric_limits<std::uint64_t>::max();

// Counts can be asked for absurd levels; saturate instead of wrapping around.
std::uint64_t add(std::uint64_t a, std::uint64_t b) { return a > kSaturated - b ? kSaturated : a + b; }
std::uint64_t mul(std::uint64_t a, std::uint64_t b) { return a != 0 && b > kSaturated / a ? kSaturated : a * b; }

void checkSubdivision(const BaseMeshSpec& spec) {
  if (spec.subdivision < 0 || spec.subdivision > kMaxSubdivision)
    throw ModelError("subdivision", "the subdivision level must be between 0 and " + std::to_string(kMaxSubdivision) +
                                        ", not " + std::to_string(spec.subdivision));
}

MeshCounts sphereCounts(int subdivision) {
  const std::uint64_t seg = std::uint64_t(sphereSegments(subdivision));
  const std::uint64_t rings = std::uint64_t(sphereRings(subdivision));
  MeshCounts c;
  c.vertices = 2 + (rings - 1) * seg;
  c.edges = seg * rings + seg * (rings - 1);  // meridian pieces + parallels
  c.faces = seg * rings;
  c.corners = 2 * 3 * seg + 4 * seg * (rings - 2);
  return c;
}

// Fan triangulation of every n-gon adds n − 3 edges and makes n − 2 triangles.
MeshCounts triangulatedCounts(const MeshCounts& c) {
  MeshCounts t;
  t.vertices = c.vertices;
  t.faces = c.corners - 2 * c.faces;
  t.edges = add(c.edges, c.corners - 3 * c.faces);
  t.corners = mul(3, t.faces);
  return t;
}

void fitIntoCube(IfsMesh& mesh) {
  OpenMesh::Vec3f lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (auto vh : mesh.vertices()) {
    lo.minimize(mesh.point(vh));
    hi.maximize(mesh.point(vh));
  }
  const OpenMesh::Vec3f center = (lo + hi) * 0.5f;
  const float half = (hi - lo).max() * 0.5f;
  if (!(half > 0.0f)) return;  // a single point: nothing sensible to scale
  for (auto vh : mesh.vertices()) mesh.set_point(vh, (mesh.point(vh) - center) / half);
}

// Checks a file's mesh and removes what the deterministic algorithm must not see.
void validateFileMesh(IfsMesh& mesh, const std::string& name) {
  if (mesh.n_faces() == 0) throw ModelError("", name + " has no faces (an empty mesh or a point cloud)");
  std::size_t splitFaces = 0;
  for (auto fh : mesh.faces())
    if (mesh.status(fh).fixed_nonmanifold()) ++splitFaces;
  std::size_t badVertices = 0;
  for (auto vh : mesh.vertices())
    if (!mesh.is_isolated(vh) && !mesh.is_manifold(vh)) ++badVertices;
  if (splitFaces > 0 || badVertices > 0)
    throw ModelError(
        "", name + " is not a manifold mesh (" +
                (splitFaces > 0 ? std::to_string(splitFaces) + " face" + (splitFaces == 1 ? "" : "s") +
                                      " on edges shared by more than two faces or at pinched vertices"
                                : std::to_string(badVertices) + " pinched vertex" + (badVertices == 1 ? "" : "es")) +
                "); repair it first, e.g. in MeshLab or Blender");
  for (auto vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw ModelError("", name + " has a vertex with a non-finite coordinate");
  }
  // Loose points are not part of any surface; they would only be transformed and written.
  mesh.delete_isolated_vertices();
  mesh.garbage_collection();
  mesh.release_face_status();
  mesh.release_edge_status();
  mesh.release_vertex_status();
}

}  // namespace

MeshCounts countMesh(const IfsMesh& mesh) {
  MeshCounts c;
  c.vertices = mesh.n_vertices();
  c.edges = mesh.n_edges();
  c.faces = mesh.n_faces();
  for (auto fh : mesh.faces()) c.corners += mesh.valence(fh);
  return c;
}

bool allTriangles(const IfsMesh& mesh) {
  for (auto fh : mesh.faces())
    if (mesh.valence(fh) != 3) return false;
  return true;
}

IfsMesh makeCube() {
  IfsMesh mesh;
  mesh.reserve(8, 12, 6);
  std::vector<IfsMesh::VertexHandle> v;
  // Vertex i has x = ±1 from bit 0, y from bit 1, z from bit 2.
  for (int i = 0; i < 8; ++i)
    v.push_back(mesh.add_vertex(IfsMesh::Point(i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f)));
  // Counter-clockwise seen from outside: -x, +x, -y, +y, -z, +z.
  const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : faces) mesh.add_face(v[f[0]], v[f[1]], v[f[2]], v[f[3]]);
  return mesh;
}

int sphereSegments(int subdivision) { return 16 << std::clamp(subdivision, 0, kMaxSubdivision); }
int sphereRings(int subdivision) { return 8 << std::clamp(subdivision, 0, kMaxSubdivision); }

IfsMesh makeUvSphere(int segments, int rings) {
  if (segments < 3 || rings < 2) throw ModelError("", "a UV sphere needs at least 3 segments and 2 rings");
  IfsMesh mesh;
  const std::size_t seg = std::size_t(segments);
  const std::size_t n = 2 + std::size_t(rings - 1) * seg;
  mesh.reserve(n, seg * std::size_t(2 * rings - 1), seg * std::size_t(rings));
  const auto north = mesh.add_vertex(IfsMesh::Point(0.0f, 0.0f, 1.0f));
  std::vector<IfsMesh::VertexHandle> ring(std::size_t(rings - 1) * seg);
  for (int r = 1; r < rings; ++r) {
    const double theta = M_PI * r / rings;
    for (int j = 0; j < segments; ++j) {
      const double phi = 2.0 * M_PI * j / segments;
      ring[std::size_t(r - 1) * seg + std::size_t(j)] = mesh.add_vertex(IfsMesh::Point(
          float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta))));
    }
  }
  const auto south = mesh.add_vertex(IfsMesh::Point(0.0f, 0.0f, -1.0f));
  auto at = [&](int r, int j) { return ring[std::size_t(r - 1) * seg + std::size_t(j % segments)]; };
  // Counter-clockwise seen from outside (φ grows from x toward y, θ from the north pole).
  for (int j = 0; j < segments; ++j) mesh.add_face(north, at(1, j), at(1, j + 1));
  for (int r = 1; r + 1 < rings; ++r)
    for (int j = 0; j < segments; ++j) mesh.add_face(at(r, j), at(r + 1, j), at(r + 1, j + 1), at(r, j + 1));
  for (int j = 0; j < segments; ++j) mesh.add_face(south, at(rings - 1, j + 1), at(rings - 1, j));
  return mesh;
}

IfsMesh loadCoarseBase(const BaseMeshSpec& spec) {
  checkSubdivision(spec);
  switch (spec.shape) {
    case BaseShape::Cube:
      return makeCube();
    case BaseShape::Sphere:
      return makeUvSphere(sphereSegments(0), sphereRings(0));
    case BaseShape::File:
      break;
  }
  if (spec.file.empty()) throw ModelError("base", "no base mesh file given");
  IfsMesh mesh = readMeshFile(spec.file);  // throws ModelError naming the file
  validateFileMesh(mesh, spec.file.string());
  if (spec.fitToCube) fitIntoCube(mesh);
  return mesh;
}

MeshCounts predictBaseCounts(const IfsMesh& coarse, const BaseMeshSpec& spec) {
  checkSubdivision(spec);
  MeshCounts c;
  if (spec.shape == BaseShape::Sphere) {
    c = sphereCounts(spec.subdivision);
  } else {
    c = countMesh(coarse);
    const bool loop = allTriangles(coarse);
    for (int level = 0; level < spec.subdivision; ++level) {
      MeshCounts next;
      if (loop) {  // every edge gains a midpoint, every triangle becomes 4
        next.vertices = add(c.vertices, c.edges);
        next.edges = add(mul(2, c.edges), mul(3, c.faces));
        next.faces = mul(4, c.faces);
        next.corners = mul(3, next.faces);
      } else {  // Catmull-Clark topology: a centroid per face, a midpoint per edge, n-gon → n quads
        next.vertices = add(add(c.vertices, c.edges), c.faces);
        next.edges = add(mul(2, c.edges), c.corners);
        next.faces = c.corners;
        next.corners = mul(4, c.corners);
      }
      c = next;
    }
  }
  return spec.triangulate ? triangulatedCounts(c) : c;
}

IfsMesh refineBase(IfsMesh coarse, const BaseMeshSpec& spec) {
  checkSubdivision(spec);
  // Regenerating keeps every vertex on the sphere; subdividing a polyhedron would not.
  IfsMesh mesh = spec.shape == BaseShape::Sphere && spec.subdivision > 0
                     ? makeUvSphere(sphereSegments(spec.subdivision), sphereRings(spec.subdivision))
                     : std::move(coarse);
  if (spec.shape != BaseShape::Sphere) {
    if (spec.subdivision > 0) {
      const bool smooth = spec.scheme == SubdivisionScheme::Smooth;
      // Without smoothing (update_points = false) both subdividers only split: new points sit
      // at edge midpoints (Loop, Catmull-Clark) and face centroids (Catmull-Clark).
      if (allTriangles(mesh)) {
        OpenMesh::Subdivider::Uniform::LoopT<IfsMesh, float> loop;
        loop(mesh, std::size_t(spec.subdivision), smooth);
      } else {
        OpenMesh::Subdivider::Uniform::CatmullClarkT<IfsMesh, float> catmullClark;
        catmullClark(mesh, std::size_t(spec.subdivision), smooth);
      }
    }
  }
  if (spec.triangulate && !allTriangles(mesh)) mesh.triangulate();
  return mesh;
}

BaseMeshSpec baseMeshSpec(BaseShape shape, const std::filesystem::path& file, int subdivision, bool smooth,
                          bool fitToCube, std::optional<MeshFormat> outputFormat) {
  BaseMeshSpec spec;
  spec.shape = shape;
  if (shape == BaseShape::File) spec.file = file;
  spec.subdivision = subdivision;
  spec.scheme = smooth ? SubdivisionScheme::Smooth : SubdivisionScheme::Flat;
  spec.triangulate = outputFormat && formatNeedsTriangles(*outputFormat);
  spec.fitToCube = fitToCube;
  return spec;
}

}  // namespace gridifs
