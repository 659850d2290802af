// Each operation against its formula (Gröller & Wegenkittl 1994, §2) on random parameters.
// Expected positions are computed here from the papers' formulas, not from the model code.
#include <cmath>

#include "op_test_support.h"

using namespace gridifs;
using namespace gridifs::test_support;

namespace {

// (a, b, t) components for an axis, in cyclic order: z → (x, y), x → (y, z), y → (z, x).
struct Frame {
  int a, b, t;
};
Frame frameOf(Axis axis) {
  switch (axis) {
    case Axis::X:
      return {1, 2, 0};
    case Axis::Y:
      return {2, 0, 1};
    default:
      return {0, 1, 2};
  }
}

// Triangle wave written independently: 2/π · asin(sin x).
double tri(double x) { return 2.0 / M_PI * std::asin(std::sin(x)); }

double profileOf(Profile p, double k, double omega, double t) {
  if (p == Profile::Linear) return k * t;
  if (p == Profile::Sine) return k * std::sin(omega * t);
  return k * tri(omega * t);
}

Vec3 centroidOfAllNodes(const Index3& res) {
  (void)res;
  return Vec3{0.0};  // the undistorted lattice is symmetric about the origin
}

}  // namespace

TEST(Operations, TranslateMovesEveryNode) {
  Random r(10);
  for (int trial = 0; trial < 10; ++trial) {
    const Vec3 d = r.vec(-0.5, 0.5);
    expectNodes(functionWith(r.resolution(), {op(TranslateOp{d})}),
                [&](const Vec3& u, int, int, int) { return u + d; });
  }
}

TEST(Operations, RotateIsRzRyRxAboutTheCenter) {
  Random r(11);
  for (int trial = 0; trial < 10; ++trial) {
    const Vec3 angles = r.vec(-180, 180);
    const Vec3 c = r.vec(-1, 1);
    const double ax = angles.x * M_PI / 180, ay = angles.y * M_PI / 180, az = angles.z * M_PI / 180;
    // Explicit matrices, multiplied out: R = Rz·Ry·Rx.
    const double Rx[3][3] = {{1, 0, 0}, {0, std::cos(ax), -std::sin(ax)}, {0, std::sin(ax), std::cos(ax)}};
    const double Ry[3][3] = {{std::cos(ay), 0, std::sin(ay)}, {0, 1, 0}, {-std::sin(ay), 0, std::cos(ay)}};
    const double Rz[3][3] = {{std::cos(az), -std::sin(az), 0}, {std::sin(az), std::cos(az), 0}, {0, 0, 1}};
    double zy[3][3] = {}, R[3][3] = {};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int m = 0; m < 3; ++m) zy[i][j] += Rz[i][m] * Ry[m][j];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int m = 0; m < 3; ++m) R[i][j] += zy[i][m] * Rx[m][j];
    Center center{Center::Kind::Point, c};
    expectNodes(functionWith(r.resolution(), {op(RotateOp{angles}, center)}), [&](const Vec3& u, int, int, int) {
      const Vec3 q = u - c;
      return c + Vec3{R[0][0] * q.x + R[0][1] * q.y + R[0][2] * q.z, R[1][0] * q.x + R[1][1] * q.y + R[1][2] * q.z,
                      R[2][0] * q.x + R[2][1] * q.y + R[2][2] * q.z};
    });
  }
}

TEST(Operations, ScaleAboutTheCenter) {
  Random r(12);
  for (int trial = 0; trial < 10; ++trial) {
    const Vec3 s = r.vec(-2, 2), c = r.vec(-1, 1);
    expectNodes(functionWith(r.resolution(), {op(ScaleOp{s}, {Center::Kind::Point, c})}),
                [&](const Vec3& u, int, int, int) { return c + (u - c) * s; });
  }
}

TEST(Operations, TaperScalesThePerpendicularComponents) {
  Random r(13);
  for (int trial = 0; trial < 30; ++trial) {
    TaperOp t{r.axis(), r.profile(), r.uniform(-1, 1), r.uniform(0.1, 6)};
    const Vec3 c = r.vec(-0.5, 0.5);
    const Frame f = frameOf(t.axis);
    expectNodes(functionWith(r.resolution(), {op(t, {Center::Kind::Point, c})}), [&](const Vec3& u, int, int, int) {
      Vec3 q = u - c;
      const double scale = 1.0 + profileOf(t.profile, t.k, t.omega, q[f.t]);
      q[f.a] *= scale;
      q[f.b] *= scale;
      return c + q;
    });
  }
}

