// The deterministic algorithm F^n(A) (Gröller & Wegenkittl 1994, §3.2): counts, analytic positions, convergence to
// the Sierpinski tetrahedron, colors and addresses, topology, threads, limits and cancellation.
#include <gtest/gtest.h>

#include <OpenMesh/Tools/Utils/MeshCheckerT.hh>
#include <algorithm>
#include <limits>
#include <sstream>

#include "deterministic_samples.h"
#include "edit/document.h"
#include "mesh/deterministic_ifs.h"
#include "model/stack_evaluator.h"

using namespace gridifs;
using namespace gridifs::test_support;

namespace {

DeterministicMesh run(const Project& project, const BaseMeshSpec& spec, int depth, int threads = 0) {
  DeterministicOptions options;
  options.depth = depth;
  options.threads = threads;
  return runDeterministic(snapshotDeterministicIfs(project), spec, options);
}

std::uint64_t power(std::uint64_t base, int exponent) {
  std::uint64_t r = 1;
  for (int i = 0; i < exponent; ++i) r *= base;
  return r;
}

// A small affine IFS with rotations and unequal scales. Every image of X stays inside X
// (|T|∞ + |S·(1,1,1)| < 1), so clamping never applies and the composition is exactly affine.
Project affineProject() {
  Project p;
  p.functions.push_back(affineFunction("a", {0.3, -0.2, 0.1}, {10, 20, 30}, {0.35, 0.3, 0.33}, {1, 0, 0}));
  p.functions.push_back(affineFunction("b", {-0.3, 0.25, -0.1}, {-40, 5, 15}, {0.3, 0.35, 0.25}, {0, 0, 1}, 0.25));
  p.functions.push_back(affineFunction("c", {0.0, 0.3, -0.35}, {0, -30, 60}, {0.3, 0.3, 0.35}, {0, 1, 0}, 0.75));
  return p;
}

// A nonlinear IFS: twisted, tapered and bent grids (Gröller & Wegenkittl 1994, §2.2–2.4).
Project nonlinearProject() {
  Project p;
  Function f = affineFunction("twist", {0.4, 0, 0}, {0, 0, 20}, Vec3(0.5), {1, 0.5, 0});
  f.resolution = {6, 6, 6};
  f.ops.push_back(Operation{TwistOp{Axis::Z, Profile::Linear, 1.2, 1.0}, {}, {}, false});
  Function g = affineFunction("taper", {-0.4, 0.2, 0}, {15, 0, 0}, Vec3(0.45), {0, 0.5, 1});
  g.resolution = {5, 4, 6};
  g.ops.push_back(Operation{TaperOp{Axis::Y, Profile::Sine, 0.3, 3.0}, {}, {}, false});
  Function h = affineFunction("bend", {0, -0.4, 0.3}, {0, 0, 0}, Vec3(0.4), {0.2, 1, 0.2});
  h.resolution = {4, 4, 7};
  h.ops.push_back(Operation{BendOp{Axis::Z, Axis::Y, 0.8}, {}, {}, false});
  p.functions = {f, g, h};
  return p;
}

}  // namespace

TEST(DeterministicIfs, CountsAreExactlyCopiesTimesBase) {
  const Project project = sierpinskiProject();
  struct Case {
    BaseShape shape;
    int subdivision;
    bool triangulate;
  };
  for (const Case c : {Case{BaseShape::Cube, 0, false}, Case{BaseShape::Cube, 1, false}, Case{BaseShape::Cube, 2, true},
                       Case{BaseShape::Sphere, 0, false}, Case{BaseShape::Sphere, 1, true}}) {
    BaseMeshSpec spec;
    spec.shape = c.shape;
    spec.subdivision = c.subdivision;
    spec.triangulate = c.triangulate;
    const MeshCounts base = countMesh(refineBase(loadCoarseBase(spec), spec));
    for (int depth = 0; depth <= 3; ++depth) {
      const DeterministicMesh out = run(project, spec, depth);
      const std::uint64_t copies = power(4, depth);
      SCOPED_TRACE("shape " + std::to_string(int(c.shape)) + " S=" + std::to_string(c.subdivision) + " depth " +
                   std::to_string(depth));
      EXPECT_EQ(out.mesh.n_faces(), copies * base.faces);
      EXPECT_EQ(out.mesh.n_vertices(), copies * base.vertices);
      EXPECT_EQ(out.mesh.n_edges(), copies * base.edges);
      EXPECT_EQ(out.plan.copies, copies);
      EXPECT_EQ(out.plan.total, countMesh(out.mesh));  // the plan predicted it exactly
    }
  }
}

