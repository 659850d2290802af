// The contractivity estimate must bound the true Lipschitz constant and be exact for affine maps.
#include <gtest/gtest.h>

#include <random>

#include "model/contractivity.h"
#include "model/stack_evaluator.h"

using namespace gridifs;

TEST(Contractivity, SpectralNormOfKnownMatrices) {
  EXPECT_NEAR(spectralNorm({0.3, 0, 0}, {0, 0.7, 0}, {0, 0, 0.5}), 0.7, 1e-12);
  // [[1,1],[0,1]] ⊕ [1]: largest singular value is the golden ratio.
  EXPECT_NEAR(spectralNorm({1, 0, 0}, {1, 1, 0}, {0, 0, 1}), (1 + std::sqrt(5.0)) / 2, 1e-9);
  EXPECT_NEAR(spectralNorm({0, 0, 0}, {0, 0, 0}, {0, 0, 0}), 0.0, 1e-12);
}

TEST(Contractivity, ExactForAffineGrids) {
  Function f;
  f.resolution = {5, 4, 6};
  f.placement = {Vec3{0.2, 0, 0}, Vec3{10, 20, 30}, Vec3{0.3, 0.6, 0.45}};
  EXPECT_NEAR(estimateContractivity(evaluateFunction(f)).bound, 0.6, 1e-9);
}

TEST(Contractivity, BoundsTheObservedLipschitzRatio) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 20; ++trial) {
    Grid g({4, 5, 3});
    for (Vec3& p : g.nodes()) p = p * 0.5 + Vec3{u(rng), u(rng), u(rng)} * 0.15;
    const double bound = estimateContractivity(g).bound;
    double worst = 0.0;
    for (int n = 0; n < 4000; ++n) {
      const Vec3 a{u(rng), u(rng), u(rng)};
      const Vec3 b = a + Vec3{u(rng), u(rng), u(rng)} * 0.05;
      const Vec3 fa = g.evaluate(a), fb = g.evaluate(b);
      const double num =
          std::sqrt((fa.x - fb.x) * (fa.x - fb.x) + (fa.y - fb.y) * (fa.y - fb.y) + (fa.z - fb.z) * (fa.z - fb.z));
      const double den = std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
      worst = std::max(worst, num / den);
    }
    EXPECT_LE(worst, bound + 1e-9);
    EXPECT_GT(worst, 0.5 * bound);  // and it is not absurdly loose
  }
}

TEST(Contractivity, ReportsTheWorstCell) {
  Grid g({4, 4, 4});
  for (Vec3& p : g.nodes()) p *= 0.4;
  g.node(3, 3, 3) = Vec3{2, 2, 2};  // stretches only the last cell
  const auto estimate = estimateContractivity(g);
  EXPECT_GT(estimate.bound, 1.0);
  EXPECT_EQ(estimate.worstCell, (Index3{2, 2, 2}));
}
