// The deterministic algorithm with condensation (Barnsley's IFS with a constant map, Sokolov &
// Gentil, §3.1): A_n = C ∪ F(A_{n−1}) with C's surface mesh. Exact counts, the level-0 copy is
// C's mesh, copies of C at scale 2^-k under f(p) = p/2, colours and addresses, outward meshes of
// every set shape, refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "deterministic_samples.h"
#include "mesh/deterministic_ifs.h"
#include "volume/condensation_mesh.h"

using namespace gridifs;
using namespace gridifs::test_support;

namespace {

Function condensation(const std::string& name, const CondensationSet& set, Vec3 color) {
  Function f;
  f.name = name;
  f.kind = FunctionKind::Condensation;
  f.set = set;
  f.color = color;
  return f;
}

CondensationSet sphereSet(Vec3 center, double radius) {
  CondensationSet s;
  s.shape = SetShape::Sphere;
  s.center = center;
  s.radius = radius;
  return s;
}

DeterministicIfs loaded(const Project& project) {
  DeterministicIfs ifs = snapshotDeterministicIfs(project);
  loadCondensationMeshes(ifs, project, ".");
  return ifs;
}

DeterministicMesh build(const Project& project, int depth, const IfsMesh& base) {
  DeterministicOptions options;
  options.depth = depth;
  return buildDeterministicMesh(loaded(project), base, options);
}

// Two contractions and two condensation sets (a sphere and a box).
Project mixedProject() {
  Project p = sierpinskiProject();
  p.functions.resize(2);
  CondensationSet box;
  box.shape = SetShape::Box;
  box.center = {0.1, 0.2, -0.3};
  box.size = {0.4, 0.3, 0.2};
  p.functions.push_back(condensation("ball", sphereSet({0.2, 0.0, 0.1}, 0.3), {0, 1, 1}));
  p.functions.push_back(condensation("brick", box, {1, 0, 1}));
  return p;
}

}  // namespace

TEST(DeterministicCondensation, FaceCountsFollowTheRecursion) {
  const Project project = mixedProject();
  const DeterministicIfs ifs = loaded(project);
  ASSERT_EQ(ifs.maps.size(), 2u);
  ASSERT_EQ(ifs.condensations.size(), 2u);
  const IfsMesh cube = makeCube();
  const std::uint64_t C = ifs.condensations[0].mesh->n_faces() + ifs.condensations[1].mesh->n_faces();
  EXPECT_EQ(ifs.condensations[0].mesh->n_faces(), std::size_t(kSphereSegments * kSphereRings));
  EXPECT_EQ(ifs.condensations[1].mesh->n_faces(), 12u);
  std::uint64_t expected = cube.n_faces();  // |A_0|
  for (int n = 0; n <= 5; ++n) {
    SCOPED_TRACE(n);
    DeterministicOptions options;
    options.depth = n;
    const DeterministicPlan plan = planDeterministic(ifs, countMesh(cube), options);
    EXPECT_EQ(plan.total.faces, expected);
    const DeterministicMesh out = buildDeterministicMesh(ifs, cube, options);
    EXPECT_EQ(out.mesh.n_faces(), expected);
    EXPECT_EQ(plan.total, countMesh(out.mesh));
    expected = C + 2 * expected;  // |A_{n+1}| = |C| + N·|A_n|
  }
}

TEST(DeterministicCondensation, LevelZeroCopyIsTheSetsMesh) {
  const Project project = mixedProject();
  const IfsMesh cube = makeCube();
  const DeterministicMesh out = build(project, 1, cube);
  // A_1 = F(A_0) (2 cubes) then C_0 and C_1 untransformed.
  const IfsMesh sphere = condensationSetMesh(project.functions[2].set, ".", "set");
  const IfsMesh box = condensationSetMesh(project.functions[3].set, ".", "set");
  const std::size_t v0 = 2 * cube.n_vertices(), f0 = 2 * cube.n_faces();
  ASSERT_EQ(out.mesh.n_vertices(), v0 + sphere.n_vertices() + box.n_vertices());
  for (std::size_t v = 0; v < sphere.n_vertices(); ++v)
    EXPECT_EQ(out.mesh.point(IfsMesh::VertexHandle(int(v0 + v))), sphere.point(IfsMesh::VertexHandle(int(v))));
  for (std::size_t f = 0; f < sphere.n_faces(); ++f) {
    std::vector<int> a, b;
    for (auto vh : out.mesh.fv_range(IfsMesh::FaceHandle(int(f0 + f)))) a.push_back(vh.idx() - int(v0));
    for (auto vh : sphere.fv_range(IfsMesh::FaceHandle(int(f)))) b.push_back(vh.idx());
    EXPECT_EQ(a, b);
  }
  const std::size_t v1 = v0 + sphere.n_vertices();
  for (std::size_t v = 0; v < box.n_vertices(); ++v)
    EXPECT_EQ(out.mesh.point(IfsMesh::VertexHandle(int(v1 + v))), box.point(IfsMesh::VertexHandle(int(v))));
  // Colours: the set's own; addresses: a1 = the condensation digit (N + j), T = 4 digits.
  const auto address = addressProperty(out.mesh);
  ASSERT_TRUE(address.is_valid());
  EXPECT_EQ(out.functionIndices, (std::vector<std::size_t>{0, 1, 2, 3}));
  const auto c = out.mesh.color(IfsMesh::VertexHandle(int(v0)));
  EXPECT_FLOAT_EQ(c[0], 0.0f);
  EXPECT_FLOAT_EQ(c[1], 1.0f);
  EXPECT_FLOAT_EQ(c[2], 1.0f);
  EXPECT_EQ(decodeAddress(std::uint64_t(out.mesh.property(address, IfsMesh::FaceHandle(int(f0)))), 4, 1),
            (std::vector<int>{2}));
  EXPECT_EQ(
      decodeAddress(std::uint64_t(out.mesh.property(address, IfsMesh::FaceHandle(int(f0 + sphere.n_faces())))), 4, 1),
      (std::vector<int>{3}));
}