TEST(DeterministicIfs, MutedAndWeightlessFunctionsAreLeftOut) {
  Project project = sierpinskiProject();
  project.functions[1].muted = true;
  project.functions[3].weight = 0.0;
  const DeterministicIfs ifs = snapshotDeterministicIfs(project);
  ASSERT_EQ(ifs.maps.size(), 2u);
  EXPECT_EQ(ifs.maps[0].functionIndex, 0u);
  EXPECT_EQ(ifs.maps[1].functionIndex, 2u);
  const DeterministicMesh out = run(project, {}, 3);
  EXPECT_EQ(out.mesh.n_faces(), 8u * 6u);
  EXPECT_EQ(out.functionIndices, (std::vector<std::size_t>{0, 2}));
}

TEST(DeterministicIfs, AffineIfsReproducesAnalyticPositions) {
  Project project = affineProject();
  project.final_function = affineFunction("final", {0.05, 0, -0.05}, {0, 0, 45}, Vec3(1.2), Vec3(1));
  BaseMeshSpec spec;
  spec.subdivision = 1;  // edge midpoints and face centroids too, not only corners
  const IfsMesh base = refineBase(loadCoarseBase(spec), spec);
  const int depth = 3, N = 3;
  DeterministicOptions options;
  options.depth = depth;
  const DeterministicMesh out = buildDeterministicMesh(snapshotDeterministicIfs(project), base, options);
  const std::size_t V = base.n_vertices();
  ASSERT_EQ(out.mesh.n_vertices(), 27 * V);
  double worst = 0.0;
  for (std::uint64_t copy = 0; copy < 27; ++copy) {
    const std::vector<int> a = decodeAddress(copy, N, depth);  // a1 outermost
    for (std::size_t v = 0; v < V; ++v) {
      Vec3 p = toVec(base.point(IfsMesh::VertexHandle(int(v))));
      for (int k = depth - 1; k >= 0; --k) p = applyAffine(project.functions[std::size_t(a[std::size_t(k)])], p);
      p = applyAffine(*project.final_function, p);
      const Vec3 got = toVec(out.mesh.point(IfsMesh::VertexHandle(int(copy * V + v))));
      worst = std::max(worst, glm::length(got - p));
    }
  }
  EXPECT_LT(worst, 2e-6);  // float storage of exact double composition
}

TEST(DeterministicIfs, NonlinearPositionsMatchDirectComposition) {
  // Several vertex blocks (the sphere at S=3 has 8066 vertices) and shared prefixes: every
  // vertex must equal the plain composition of the evaluated grids.
  const Project project = nonlinearProject();
  std::vector<Grid> grids;
  for (const Function& f : project.functions) grids.push_back(evaluateFunction(f));
  BaseMeshSpec spec;
  spec.shape = BaseShape::Sphere;
  spec.subdivision = 3;
  const IfsMesh base = refineBase(loadCoarseBase(spec), spec);
  DeterministicOptions options;
  options.depth = 2;
  options.threads = 3;
  const DeterministicMesh out = buildDeterministicMesh(snapshotDeterministicIfs(project), base, options);
  const std::size_t V = base.n_vertices();
  ASSERT_GT(V, 4096u);
  std::size_t mismatches = 0;
  for (std::uint64_t copy = 0; copy < 9; ++copy) {
    const std::vector<int> a = decodeAddress(copy, 3, 2);
    for (std::size_t v = 0; v < V; ++v) {
      Vec3 p = toVec(base.point(IfsMesh::VertexHandle(int(v))));
      p = grids[std::size_t(a[0])].evaluate(grids[std::size_t(a[1])].evaluate(p));
      const IfsMesh::Point expected(float(p.x), float(p.y), float(p.z));
      if (out.mesh.point(IfsMesh::VertexHandle(int(copy * V + v))) != expected) ++mismatches;
    }
  }
  EXPECT_EQ(mismatches, 0u);
}