TEST(Operations, TwistRotatesThePerpendicularComponents) {
  Random r(14);
  for (int trial = 0; trial < 30; ++trial) {
    TwistOp t{r.axis(), r.profile(), r.uniform(-3, 3), r.uniform(0.1, 6)};
    const Vec3 c = r.vec(-0.5, 0.5);
    const Frame f = frameOf(t.axis);
    expectNodes(functionWith(r.resolution(), {op(t, {Center::Kind::Point, c})}), [&](const Vec3& u, int, int, int) {
      Vec3 q = u - c;
      const double phi = profileOf(t.profile, t.k, t.omega, q[f.t]);
      const double x = q[f.a], y = q[f.b];
      q[f.a] = x * std::cos(phi) - y * std::sin(phi);
      q[f.b] = x * std::sin(phi) + y * std::cos(phi);
      return c + q;
    });
  }
}

TEST(Operations, BendFollowsBarrsFormula) {
  Random r(15);
  for (int trial = 0; trial < 30; ++trial) {
    BendOp b{r.axis(), Axis::X, 0.0};
    do b.toward = r.axis();
    while (b.toward == b.axis);
    b.k = r.uniform(0.2, 2.5) * (r.integer(0, 1) ? 1 : -1);
    const Vec3 c = r.vec(-0.5, 0.5);
    const int along = int(b.axis), toward = int(b.toward);
    expectNodes(functionWith(r.resolution(), {op(b, {Center::Kind::Point, c})}), [&](const Vec3& u, int, int, int) {
      Vec3 q = u - c;
      const double z = q[along], y = q[toward], R = 1.0 / b.k, theta = b.k * z;
      q[toward] = R - (R - y) * std::cos(theta);
      q[along] = (R - y) * std::sin(theta);
      return c + q;
    });
  }
}

TEST(Operations, BendIsSmoothAsCurvatureVanishes) {
  const Index3 res{4, 5, 6};
  expectNodes(
      functionWith(res, {op(BendOp{Axis::Z, Axis::Y, 0.0})}), [](const Vec3& u, int, int, int) { return u; }, 0.0);
  const Grid small = evaluateFunction(functionWith(res, {op(BendOp{Axis::Z, Axis::Y, 1e-7})}));
  const Grid identity(res);
  for (std::size_t n = 0; n < small.nodeCount(); ++n) {
    EXPECT_NEAR(small.nodes()[n].y, identity.nodes()[n].y, 1e-6);
    EXPECT_NEAR(small.nodes()[n].z, identity.nodes()[n].z, 1e-6);
  }
  // Continuity from both sides: k = ±1e-4 differ from each other by O(k).
  const Grid plus = evaluateFunction(functionWith(res, {op(BendOp{Axis::Z, Axis::Y, 1e-4})}));
  const Grid minus = evaluateFunction(functionWith(res, {op(BendOp{Axis::Z, Axis::Y, -1e-4})}));
  for (std::size_t n = 0; n < plus.nodeCount(); ++n) EXPECT_NEAR(plus.nodes()[n].y, minus.nodes()[n].y, 1e-3);
}

TEST(Operations, MagnetPullsWithinRange) {
  Random r(16);
  for (int trial = 0; trial < 20; ++trial) {
    MagnetOp m{r.vec(-1.2, 1.2), r.uniform(0.2, 2), r.uniform(-1, 1), r.uniform(0, 4)};
    expectNodes(functionWith(r.resolution(), {op(m)}), [&](const Vec3& p, int, int, int) {
      const double d = std::sqrt((p.x - m.point.x) * (p.x - m.point.x) + (p.y - m.point.y) * (p.y - m.point.y) +
                                 (p.z - m.point.z) * (p.z - m.point.z));
      if (d >= m.dmax) return p;
      const double f = m.strength * std::pow((m.dmax - d) / m.dmax, m.falloff);
      return Vec3{p.x + f * (m.point.x - p.x), p.y + f * (m.point.y - p.y), p.z + f * (m.point.z - p.z)};
    });
  }
}

