// The final function's "bezier" lattice (Sederberg & Parry's free-form deformation): an
// undistorted lattice is the identity in the model, in the renderer and in the file.
#include <gtest/gtest.h>

#include "freeform/bezier_lattice.h"
#include "io/project_io.h"
#include "model/stack_evaluator.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"

using namespace gridifs;

namespace {

std::vector<Vec3> samplePoints() {
  std::vector<Vec3> out;
  for (int n = 0; n < 200; ++n)
    out.push_back(Vec3{std::sin(n * 1.7), std::cos(n * 2.3), std::sin(n * 0.37 + 1.0)} * 0.999);
  return out;
}

std::vector<float> chaosPoints(const Project& p) {
  RenderJob job = RenderJob::fromProject(p, 1);
  job.samples = 4000;
  std::vector<float> out;
  generatePoints(*compileIfs(p), job, [&](const PointBatch& b, const RenderStats&) {
    out.insert(out.end(), b.xyz, b.xyz + 3 * b.count);
    return true;
  });
  return out;
}

}  // namespace

TEST(BezierLattice, UndistortedLatticeIsTheIdentity) {
  for (const Index3 n : {Index3{2, 2, 2}, Index3{4, 5, 8}, Index3{8, 8, 8}}) {
    const Grid lattice(n);
    for (const Vec3& p : samplePoints()) {
      const Vec3 q = evaluateBezierLattice(lattice, p);
      EXPECT_NEAR(q.x, p.x, 1e-12);
      EXPECT_NEAR(q.y, p.y, 1e-12);
      EXPECT_NEAR(q.z, p.z, 1e-12);
    }
  }
}

TEST(BezierLattice, InterpolatesTheCornersAndIsSmoothInside) {
  Grid lattice(Index3{4, 4, 4});
  lattice.node(1, 2, 1) += Vec3{0.3, -0.2, 0.5};
  lattice.node(3, 3, 3) = Vec3{1.2, 0.9, 1.1};
  EXPECT_EQ(evaluateBezierLattice(lattice, Vec3{1.0}), lattice.node(3, 3, 3));  // corners are interpolated
  // Inside, every node pulls a little (unlike trilinear cells, which move only near the node).
  const Vec3 p{-0.5, -0.5, -0.5};  // its trilinear cell has no moved node
  EXPECT_LT(glm::length(lattice.evaluate(p) - p), 1e-12);
  EXPECT_GT(glm::length(evaluateBezierLattice(lattice, p) - p), 1e-3);
  // The renderer's sampled grid follows the polynomial closely.
  const auto sampled = sampleBezierLattice(lattice);
  for (const Vec3& q : samplePoints())
    EXPECT_LT(glm::length(sampled->evaluate(q) - evaluateBezierLattice(lattice, q)), 5e-3);
}

TEST(BezierLattice, IdentityFinalFunctionLeavesEveryPointWhereItWas) {
  Project p = loadProject(std::string(GRIDIFS_ASSETS) + "/sierpinski_tetrahedron.gridifs");
  const std::vector<float> plain = chaosPoints(p);
  Function final;
  final.name = "lattice";
  final.resolution = {5, 6, 7};
  final.placement.scale = Vec3{1.0};
  final.interpolation = LatticeInterpolation::Bezier;
  p.final_function = final;
  const std::vector<float> deformed = chaosPoints(p);
  ASSERT_EQ(plain.size(), deformed.size());
  for (std::size_t i = 0; i < plain.size(); ++i) ASSERT_NEAR(plain[i], deformed[i], 2e-6) << i;
  EXPECT_EQ(parseProject(serializeProject(p)), p);
  EXPECT_NE(serializeProject(p).find("\"interpolation\": \"bezier\""), std::string::npos);
}