TEST(DeterministicIfs, SierpinskiVerticesApproachTheAttractor) {
  // Every point of F^n(cube) is within 0.5^n · r of the attractor (each f_i halves distances and
  // maps the attractor onto part of itself), where r ≤ 2 bounds the distance from a point of the
  // cube to the tetrahedron's corners, which lie on the attractor.
  // The attractor is sampled by the images of its corners under all words of length m: every
  // attractor point is within 0.5^m · 2√2 (a level-m piece's diameter) of the sample.
  const int depth = 4, m = 6;
  const DeterministicMesh out = run(sierpinskiProject(), {}, depth);
  std::vector<Vec3> sample;
  for (std::uint64_t word = 0; word < power(4, m); ++word)
    for (const Vec3& corner : tetrahedronCorners()) {
      Vec3 p = corner;
      for (int digit : decodeAddress(word, 4, m)) p = 0.5 * p + 0.5 * tetrahedronCorners()[std::size_t(digit)];
      sample.push_back(p);
    }
  const double near = 2.0 * std::pow(0.5, depth) + 2.0 * std::sqrt(2.0) * std::pow(0.5, m) + 1e-6;
  double worst = 0.0;
  std::vector<Vec3> vertices;
  for (auto vh : out.mesh.vertices()) vertices.push_back(toVec(out.mesh.point(vh)));
  for (const Vec3& v : vertices) {
    double best = std::numeric_limits<double>::max();
    for (const Vec3& s : sample) best = std::min(best, glm::length(v - s));
    worst = std::max(worst, best);
  }
  EXPECT_LE(worst, near);
  // Not vacuous: the copies' free cube corners really are about 1.2 · 0.5^n from the attractor.
  EXPECT_GT(worst, std::pow(0.5, depth));
  // And the other way: each attractor point lies in a piece f_w(cube) of diameter 0.5^n · 2√3,
  // so some vertex is that close.
  const double cover = 2.0 * std::sqrt(3.0) * std::pow(0.5, depth) + 1e-6;
  double worstCover = 0.0;
  for (const Vec3& s : sample) {
    double best = std::numeric_limits<double>::max();
    for (const Vec3& v : vertices) best = std::min(best, glm::length(v - s));
    worstCover = std::max(worstCover, best);
  }
  EXPECT_LE(worstCover, cover);
}

TEST(DeterministicIfs, ColorsBlendAlongTheAddressAndFacesCarryIt) {
  const Project project = affineProject();
  const int depth = 3, N = 3;
  const DeterministicMesh out = run(project, {}, depth);
  const auto address = addressProperty(out.mesh);
  ASSERT_TRUE(address.is_valid());
  const std::size_t F = 6, V = 8;
  for (std::size_t face = 0; face < out.mesh.n_faces(); ++face)
    ASSERT_EQ(out.mesh.property(address, IfsMesh::FaceHandle(int(face))), int(face / F));
  for (std::uint64_t copy = 0; copy < power(N, depth); ++copy) {
    const std::vector<int> a = decodeAddress(copy, N, depth);
    // Applied first: a_n; its color starts the blend, then a_{n-1}, ..., a_1 (chaos game order).
    Vec3 c = project.functions[std::size_t(a[std::size_t(depth - 1)])].color;
    for (int k = depth - 2; k >= 0; --k) {
      const Function& f = project.functions[std::size_t(a[std::size_t(k)])];
      c = c + (f.color - c) * f.color_speed;
    }
    for (std::size_t v = 0; v < V; ++v) {
      const auto got = out.mesh.color(IfsMesh::VertexHandle(int(copy * V + v)));
      for (int d = 0; d < 3; ++d) ASSERT_NEAR(got[d], c[d], 1e-6) << "copy " << copy;
      ASSERT_EQ(got[3], 1.0f);
    }
  }
  // Depth 1: each copy is exactly its function's color; depth 0: white.
  const DeterministicMesh one = run(project, {}, 1);
  for (int i = 0; i < N; ++i) {
    const auto got = one.mesh.color(IfsMesh::VertexHandle(i * 8));
    EXPECT_NEAR(got[0], project.functions[std::size_t(i)].color.x, 1e-6);
    EXPECT_NEAR(got[2], project.functions[std::size_t(i)].color.z, 1e-6);
  }
  const DeterministicMesh zero = run(project, {}, 0);
  EXPECT_EQ(zero.mesh.color(IfsMesh::VertexHandle(0)), IfsMesh::Color(1, 1, 1, 1));
}

