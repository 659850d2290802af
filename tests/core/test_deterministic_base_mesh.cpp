// Base meshes A of the deterministic algorithm: built-in cube and sphere, files through OpenMesh,
// validation (empty, non-manifold, unreadable), subdivision and its predicted counts.
#include <gtest/gtest.h>

#include <cstring>

#include <algorithm>

#include "deterministic_samples.h"
#include "mesh/base_mesh.h"
#include "model_error_text.h"

using namespace gridifs;
using namespace gridifs::test_support;

namespace {

float maxAbsCoordinate(const IfsMesh& mesh) {
  float m = 0.0f;
  for (auto vh : mesh.vertices())
    for (int d = 0; d < 3; ++d) m = std::max(m, std::fabs(mesh.point(vh)[d]));
  return m;
}

bool closed(const IfsMesh& mesh) {
  for (auto vh : mesh.vertices())
    if (mesh.is_boundary(vh)) return false;
  return true;
}

std::string baseMeshErrorOf(const BaseMeshSpec& spec) {
  return test_support::modelErrorText([&] { loadCoarseBase(spec); });
}

BaseMeshSpec fileSpec(const std::filesystem::path& file, int subdivision = 0) {
  BaseMeshSpec spec;
  spec.shape = BaseShape::File;
  spec.file = file;
  spec.subdivision = subdivision;
  return spec;
}

}  // namespace

TEST(BaseMesh, CubeFillsXOutwardAndClosed) {
  const IfsMesh cube = makeCube();
  EXPECT_EQ(countMesh(cube), (MeshCounts{8, 12, 6, 24}));
  EXPECT_FLOAT_EQ(maxAbsCoordinate(cube), 1.0f);
  EXPECT_TRUE(closed(cube));
  EXPECT_NEAR(signedVolume(cube), 8.0, 1e-9);
}

TEST(BaseMesh, SphereIsOnTheUnitSphereAndOutward) {
  for (int s = 0; s <= 2; ++s) {
    BaseMeshSpec spec;
    spec.shape = BaseShape::Sphere;
    spec.subdivision = s;
    const IfsMesh sphere = refineBase(loadCoarseBase(spec), spec);
    EXPECT_EQ(countMesh(sphere), predictBaseCounts(loadCoarseBase(spec), spec));
    EXPECT_EQ(sphere.n_faces(), std::size_t(sphereSegments(s)) * std::size_t(sphereRings(s)));
    for (auto vh : sphere.vertices()) ASSERT_NEAR(glm::length(toVec(sphere.point(vh))), 1.0, 1e-6);
    EXPECT_TRUE(closed(sphere));
    const double volume = signedVolume(sphere);
    EXPECT_GT(volume, 0.9 * 4.0 / 3.0 * M_PI);
    EXPECT_LT(volume, 4.0 / 3.0 * M_PI);
  }
  EXPECT_THROW(makeUvSphere(2, 4), ModelError);
}

TEST(BaseMesh, FlatSubdivisionKeepsTheShape) {
  TempFolder folder("base-flat");
  writeFile(folder / "tetra.off", tetrahedronOff());
  for (int s = 1; s <= 3; ++s) {
    BaseMeshSpec cube;
    cube.subdivision = s;
    const IfsMesh refined = refineBase(loadCoarseBase(cube), cube);
    EXPECT_EQ(refined.n_faces(), 6u << (2 * s));  // quads: ×4 per level
    EXPECT_FLOAT_EQ(maxAbsCoordinate(refined), 1.0f);
    for (auto vh : refined.vertices()) {  // every vertex still on the cube's surface
      const auto& p = refined.point(vh);
      ASSERT_FLOAT_EQ(std::max({std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])}), 1.0f);
    }
    EXPECT_NEAR(signedVolume(refined), 8.0, 1e-5);

    const BaseMeshSpec tetra = fileSpec(folder / "tetra.off", s);
    const IfsMesh t = refineBase(loadCoarseBase(tetra), tetra);
    EXPECT_TRUE(allTriangles(t));  // Loop topology: 1 triangle → 4
    EXPECT_EQ(t.n_faces(), 4u << (2 * s));
    EXPECT_NEAR(signedVolume(t), 8.0 / 3.0, 1e-5);
    EXPECT_TRUE(closed(t));
  }
}