TEST(DeterministicCondensation, HalvingMapGivesCopiesAtScaleTwoToTheMinusK) {
  // f(p) = p/2 and C a ball of radius 0.8 around the origin: A_n holds f^k(C), k = 0 … n−1, balls
  // of radius 0.8·2^-k around the origin, and f^n(A_0).
  Project project;
  project.functions.push_back(affineFunction("half", Vec3(0.0), Vec3(0.0), Vec3(0.5), {1, 0, 0}, 0.5));
  project.functions.push_back(condensation("ball", sphereSet(Vec3(0.0), 0.8), {0, 0, 1}));
  const IfsMesh cube = makeCube();
  const int n = 6;
  const DeterministicMesh out = build(project, n, cube);
  const std::size_t V = std::size_t(kSphereSegments * (kSphereRings - 1) + 2);
  ASSERT_EQ(out.mesh.n_vertices(), cube.n_vertices() + n * V);
  const auto address = addressProperty(out.mesh);
  for (int k = 0; k < n; ++k) {
    SCOPED_TRACE(k);
    const std::size_t first = cube.n_vertices() + std::size_t(k) * V;
    double lo = 1e9, hi = 0.0;
    for (std::size_t v = first; v < first + V; ++v) {
      const auto& p = out.mesh.point(IfsMesh::VertexHandle(int(v)));
      const double r = std::sqrt(double(p[0]) * p[0] + double(p[1]) * p[1] + double(p[2]) * p[2]);
      lo = std::min(lo, r);
      hi = std::max(hi, r);
    }
    const double radius = 0.8 * std::pow(0.5, k);
    EXPECT_NEAR(lo, radius, 1e-6);
    EXPECT_NEAR(hi, radius, 1e-6);
    // Colour: C's blue, then k blends toward red at speed 1/2.
    const double blue = std::pow(0.5, k);
    const auto c = out.mesh.color(IfsMesh::VertexHandle(int(first)));
    EXPECT_NEAR(c[0], 1.0 - blue, 1e-6);
    EXPECT_NEAR(c[2], blue, 1e-6);
    // Address: k digits of the map (0), then the condensation digit (1) to length n.
    std::vector<int> word(std::size_t(n), 1);
    for (int j = 0; j < k; ++j) word[std::size_t(j)] = 0;
    const std::size_t face = cube.n_faces() + std::size_t(k) * std::size_t(kSphereSegments * kSphereRings);
    EXPECT_EQ(decodeAddress(std::uint64_t(out.mesh.property(address, IfsMesh::FaceHandle(int(face)))), 2, n), word);
  }
  // f^n(A_0): the cube scaled by 2^-n.
  const auto& corner = out.mesh.point(IfsMesh::VertexHandle(0));
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(std::fabs(corner[d]), std::pow(0.5, n), 1e-6);
}

TEST(DeterministicCondensation, PrimitiveMeshesAreClosedAndOutward) {
  CondensationSet torus;
  torus.shape = SetShape::Torus;
  torus.center = {0.1, -0.1, 0.2};
  torus.major = 0.5;
  torus.minor = 0.15;
  torus.axis = {1.0, 1.0, 0.0};
  CondensationSet box;
  box.shape = SetShape::Box;
  box.size = {0.4, 0.6, 0.8};
  const double pi = M_PI;
  struct Case {
    CondensationSet set;
    double volume, tolerance;
  };
  for (const Case& c : {Case{sphereSet({0.3, 0, 0}, 0.5), 4.0 / 3.0 * pi * 0.125, 0.02},
                        Case{box, 0.4 * 0.6 * 0.8, 1e-6}, Case{torus, 2.0 * pi * pi * 0.5 * 0.15 * 0.15, 0.03}}) {
    SCOPED_TRACE(setShapeName(c.set.shape));
    const IfsMesh mesh = condensationSetMesh(c.set, ".", "set");
    for (auto h : mesh.halfedges()) ASSERT_FALSE(mesh.is_boundary(h));
    EXPECT_NEAR(signedVolume(mesh), c.volume, c.tolerance * c.volume);
  }
}

TEST(DeterministicCondensation, RefusesMedianFunctionsAndMissingMeshes) {
  Project project = sierpinskiProject();
  Function median = condensation("m", sphereSet(Vec3(0.0), 0.3), Vec3(1.0));
  median.kind = FunctionKind::Median;
  project.functions.push_back(median);
  try {
    snapshotDeterministicIfs(project);
    FAIL() << "a median function was accepted";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.path(), "functions[4].kind");
    EXPECT_NE(e.message().find("median"), std::string::npos);
  }
  project.functions.back().kind = FunctionKind::Condensation;
  const DeterministicIfs unloaded = snapshotDeterministicIfs(project);  // meshes not loaded
  DeterministicOptions options;
  EXPECT_THROW(planDeterministic(unloaded, countMesh(makeCube()), options), ModelError);
  CondensationSet file;
  file.shape = SetShape::Mesh;
  file.path = "no_such_tree.obj";
  project.functions.back().set = file;
  DeterministicIfs ifs = snapshotDeterministicIfs(project);
  try {
    loadCondensationMeshes(ifs, project, "/nonexistent-folder");
    FAIL() << "a missing mesh was accepted";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.path(), "functions[4].set.mesh");
    EXPECT_NE(e.message().find("no_such_tree.obj"), std::string::npos) << e.message();
  }
}
