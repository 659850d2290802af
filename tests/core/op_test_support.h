#pragma once
// Shared helpers for the operation tests: run one op on an undistorted grid and
// compare against positions computed independently from the paper's formulas.
#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "model/stack_evaluator.h"

namespace gridifs::test_support {

inline Function functionWith(const Index3& res, std::vector<Operation> ops) {
  Function f;
  f.resolution = res;
  f.ops = std::move(ops);
  return f;  // identity placement
}

inline Operation op(OpParams params, Center center = {}, Selection selection = {}) {
  Operation o;
  o.params = std::move(params);
  o.center = center;
  o.selection = std::move(selection);
  return o;
}

/// Expects every node of `f` evaluated to equal expected(undistorted node, i, j, k).
inline void expectNodes(const Function& f, const std::function<Vec3(const Vec3&, int, int, int)>& expected,
                        double tolerance = 1e-9) {
  const Grid g = evaluateFunction(f);
  const Grid u(f.resolution);
  for (int k = 0; k < f.resolution[2]; ++k)
    for (int j = 0; j < f.resolution[1]; ++j)
      for (int i = 0; i < f.resolution[0]; ++i) {
        const Vec3 e = expected(u.node(i, j, k), i, j, k);
        const Vec3& a = g.node(i, j, k);
        ASSERT_NEAR(a.x, e.x, tolerance) << "node " << i << "," << j << "," << k;
        ASSERT_NEAR(a.y, e.y, tolerance) << "node " << i << "," << j << "," << k;
        ASSERT_NEAR(a.z, e.z, tolerance) << "node " << i << "," << j << "," << k;
      }
}

struct Random {
  std::mt19937 rng;
  explicit Random(unsigned seed) : rng(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
  Vec3 vec(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
  Axis axis() { return static_cast<Axis>(integer(0, 2)); }
  Profile profile() { return static_cast<Profile>(integer(0, 2)); }
  Index3 resolution() { return {integer(2, 7), integer(2, 7), integer(2, 7)}; }
};

}  // namespace gridifs::test_support