TEST(BaseMesh, SmoothSubdivisionRounds) {
  BaseMeshSpec spec;
  spec.subdivision = 2;
  spec.scheme = SubdivisionScheme::Smooth;
  const IfsMesh blob = refineBase(loadCoarseBase(spec), spec);
  spec.scheme = SubdivisionScheme::Flat;
  EXPECT_EQ(countMesh(blob), countMesh(refineBase(loadCoarseBase(spec), spec)));
  EXPECT_LT(signedVolume(blob), 7.0);  // Catmull-Clark pulls the corners in
  EXPECT_GT(signedVolume(blob), 2.0);
}

TEST(BaseMesh, PredictedCountsMatchEverySchemeAndTriangulation) {
  TempFolder folder("base-predict");
  writeFile(folder / "tetra.off", tetrahedronOff());
  writeFile(folder / "pyramid.obj", pyramidObj());
  std::vector<BaseMeshSpec> specs;
  for (int s = 0; s <= 3; ++s)
    for (bool triangulate : {false, true})
      for (auto scheme : {SubdivisionScheme::Flat, SubdivisionScheme::Smooth}) {
        BaseMeshSpec cube;
        cube.subdivision = s;
        cube.triangulate = triangulate;
        cube.scheme = scheme;
        specs.push_back(cube);
        BaseMeshSpec sphere = cube;
        sphere.shape = BaseShape::Sphere;
        if (s <= 2) specs.push_back(sphere);
        BaseMeshSpec tetra = fileSpec(folder / "tetra.off", s);
        tetra.triangulate = triangulate;
        tetra.scheme = scheme;
        specs.push_back(tetra);
        BaseMeshSpec pyramid = fileSpec(folder / "pyramid.obj", s);
        pyramid.triangulate = triangulate;
        pyramid.scheme = scheme;
        specs.push_back(pyramid);
      }
  for (const BaseMeshSpec& spec : specs) {
    const IfsMesh coarse = loadCoarseBase(spec);
    const MeshCounts predicted = predictBaseCounts(coarse, spec);
    const IfsMesh refined = refineBase(coarse, spec);
    EXPECT_EQ(predicted, countMesh(refined))
        << "shape " << int(spec.shape) << " S=" << spec.subdivision << " triangulate " << spec.triangulate;
    if (spec.triangulate) {
      EXPECT_TRUE(allTriangles(refined));
    }
    if (spec.shape != BaseShape::Sphere) {
      EXPECT_TRUE(closed(refined));
    }
  }
  BaseMeshSpec absurd;
  absurd.subdivision = kMaxSubdivision + 1;
  EXPECT_THROW(loadCoarseBase(absurd), ModelError);
  absurd.subdivision = -1;
  EXPECT_THROW(predictBaseCounts(makeCube(), absurd), ModelError);
  // The largest allowed level is predicted without overflow or allocation.
  absurd.subdivision = kMaxSubdivision;
  EXPECT_EQ(predictBaseCounts(makeCube(), absurd).faces, 6ull << (2 * kMaxSubdivision));
}

TEST(BaseMesh, FilesLoadInEveryFormat) {
  TempFolder folder("base-formats");
  writeFile(folder / "tetra.off", tetrahedronOff());
  writeFile(folder / "pyramid.obj", pyramidObj());
  writeFile(folder / "tri.ply",
            "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
            "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
            "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n");
  writeFile(folder / "tri.stl",
            "solid t\n"
            "facet normal 0 0 0\nouter loop\nvertex 1 1 1\nvertex 1 -1 -1\nvertex -1 1 -1\nendloop\nendfacet\n"
            "facet normal 0 0 0\nouter loop\nvertex 1 1 1\nvertex -1 -1 1\nvertex 1 -1 -1\nendloop\nendfacet\n"
            "facet normal 0 0 0\nouter loop\nvertex 1 1 1\nvertex -1 1 -1\nvertex -1 -1 1\nendloop\nendfacet\n"
            "facet normal 0 0 0\nouter loop\nvertex 1 -1 -1\nvertex -1 -1 1\nvertex -1 1 -1\nendloop\nendfacet\n"
            "endsolid t\n");
  for (const char* name : {"tetra.off", "tri.ply", "tri.stl"}) {
    const IfsMesh mesh = loadCoarseBase(fileSpec(folder / name));
    EXPECT_EQ(countMesh(mesh), (MeshCounts{4, 6, 4, 12})) << name;  // STL vertices are welded
    EXPECT_NEAR(signedVolume(mesh), 8.0 / 3.0, 1e-6) << name;
    EXPECT_FALSE(mesh.has_vertex_status());
  }
  EXPECT_EQ(countMesh(loadCoarseBase(fileSpec(folder / "pyramid.obj"))), (MeshCounts{5, 8, 5, 16}));
}

