#pragma once
// The initial shape A of the deterministic algorithm F^n(A) (Gröller & Wegenkittl 1994, §3.2): a built-in cube or
// UV sphere, or a mesh file read with OpenMesh, optionally refined so that the nonlinear
// functions bend its long edges smoothly.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "mesh/ifs_mesh.h"
#include "mesh/mesh_io.h"

namespace gridifs {

enum class BaseShape { Cube, Sphere, File };

/// How subdivision refines a mesh file or the cube (the sphere is instead generated finer).
enum class SubdivisionScheme {
  /// Shape-preserving: new vertices at edge midpoints and face centroids, old vertices stay.
  /// Triangle meshes: OpenMesh's Loop topology (1 triangle → 4) without smoothing; other
  /// meshes: Catmull-Clark topology (n-gon → n quads) without smoothing.
  Flat,
  /// The same OpenMesh subdividers with their smoothing rules (rounds corners: a cube becomes
  /// a blob). For low-poly files meant to be smooth.
  Smooth,
};

inline constexpr int kMaxSubdivision = 10;

struct BaseMeshSpec {
  BaseShape shape = BaseShape::Cube;
  std::filesystem::path file;  // for BaseShape::File
  int subdivision = 0;         // levels, 0..kMaxSubdivision; each level multiplies faces by about 4
  SubdivisionScheme scheme = SubdivisionScheme::Flat;
  bool triangulate = false;  // fan-triangulate after subdividing (STL output needs triangles)
  bool fitToCube = false;    // scale and center a file's mesh uniformly into X = [-1, 1]^3
};

/// The spec the CLI and the export dialog build from their options: `file` is used for
/// BaseShape::File; the mesh is triangulated when the output format needs triangles (STL).
BaseMeshSpec baseMeshSpec(BaseShape shape, const std::filesystem::path& file, int subdivision, bool smooth,
                          bool fitToCube, std::optional<MeshFormat> outputFormat);

/// Element counts; corners = Σ over faces of the face's valence (halfedges inside faces).
struct MeshCounts {
  std::uint64_t vertices = 0, edges = 0, faces = 0, corners = 0;
  bool operator==(const MeshCounts&) const = default;
};

MeshCounts countMesh(const IfsMesh& mesh);

/// The cube filling X = [-1, 1]^3: 8 vertices, 6 outward-oriented quads.
IfsMesh makeCube();
/// A UV sphere of radius 1 around the origin, poles on ±z: `segments` around, `rings` from pole
/// to pole (triangle fans at the poles, quads elsewhere), outward oriented. Needs segments ≥ 3,
/// rings ≥ 2 (throws ModelError otherwise).
IfsMesh makeUvSphere(int segments, int rings);
/// Segments and rings of the built-in sphere at a subdivision level: 16·2^S and 8·2^S.
int sphereSegments(int subdivision);
int sphereRings(int subdivision);

/// The unrefined base: the cube, the level-0 sphere or the file's mesh, validated (at least one
/// face, manifold, finite coordinates), isolated vertices removed, fitted into X when asked.
/// Throws ModelError with one sentence naming the file (unreadable, empty, non-manifold, ...) or
/// the bad field (subdivision outside 0..kMaxSubdivision). Thread-safe for distinct specs.
IfsMesh loadCoarseBase(const BaseMeshSpec& spec);

/// The exact counts refineBase(coarse, spec) will have, computed without building it (so an
/// absurd subdivision level can be refused before it allocates anything). Pure; throws
/// ModelError for a subdivision level outside 0..kMaxSubdivision.
MeshCounts predictBaseCounts(const IfsMesh& coarse, const BaseMeshSpec& spec);

/// Subdivides (OpenMesh's Loop or Catmull-Clark subdivider, see SubdivisionScheme) or, for the
/// sphere, regenerates it at the level's resolution, then triangulates if asked. The result has
/// contiguous handles (no deleted elements) and no status properties. Thread-safe for distinct
/// meshes; throws ModelError like predictBaseCounts.
IfsMesh refineBase(IfsMesh coarse, const BaseMeshSpec& spec);

/// Whether every face of `mesh` is a triangle.
bool allTriangles(const IfsMesh& mesh);

}  // namespace gridifs