TEST(DeterministicIfs, TopologyIsTheBaseReplicated) {
  BaseMeshSpec spec;
  spec.shape = BaseShape::File;
  TempFolder folder("det-topology");
  writeFile(folder / "pyramid.obj", pyramidObj());
  spec.file = folder / "pyramid.obj";
  spec.subdivision = 1;
  const IfsMesh base = refineBase(loadCoarseBase(spec), spec);
  DeterministicOptions options;
  options.depth = 2;
  DeterministicMesh out = buildDeterministicMesh(snapshotDeterministicIfs(sierpinskiProject()), base, options);
  IfsMesh& mesh = out.mesh;
  mesh.request_vertex_status();
  mesh.request_edge_status();
  mesh.request_face_status();
  std::ostringstream report;
  EXPECT_TRUE(
      OpenMesh::Utils::MeshCheckerT<IfsMesh>(mesh).check(OpenMesh::Utils::MeshCheckerT<IfsMesh>::CHECK_ALL, report))
      << report.str();
  const std::size_t V = base.n_vertices(), F = base.n_faces();
  for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
    std::vector<int> got, want;
    for (auto vh : mesh.fv_range(IfsMesh::FaceHandle(int(f)))) got.push_back(vh.idx());
    for (auto vh : base.fv_range(IfsMesh::FaceHandle(int(f % F)))) want.push_back(vh.idx() + int((f / F) * V));
    ASSERT_EQ(got, want) << "face " << f;
  }
  for (auto vh : mesh.vertices()) ASSERT_FALSE(mesh.is_boundary(vh));  // closed base → closed copies
  // Each copy of an outward pyramid keeps its orientation (positive volume 8/3 · 0.5^(3n)).
  EXPECT_NEAR(signedVolume(mesh), 16.0 * (8.0 / 3.0) / 64.0, 1e-5);
}

TEST(DeterministicIfs, ResultDoesNotDependOnThreads) {
  const Project project = nonlinearProject();
  BaseMeshSpec spec;
  spec.subdivision = 2;
  const DeterministicMesh a = run(project, spec, 4, 1);
  const DeterministicMesh b = run(project, spec, 4, 2);
  const DeterministicMesh c = run(project, spec, 4, 5);
  ASSERT_EQ(a.mesh.n_vertices(), b.mesh.n_vertices());
  ASSERT_EQ(a.mesh.n_vertices(), c.mesh.n_vertices());
  for (auto vh : a.mesh.vertices()) {
    ASSERT_EQ(a.mesh.point(vh), b.mesh.point(vh));
    ASSERT_EQ(a.mesh.point(vh), c.mesh.point(vh));
    ASSERT_EQ(a.mesh.color(vh), c.mesh.color(vh));
  }
}

TEST(DeterministicIfs, SnapshotFromDocumentMatchesProject) {
  const Project project = nonlinearProject();
  Document document(project);
  const DeterministicIfs fromDocument = snapshotDeterministicIfs(document.project(), document.evaluation());
  const DeterministicIfs fromProject = snapshotDeterministicIfs(project);
  ASSERT_EQ(fromDocument.maps.size(), fromProject.maps.size());
  for (std::size_t i = 0; i < fromDocument.maps.size(); ++i)
    EXPECT_EQ(*fromDocument.maps[i].grid, *fromProject.maps[i].grid);
  EXPECT_EQ(fromDocument.finalGrid, nullptr);
}

