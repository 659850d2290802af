// Symmetry helpers (Draves & Reckase 2003, §7): added functions with weight = sum of the others and
// color speed 0; a symmetry function is an affine 2×2×2 grid.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "edit/flame_symmetry.h"
#include "model/stack_evaluator.h"

using namespace gridifs;

namespace {
Project twoFunctions() {
  Project p;
  Function a, b;
  a.weight = 1.0;
  b.weight = 2.0;
  b.name = "f2";
  p.functions = {a, b};
  return p;
}
}  // namespace

TEST(FlameSymmetry, RotationalSymmetryAddsNMinusOneBalancedRotations) {
  const Project p = twoFunctions();
  SymmetryFrame frame;  // about +z through the origin
  const auto added = symmetryFunctions(p, 3, frame);
  ASSERT_EQ(added.size(), 2u);
  for (const Function& f : added) {
    EXPECT_DOUBLE_EQ(f.weight, 3.0);  // Draves & Reckase 2003, §7: the sum of the other weights
    EXPECT_EQ(f.color_speed, 0.0);    // and the color coordinate is left alone
    EXPECT_EQ(f.resolution, (Index3{2, 2, 2}));
  }
  const Grid g = evaluateFunction(added[0]);
  const Vec3 q = g.evaluate({0.5, 0.0, 0.25});
  EXPECT_NEAR(q.x, 0.5 * std::cos(2 * M_PI / 3), 1e-12);
  EXPECT_NEAR(q.y, 0.5 * std::sin(2 * M_PI / 3), 1e-12);
  EXPECT_NEAR(q.z, 0.25, 1e-12);
  const Vec3 r = evaluateFunction(added[1]).evaluate({0.5, 0.0, 0.25});
  EXPECT_NEAR(r.x, 0.5 * std::cos(4 * M_PI / 3), 1e-12);
  EXPECT_NEAR(r.y, 0.5 * std::sin(4 * M_PI / 3), 1e-12);
  EXPECT_TRUE(symmetryFunctions(p, 1, frame).empty());
  EXPECT_TRUE(symmetryFunctions(p, 0, frame).empty());
  EXPECT_THROW(symmetryFunctions(p, 40, frame), ModelError);
}

TEST(FlameSymmetry, DihedralSymmetryAddsAMirrorAndRotations) {
  const Project p = twoFunctions();
  SymmetryFrame frame;
  const auto added = symmetryFunctions(p, -4, frame);
  ASSERT_EQ(added.size(), 4u);  // mirror + 3 rotations
  const Vec3 m = evaluateFunction(added[0]).evaluate({0.3, 0.2, -0.1});
  EXPECT_NEAR(m.x, -0.3, 1e-12);  // the mirror flips the image's horizontal direction only
  EXPECT_NEAR(m.y, 0.2, 1e-12);
  EXPECT_NEAR(m.z, -0.1, 1e-12);
  Project q = p;
  addSymmetry(q, -4, frame);
  EXPECT_EQ(q.functions.size(), 6u);
  EXPECT_EQ(symmetryFunctions(p, -1, frame).size(), 1u);  // bilateral
}

TEST(FlameSymmetry, FrameFollowsTheViewAndItsTarget) {
  Camera top;
  top.pitch = 90.0;  // looking straight down
  top.yaw = 0.0;
  top.target = {0.1, 0.0, 0.0};
  const SymmetryFrame f = symmetryFrameForView(top);
  EXPECT_NEAR(f.axis.z, -1.0, 1e-5);
  EXPECT_NEAR(glm::dot(f.axis, f.mirror), 0.0, 1e-12);
  // A half turn about the view axis through the target maps the target to itself.
  Project p = twoFunctions();
  const auto added = symmetryFunctions(p, 2, f);
  ASSERT_EQ(added.size(), 1u);
  const Vec3 c = evaluateFunction(added[0]).evaluate(top.target);
  EXPECT_NEAR(glm::length(c - top.target), 0.0, 1e-4);
  const Vec3 other = evaluateFunction(added[0]).evaluate({0.3, 0.0, 0.2});
  EXPECT_NEAR(other.x, -0.1, 1e-3);
  EXPECT_NEAR(other.z, 0.2, 1e-3);
}