TEST(Operations, MorphMovesEachStartPointOntoItsEnd) {
  // Start points on lattice nodes of a 5×5×5 grid: those nodes must land on the ends.
  Random r(17);
  const Index3 res{5, 5, 5};
  const Grid u(res);
  for (int trial = 0; trial < 10; ++trial) {
    const int n = r.integer(1, 6);
    MorphOp m;
    std::vector<Index3> used;
    while (int(m.pairs.size()) < n) {
      const Index3 ix{r.integer(0, 4), r.integer(0, 4), r.integer(0, 4)};
      if (std::find(used.begin(), used.end(), ix) != used.end()) continue;
      used.push_back(ix);
      const Vec3 from = u.node(ix[0], ix[1], ix[2]);
      m.pairs.push_back({from, from + r.vec(-0.3, 0.3)});
    }
    const Grid g = evaluateFunction(functionWith(res, {op(m)}));
    for (std::size_t p = 0; p < used.size(); ++p) {
      const Vec3& got = g.node(used[p][0], used[p][1], used[p][2]);
      EXPECT_NEAR(got.x, m.pairs[p].to.x, 1e-9);
      EXPECT_NEAR(got.y, m.pairs[p].to.y, 1e-9);
      EXPECT_NEAR(got.z, m.pairs[p].to.z, 1e-9);
    }
  }
}

TEST(Operations, MorphMatchesTheRbfFormulaForOnePair) {
  // n = 1: r_1 = 1, α = (Q − P)·(0 + 1), P̂ = P + s·α/(d² + 1).
  const Vec3 P{0.2, -0.1, 0.3}, Q{0.5, 0.1, 0.0};
  const double s = 0.7;
  MorphOp m{{{P, Q}}, s};
  expectNodes(functionWith({4, 4, 4}, {op(m)}), [&](const Vec3& x, int, int, int) {
    const Vec3 d = x - P;
    return x + s * (Q - P) / (d.x * d.x + d.y * d.y + d.z * d.z + 1.0);
  });
}

TEST(Operations, MorphWithCoincidentStartPointsIsSingular) {
  MorphOp m{{{Vec3{0.1, 0, 0}, Vec3{0.2, 0, 0}}, {Vec3{0.1, 0, 0}, Vec3{0.3, 0, 0}}}, 1.0};
  EXPECT_THROW(evaluateFunction(functionWith({3, 3, 3}, {op(m)})), ModelError);
}

TEST(Operations, NodesOpDisplacesListedNodes) {
  NodesOp n{{{{1, 2, 0}, Vec3{0.1, 0.2, 0.3}}, {{0, 0, 1}, Vec3{-0.5, 0, 0}}, {{9, 9, 9}, Vec3{1, 1, 1}}}};
  expectNodes(functionWith({3, 3, 2}, {op(n)}), [](const Vec3& u, int i, int j, int k) {
    if (i == 1 && j == 2 && k == 0) return u + Vec3{0.1, 0.2, 0.3};
    if (i == 0 && j == 0 && k == 1) return u + Vec3{-0.5, 0, 0};
    return u;
  });
}

TEST(Operations, SelectionRestrictsTheOperation) {
  Random r(18);
  for (int trial = 0; trial < 10; ++trial) {
    const Index3 res{5, 6, 4};
    SelectionBox box{{r.integer(0, 4), r.integer(0, 4)}, {r.integer(0, 5), r.integer(0, 5)}, {0, 3}, SelectionOp::Or};
    const Vec3 d = r.vec(-0.3, 0.3);
    auto inBox = [&](int i, int j, int) {
      return i >= std::min(box.i[0], box.i[1]) && i <= std::max(box.i[0], box.i[1]) &&
             j >= std::min(box.j[0], box.j[1]) && j <= std::max(box.j[0], box.j[1]);
    };
    expectNodes(functionWith(res, {op(TranslateOp{d}, {}, {box})}),
                [&](const Vec3& u, int i, int j, int k) { return inBox(i, j, k) ? u + d : u; });
  }
}