TEST(DeterministicIfs, PlansWarnAndRefuse) {
  const DeterministicIfs ifs = snapshotDeterministicIfs(sierpinskiProject());
  const MeshCounts cube = countMesh(makeCube());
  DeterministicOptions options;
  options.depth = 30;  // 4^30 · 6 faces
  DeterministicPlan plan = planDeterministic(ifs, cube, options);
  EXPECT_TRUE(plan.overLimit);
  EXPECT_NE(plan.message.find("faces"), std::string::npos) << plan.message;
  EXPECT_NE(plan.message.find("limit"), std::string::npos) << plan.message;
  EXPECT_THROW(buildDeterministicMesh(ifs, makeCube(), options), ModelError);
  EXPECT_THROW(runDeterministic(ifs, BaseMeshSpec{}, options), ModelError);

  options.depth = 200;  // saturates 64-bit counts; still a clear refusal
  plan = planDeterministic(ifs, cube, options);
  EXPECT_TRUE(plan.overLimit);
  EXPECT_NE(plan.message.find("about"), std::string::npos) << plan.message;

  options.depth = 5;
  options.limits.memoryBudgetBytes = 1000;
  plan = planDeterministic(ifs, cube, options);
  EXPECT_FALSE(plan.overLimit);
  EXPECT_TRUE(plan.overBudget);
  EXPECT_GT(plan.estimatedBytes, 1000u);
  EXPECT_NO_THROW(buildDeterministicMesh(ifs, makeCube(), options));  // a warning, not a refusal

  options.limits = {};
  options.depth = -1;
  EXPECT_THROW(planDeterministic(ifs, cube, options), ModelError);
  options.depth = kMaxDeterministicDepth + 1;
  EXPECT_THROW(planDeterministic(ifs, cube, options), ModelError);
  options.depth = 2;
  EXPECT_THROW(planDeterministic(DeterministicIfs{}, cube, options), ModelError);
}

TEST(DeterministicIfs, SingleFunctionAtGreatDepthConvergesToItsFixedPoint) {
  Project project;
  project.functions.push_back(affineFunction("f", {0.2, -0.1, 0.3}, Vec3(0.0), Vec3(0.5), Vec3(1)));
  DeterministicOptions options;
  options.depth = kMaxDeterministicDepth;
  const DeterministicMesh out = runDeterministic(snapshotDeterministicIfs(project), BaseMeshSpec{}, options);
  ASSERT_EQ(out.mesh.n_vertices(), 8u);
  for (auto vh : out.mesh.vertices())  // fixed point of p/2 + t: 2t
    EXPECT_LT(glm::length(toVec(out.mesh.point(vh)) - Vec3(0.4, -0.2, 0.6)), 1e-6);
}

TEST(DeterministicIfs, ProgressIsMonotoneAndCancellationStops) {
  const DeterministicIfs ifs = snapshotDeterministicIfs(sierpinskiProject());
  DeterministicOptions options;
  options.depth = 6;
  std::vector<double> seen;
  buildDeterministicMesh(ifs, makeCube(), options, [&](double f) {
    seen.push_back(f);
    return true;
  });
  ASSERT_FALSE(seen.empty());
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(seen.back(), 1.0);

  EXPECT_THROW(buildDeterministicMesh(ifs, makeCube(), options, [](double) { return false; }), DeterministicCancelled);
  std::atomic<bool> cancel{true};
  EXPECT_THROW(buildDeterministicMesh(ifs, makeCube(), options, {}, &cancel), DeterministicCancelled);
}

TEST(DeterministicIfs, BuildsIntoACallerOwnedObject) {
  // The GUI keeps results on the heap (OpenMesh meshes copy instead of moving).
  const DeterministicIfs ifs = snapshotDeterministicIfs(sierpinskiProject());
  auto shared = std::make_shared<DeterministicMesh>();
  DeterministicOptions options;
  options.depth = 3;
  runDeterministic(ifs, BaseMeshSpec{}, options, *shared);
  EXPECT_EQ(shared->mesh.n_faces(), 384u);
  options.depth = 1;  // reusing the object replaces everything, including the address property
  buildDeterministicMesh(ifs, makeCube(), options, *shared);
  EXPECT_EQ(shared->mesh.n_faces(), 24u);
  EXPECT_EQ(shared->plan.copies, 4u);
  EXPECT_EQ(shared->functionIndices.size(), 4u);
  const auto address = addressProperty(shared->mesh);
  ASSERT_TRUE(address.is_valid());
  EXPECT_EQ(shared->mesh.property(address, IfsMesh::FaceHandle(23)), 3);
  std::size_t properties = 0;
  for (auto it = shared->mesh.fprops_begin(); it != shared->mesh.fprops_end(); ++it)
    properties += *it && (*it)->name() == kAddressPropertyName;
  EXPECT_EQ(properties, 1u);
}