TEST(BaseMesh, BadFilesAreRefusedNamingTheFile) {
  TempFolder folder("base-bad");
  const auto path = [&](const char* name) { return (folder / name).string(); };
  writeFile(folder / "empty.obj", "");
  writeFile(folder / "points.ply",
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
            "end_header\n0 0 0\n1 0 0\n0 1 0\n");
  writeFile(folder / "vertices_only.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  // Three triangles on one edge: no 2-manifold can hold them.
  writeFile(folder / "fin.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n");
  // Two triangles touching at one vertex (a bow tie).
  writeFile(folder / "bowtie.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\nf 1 2 3\nf 1 4 5\n");
  writeFile(folder / "truncated.ply",
            "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n\x01\x02");
  writeFile(folder / "notes.txt", "hello");
  writeFile(folder / "hostile.off", "OFF\n900000000 900000000 0\n0 0 0\n");  // declares far more than it holds
  writeFile(folder / "hostile.ply",
            "ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\n"
            "property float y\nproperty float z\nelement face 1\n"
            "property list uchar int vertex_indices\nend_header\n0 0 0\n");
  {
    std::string stl(84, '\0');  // binary STL: 80-byte header, then the triangle count
    const std::uint32_t triangles = 2'000'000'000u;
    std::memcpy(stl.data() + 80, &triangles, 4);
    writeFile(folder / "hostile.stl", stl);
  }
  std::filesystem::create_directories(folder / "folder.obj");

  struct Case {
    const char* name;
    const char* expect;
  };
  for (const Case c :
       {Case{"missing.obj", "cannot read"}, Case{"empty.obj", "empty"}, Case{"points.ply", "no faces"},
        Case{"vertices_only.obj", "no faces"}, Case{"fin.obj", "not a manifold"}, Case{"bowtie.obj", "not a manifold"},
        Case{"truncated.ply", ""}, Case{"hostile.off", "header declares"}, Case{"hostile.ply", "header declares"},
        Case{"hostile.stl", "header declares"}, Case{"notes.txt", "not a mesh file"}, Case{"folder.obj", "folder"}}) {
    const std::string message = baseMeshErrorOf(fileSpec(path(c.name)));
    EXPECT_NE(message.find(path(c.name)), std::string::npos) << c.name << ": " << message;
    EXPECT_NE(message.find(c.expect), std::string::npos) << c.name << ": " << message;
  }
  EXPECT_EQ(baseMeshErrorOf(fileSpec("")), "base: no base mesh file given");
}

TEST(BaseMesh, FitScalesIntoTheCubeAndLooseVerticesGo) {
  TempFolder folder("base-fit");
  // A tetrahedron far from X, plus an unused vertex.
  writeFile(folder / "far.off",
            "OFF\n5 4 0\n11 11 11\n11 9 9\n9 11 9\n9 9 11\n50 50 50\n"
            "3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n");
  BaseMeshSpec spec = fileSpec(folder / "far.off");
  EXPECT_EQ(loadCoarseBase(spec).n_vertices(), 4u);  // the loose vertex is dropped
  EXPECT_GT(maxAbsCoordinate(loadCoarseBase(spec)), 8.0f);
  spec.fitToCube = true;
  const IfsMesh fitted = loadCoarseBase(spec);
  EXPECT_FLOAT_EQ(maxAbsCoordinate(fitted), 1.0f);
  EXPECT_NEAR(signedVolume(fitted), 8.0 / 3.0, 1e-5);  // the tetrahedron's box is 2×2×2 → scale 1
}
