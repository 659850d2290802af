// Grid basics and trilinear evaluation (Gröller & Wegenkittl 1994, §1.3).
#include <gtest/gtest.h>

#include <random>

#include "model/grid.h"
#include "model/stack_evaluator.h"

using namespace gridifs;

TEST(Grid, UndistortedNodesTileTheBiUnitCube) {
  Grid g({3, 5, 2});
  EXPECT_EQ(g.nodeCount(), 30u);
  EXPECT_EQ(g.node(0, 0, 0), Vec3(-1, -1, -1));
  EXPECT_EQ(g.node(2, 4, 1), Vec3(1, 1, 1));
  EXPECT_DOUBLE_EQ(g.node(1, 2, 0).x, 0.0);
  EXPECT_DOUBLE_EQ(g.node(1, 1, 0).y, -0.5);
}

TEST(Grid, RejectsResolutionOutsideLimits) {
  EXPECT_THROW(Grid({1, 4, 4}), ModelError);
  EXPECT_THROW(Grid({4, 129, 4}), ModelError);
  EXPECT_NO_THROW(Grid({2, 128, 2}));
}

TEST(Grid, UndistortedGridIsTheIdentityInsideX) {
  Grid g({4, 7, 5});
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int n = 0; n < 200; ++n) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    const Vec3 q = g.evaluate(p);
    EXPECT_NEAR(q.x, p.x, 1e-12);
    EXPECT_NEAR(q.y, p.y, 1e-12);
    EXPECT_NEAR(q.z, p.z, 1e-12);
  }
}

TEST(Grid, TrilinearIsExactOnNodes) {
  Grid g({5, 4, 6});
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (Vec3& p : g.nodes()) p += Vec3{u(rng), u(rng), u(rng)};
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 5; ++i) {
        const Vec3 q = g.evaluate(g.undistorted(i, j, k));
        EXPECT_NEAR(q.x, g.node(i, j, k).x, 1e-12);
        EXPECT_NEAR(q.y, g.node(i, j, k).y, 1e-12);
        EXPECT_NEAR(q.z, g.node(i, j, k).z, 1e-12);
      }
}

TEST(Grid, AffineGridsReproduceAffineMaps) {
  // A grid whose nodes are A·u + b evaluates to A·p + b everywhere in X.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  double a[3][3];
  for (auto& row : a)
    for (double& v : row) v = 0.4 * u(rng);
  const Vec3 b{u(rng) * 0.3, u(rng) * 0.3, u(rng) * 0.3};
  auto affine = [&](const Vec3& p) {
    return Vec3{a[0][0] * p.x + a[0][1] * p.y + a[0][2] * p.z + b.x,
                a[1][0] * p.x + a[1][1] * p.y + a[1][2] * p.z + b.y,
                a[2][0] * p.x + a[2][1] * p.y + a[2][2] * p.z + b.z};
  };
  Grid g({3, 6, 4});
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 3; ++i) g.node(i, j, k) = affine(g.undistorted(i, j, k));
  for (int n = 0; n < 500; ++n) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    const Vec3 q = g.evaluate(p), e = affine(p);
    EXPECT_NEAR(q.x, e.x, 1e-12);
    EXPECT_NEAR(q.y, e.y, 1e-12);
    EXPECT_NEAR(q.z, e.z, 1e-12);
  }
}

TEST(Grid, PointsOutsideXAreClampedFirst) {
  Grid g({4, 4, 4});
  for (Vec3& p : g.nodes()) p = p * 0.5 + Vec3{0.1, 0, 0};
  const Vec3 outside{3.0, -7.0, 0.25};
  const Vec3 clamped{1.0, -1.0, 0.25};
  EXPECT_EQ(g.evaluate(outside), g.evaluate(clamped));
  const Vec3 q = g.evaluate(Vec3{NAN, 0, 0});  // NaN does not poison the map
  EXPECT_TRUE(std::isfinite(q.x));
}

TEST(Grid, TrilinearMatchesTheFormulaInsideACell) {
  // f(p) = Σ w_abc · P_abc with w = product of (1 − t) or t per axis.
  Grid g({2, 2, 2});
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1, 1);
  for (Vec3& p : g.nodes()) p = {u(rng), u(rng), u(rng)};
  for (int n = 0; n < 100; ++n) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    const Vec3 t = (p + 1.0) * 0.5;
    Vec3 expected{0.0};
    for (int c = 0; c < 8; ++c) {
      const int a = c & 1, b = (c >> 1) & 1, d = c >> 2;
      const double w = (a ? t.x : 1 - t.x) * (b ? t.y : 1 - t.y) * (d ? t.z : 1 - t.z);
      expected += w * g.node(a, b, d);
    }
    const Vec3 q = g.evaluate(p);
    EXPECT_NEAR(q.x, expected.x, 1e-12);
    EXPECT_NEAR(q.y, expected.y, 1e-12);
    EXPECT_NEAR(q.z, expected.z, 1e-12);
  }
}