TEST(Operations, SelectionCenterIsTheCentroidOfSelectedNodes) {
  // Scale by 0 about the selection center collapses the selected nodes onto their centroid.
  const Index3 res{4, 4, 4};
  SelectionBox box{{0, 1}, {2, 3}, {1, 1}, SelectionOp::Or};
  const Grid u(res);
  Vec3 centroid{0.0};
  int count = 0;
  for (int i = 0; i <= 1; ++i)
    for (int j = 2; j <= 3; ++j) centroid += u.node(i, j, 1), ++count;
  centroid /= double(count);
  expectNodes(functionWith(res, {op(ScaleOp{Vec3{0.0}}, {Center::Kind::Selection, {}}, {box})}),
              [&](const Vec3& p, int i, int j, int k) { return (i <= 1 && j >= 2 && k == 1) ? centroid : p; });
}

TEST(Operations, GridCenterIsTheCentroidOfTheCurrentNodes) {
  // After a translate the grid centroid moves with it; a rotate about it keeps the centroid.
  const Vec3 d{0.3, -0.2, 0.1};
  Function f = functionWith({3, 4, 5}, {op(TranslateOp{d}), op(RotateOp{Vec3{0, 0, 90}})});
  const Grid g = evaluateFunction(f);
  Vec3 sum{0.0};
  for (const Vec3& p : g.nodes()) sum += p;
  sum /= double(g.nodeCount());
  EXPECT_NEAR(sum.x, d.x, 1e-12);
  EXPECT_NEAR(sum.y, d.y, 1e-12);
  expectNodes(f, [&](const Vec3& u, int, int, int) { return d + Vec3{-u.y, u.x, u.z}; });
  (void)centroidOfAllNodes;
}

TEST(Operations, PlacementIsTranslateRotateScale) {
  Function f = functionWith({3, 3, 3}, {});
  f.placement = {Vec3{0.1, 0.2, 0.3}, Vec3{0, 0, 90}, Vec3{0.5, 0.25, 2}};
  expectNodes(f, [](const Vec3& u, int, int, int) {
    const Vec3 s{u.x * 0.5, u.y * 0.25, u.z * 2};
    return Vec3{0.1 - s.y, 0.2 + s.x, 0.3 + s.z};
  });
}

TEST(Operations, StackEditsReevaluate) {
  Function f = functionWith({4, 4, 4},
                            {op(TranslateOp{Vec3{0.1, 0, 0}}), op(ScaleOp{Vec3{2, 2, 2}}, {Center::Kind::Point, {}})});
  // translate then scale about the origin
  expectNodes(f, [](const Vec3& u, int, int, int) { return (u + Vec3{0.1, 0, 0}) * 2.0; });
  std::swap(f.ops[0], f.ops[1]);  // reorder
  expectNodes(f, [](const Vec3& u, int, int, int) { return u * 2.0 + Vec3{0.1, 0, 0}; });
  f.ops[0].muted = true;  // mute
  expectNodes(f, [](const Vec3& u, int, int, int) { return u + Vec3{0.1, 0, 0}; });
  f.ops.erase(f.ops.begin() + 1);  // delete
  expectNodes(f, [](const Vec3& u, int, int, int) { return u; });
  std::get<ScaleOp>(f.ops[0].params).factors = Vec3{3, 1, 1};  // edit a parameter
  f.ops[0].muted = false;
  expectNodes(f, [](const Vec3& u, int, int, int) { return Vec3{3 * u.x, u.y, u.z}; });
}

TEST(Operations, TriangleWaveHasSinesPeriodAndPhase) {
  EXPECT_DOUBLE_EQ(triangleWave(0.0), 0.0);
  EXPECT_NEAR(triangleWave(M_PI / 2), 1.0, 1e-12);
  EXPECT_NEAR(triangleWave(-M_PI / 2), -1.0, 1e-12);
  EXPECT_NEAR(triangleWave(M_PI), 0.0, 1e-12);
  EXPECT_NEAR(triangleWave(M_PI / 4 + 2 * M_PI), 0.5, 1e-12);
  for (double x = -10; x < 10; x += 0.37) EXPECT_NEAR(triangleWave(x), tri(x), 1e-7);
}
