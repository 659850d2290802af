// Colonna's fractal field (superposed random meshes, n-linear and pseudo n-cubic interpolation,
// the modulo mapping of §3.2): exactness at vertices, bilinear reproduction, bounds,
// periodicity, continuity and determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "field/fractal_field.h"

using namespace gridifs;

namespace {

FractalFieldParams oneLevel(FieldInterpolation interpolation) {
  FractalFieldParams p;
  p.octaves = 1;
  p.scale = 0.25;
  p.seed = 11;
  p.interpolation = interpolation;
  p.amplitude = {1.0, 1.0, 1.0};
  return p;
}

FieldPoint vertex(const FractalField::MeshGeometry& g, std::array<int, 4> index) {
  FieldPoint s{};
  for (int d = 0; d < 4; ++d) s[d] = g.origin[d] + index[d] * g.cell[d];
  return s;
}

FieldPoint randomPoint(std::mt19937_64& rng, double extent) {
  std::uniform_real_distribution<double> u(-extent, extent);
  return {u(rng), u(rng), u(rng), u(rng)};
}

}  // namespace

TEST(FractalField, OneLevelTakesItsRandomValuesAtTheVertices) {
  // Both interpolations pass through the vertex values (the cubic's a0 = f(V0)), so they agree
  // there and differ in between.
  const FractalField linear(oneLevel(FieldInterpolation::Linear));
  const FractalField cubic(oneLevel(FieldInterpolation::Cubic));
  const auto g = linear.mesh(1);
  EXPECT_DOUBLE_EQ(g.weight, 1.0);
  int differentInside = 0;
  for (int i = -3; i <= 3; ++i) {
    for (int j = -2; j <= 2; ++j) {
      const FieldPoint v = vertex(g, {i, j, i + j, 2 * j});
      const double a = linear.value(0, v);
      EXPECT_NEAR(a, cubic.value(0, v), 1e-12);
      EXPECT_GE(a, -1.0);
      EXPECT_LE(a, 1.0);
      FieldPoint inside = v;
      inside[0] += 0.37 * g.cell[0];
      inside[3] += 0.61 * g.cell[3];
      if (std::abs(linear.value(0, inside) - cubic.value(0, inside)) > 1e-6) ++differentInside;
    }
  }
  EXPECT_GT(differentInside, 20);
}

TEST(FractalField, LinearInterpolationReproducesBilinearDataExactly) {
  const FractalField field(oneLevel(FieldInterpolation::Linear));
  const auto g = field.mesh(1);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const std::array<int, 4> base{trial % 7 - 3, trial % 5 - 2, trial % 3, trial % 11 - 5};
    const double u = unit(rng), v = unit(rng);
    // A face of a cell in the (y, t) plane: the field there is the bilinear blend of its corners.
    const double f00 = field.value(1, vertex(g, base));
    const double f10 = field.value(1, vertex(g, {base[0], base[1] + 1, base[2], base[3]}));
    const double f01 = field.value(1, vertex(g, {base[0], base[1], base[2], base[3] + 1}));
    const double f11 = field.value(1, vertex(g, {base[0], base[1] + 1, base[2], base[3] + 1}));
    FieldPoint s = vertex(g, base);
    s[1] += u * g.cell[1];
    s[3] += v * g.cell[3];
    const double expected = (1 - u) * (1 - v) * f00 + u * (1 - v) * f10 + (1 - u) * v * f01 + u * v * f11;
    EXPECT_NEAR(field.value(1, s), expected, 1e-12);
  }
}

TEST(FractalField, WeightsFollowTheGainAndSumToOne) {
  FractalFieldParams p;
  p.octaves = 5;
  p.gain = 0.6;
  const FractalField field(p);
  double total = 0.0;
  for (int k = 1; k <= 5; ++k) {
    total += field.mesh(k).weight;
    if (k > 1) {
      EXPECT_NEAR(field.mesh(k).weight / field.mesh(k - 1).weight, 0.6, 1e-12);
    }
    EXPECT_NEAR(field.mesh(k).cell[0], p.scale * std::pow(p.ratio, k - 1), 1e-15);
  }
  EXPECT_NEAR(total, 1.0, 1e-12);
}

TEST(FractalField, MeshesOfDifferentLevelsDoNotShareVertices) {
  FractalFieldParams p;
  p.octaves = 8;
  const FractalField field(p);
  for (int k = 2; k <= 8; ++k) {
    const auto fine = field.mesh(k), coarse = field.mesh(k - 1);
    // The coarse origin, in fine cells, must not be a whole number in every dimension.
    int aligned = 0;
    for (int d = 0; d < 4; ++d) {
      const double cells = (coarse.origin[d] - fine.origin[d]) / fine.cell[d];
      if (std::abs(cells - std::round(cells)) < 1e-6) ++aligned;
    }
    EXPECT_LT(aligned, 4) << "level " << k;
  }
}

TEST(FractalField, StaysWithinItsBound) {
  for (const auto interpolation : {FieldInterpolation::Linear, FieldInterpolation::Cubic}) {
    FractalFieldParams p;
    p.interpolation = interpolation;
    p.octaves = 6;
    p.amplitude = {0.2, 0.1, 0.05};
    const FractalField field(p);
    std::mt19937_64 rng(9);
    double largest = 0.0;
    for (int i = 0; i < 4000; ++i) {
      const FieldPoint s = randomPoint(rng, 3.0);
      const Vec3 d = field.displacement({s[0], s[1], s[2]}, s[3]);
      EXPECT_LE(std::abs(d.x), 0.2 * field.bound() + 1e-12);
      EXPECT_LE(std::abs(d.y), 0.1 * field.bound() + 1e-12);
      EXPECT_LE(std::abs(d.z), 0.05 * field.bound() + 1e-12);
      largest = std::max(largest, std::abs(field.value(0, s)));
    }
    EXPECT_GT(largest, 0.3);  // a field, not a constant
  }
}

TEST(FractalField, PeriodicInTimeAndSpaceAndContinuousAcrossTheWrap) {
  FractalFieldParams p;
  p.octaves = 7;
  p.period = {2.0, 0.0, 0.0, 4.0};
  p.wind = {0.5, 0.0, 0.0};  // wind·Lt = 2 = Lx: the loop also closes with the wind
  const FractalField field(p);
  std::mt19937_64 rng(3);
  for (int i = 0; i < 500; ++i) {
    const FieldPoint s = randomPoint(rng, 1.0);
    const Vec3 q{s[0], s[1], s[2]};
    const Vec3 a = field.displacement(q, s[3]);
    const Vec3 b = field.displacement(q, s[3] + 4.0);
    const Vec3 c = field.displacement(q + Vec3{2.0, 0.0, 0.0}, s[3]);
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_NEAR(a[axis], b[axis], 1e-9);
      EXPECT_NEAR(a[axis], c[axis], 1e-9);
    }
  }
  // No seam at the wrap: just before t = Lt and just after t = 0 the field is close.
  for (int i = 0; i < 200; ++i) {
    const FieldPoint s = randomPoint(rng, 1.0);
    const Vec3 q{s[0], s[1], s[2]};
    const Vec3 before = field.displacement(q, 4.0 - 1e-7);
    const Vec3 after = field.displacement(q, 1e-7);
    for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(before[axis], after[axis], 1e-4);
  }
}

TEST(FractalField, ContinuousInTime) {
  for (const auto interpolation : {FieldInterpolation::Linear, FieldInterpolation::Cubic}) {
    FractalFieldParams p;
    p.interpolation = interpolation;
    p.octaves = 8;
    const FractalField field(p);
    std::mt19937_64 rng(4);
    for (int i = 0; i < 500; ++i) {
      const FieldPoint s = randomPoint(rng, 2.0);
      const Vec3 q{s[0], s[1], s[2]};
      const Vec3 a = field.displacement(q, s[3]);
      const Vec3 b = field.displacement(q, s[3] + 1e-7);
      // The finest cell is 0.5·0.5^7 ≈ 0.004, so slopes are at most ~2/0.004 per unit time.
      for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(a[axis], b[axis], 1e-7 * 0.1 * 2.0 / 0.0039 * 2.0);
    }
  }
}

TEST(FractalField, DeterministicPerSeedAndDifferentAcrossSeedsAndAxes) {
  FractalFieldParams p;
  p.seed = 42;
  const FractalField a(p), b(p);
  p.seed = 43;
  const FractalField c(p);
  std::mt19937_64 rng(8);
  int differentSeed = 0, differentAxis = 0;
  for (int i = 0; i < 100; ++i) {
    const FieldPoint s = randomPoint(rng, 1.0);
    EXPECT_EQ(a.value(0, s), b.value(0, s));
    if (a.value(0, s) != c.value(0, s)) ++differentSeed;
    if (a.value(0, s) != a.value(1, s)) ++differentAxis;
  }
  EXPECT_EQ(differentSeed, 100);
  EXPECT_EQ(differentAxis, 100);
  // Seed S+1's first axis is seed S's second axis (one field per axis: seeds S, S+1, S+2).
  const FieldPoint s{0.1, 0.2, 0.3, 0.4};
  EXPECT_EQ(a.value(1, s), c.value(0, s));
}

TEST(FractalField, KnownValuesAreStableAcrossMachines) {
  // RDN is integer hashing plus IEEE arithmetic: these digits must not change between builds.
  FractalFieldParams p;
  p.octaves = 3;
  p.seed = 7;
  p.interpolation = FieldInterpolation::Linear;
  const FractalField field(p);
  // Recorded when RDN became one half of a 32-bit hash shared by a pair of seeds (one round of
  // lowbias32 over the vertex's index shares plus the pair's key): seed 7 reads the lower half,
  // seed 8 (axis 1) the upper one. A change here changes every saved animation.
  EXPECT_NEAR(field.value(0, {0.125, -0.25, 0.5, 1.0}), -0.053617217368504083, 1e-15);
  EXPECT_NEAR(field.value(1, {0.125, -0.25, 0.5, 1.0}), 0.044519279950097877, 1e-15);
}

TEST(FractalField, VertexValuesAreUniformAndUncorrelated) {
  // RDN is a hash, so its values at the vertices should look like independent uniform draws on
  // [-1, 1]: mean 0, variance 1/3, no correlation with the neighbouring vertex along any
  // dimension, none between the axes (seeds S and S+1), none between vertices far apart.
  const FractalField field(oneLevel(FieldInterpolation::Linear));
  const auto g = field.mesh(1);
  const int n = 24000;
  double sum = 0.0, square = 0.0, axes = 0.0, far = 0.0;
  std::array<double, 4> neighbour{};
  double lowest = 1.0, highest = -1.0;
  for (int i = 0; i < n; ++i) {
    const std::array<int, 4> index{i % 29 - 14, (i / 29) % 31 - 15, (i / 899) % 5 + 300, i / 4495 - 2};
    const double v = field.value(0, vertex(g, index));
    sum += v;
    square += v * v;
    lowest = std::min(lowest, v);
    highest = std::max(highest, v);
    axes += v * field.value(1, vertex(g, index));
    for (int d = 0; d < 4; ++d) {
      std::array<int, 4> next = index;
      ++next[d];
      neighbour[d] += v * field.value(0, vertex(g, next));
    }
    // Hundreds of cells away along every dimension: the hash must not repeat there.
    far += v * field.value(0, vertex(g, {index[0] + 256, index[1] - 256, index[2] + 256, index[3] + 256}));
  }
  // Sample correlations of n independent uniform pairs have a standard deviation of about
  // (1/3)/sqrt(n) ≈ 0.002 here; the bounds are 10 of those.
  EXPECT_NEAR(sum / n, 0.0, 0.02);
  EXPECT_NEAR(square / n, 1.0 / 3.0, 0.02);
  EXPECT_LT(lowest, -0.99);
  EXPECT_GT(highest, 0.99);
  EXPECT_NEAR(axes / n, 0.0, 0.02);
  EXPECT_NEAR(far / n, 0.0, 0.02);
  for (int d = 0; d < 4; ++d) EXPECT_NEAR(neighbour[d] / n, 0.0, 0.02) << "dimension " << d;
}

TEST(FractalField, VertexValuesShowNoStructureInTheirHistogramOrMagnitudes) {
  // Stricter than uncorrelated values: a hash with too little mixing can give values that are
  // uncorrelated yet not independent (a lumpy histogram, magnitudes that go together, two seeds
  // that share a hash and mirror each other). Seed 11's axes are seeds 11, 12, 13; 12 and 13
  // are the two halves of one hash.
  const FractalField field(oneLevel(FieldInterpolation::Linear));
  const auto g = field.mesh(1);
  const int n = 24000;
  constexpr int kBins = 16;
  std::array<std::array<int, kBins>, 3> histogram{};
  // Products of v² - 1/3 (zero mean for uniform values, variance 4/45): for the neighbour along
  // each dimension, for the two steps along time that pair up nothing, for each pair of axes.
  std::array<double, 4> neighbour{};
  std::array<double, 3> axes{};
  double twoSteps = 0.0;
  const auto square = [](double v) { return v * v - 1.0 / 3.0; };
  for (int i = 0; i < n; ++i) {
    const std::array<int, 4> index{i % 31 - 15, (i / 31) % 29 - 14, (i / 899) % 5 - 700, i / 4495 + 40};
    std::array<double, 3> v{};
    for (int a = 0; a < 3; ++a) {
      v[a] = field.value(a, vertex(g, index));
      ++histogram[a][std::min(kBins - 1, int((v[a] + 1.0) * 0.5 * kBins))];
    }
    for (int a = 0; a < 3; ++a) axes[a] += square(v[a]) * square(v[(a + 1) % 3]);
    for (int d = 0; d < 4; ++d) {
      std::array<int, 4> next = index;
      ++next[d];
      neighbour[d] += square(v[0]) * square(field.value(0, vertex(g, next)));
    }
    twoSteps += square(v[1]) * square(field.value(1, vertex(g, {index[0], index[1], index[2], index[3] + 2})));
  }
  // Chi-square over 16 bins: 15 degrees of freedom, mean 15, standard deviation 5.5; 60 is
  // beyond 8 of them.
  for (int a = 0; a < 3; ++a) {
    double chi2 = 0.0;
    for (int count : histogram[a])
      chi2 += (count - n / double(kBins)) * (count - n / double(kBins)) / (n / double(kBins));
    EXPECT_LT(chi2, 60.0) << "axis " << a;
  }
  // The means of the products have a standard deviation of (4/45)/sqrt(n) ≈ 0.0006; the bounds
  // are 10 of those.
  for (int d = 0; d < 4; ++d) EXPECT_NEAR(neighbour[d] / n, 0.0, 0.006) << "dimension " << d;
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(axes[a] / n, 0.0, 0.006) << "axes " << a << ", " << (a + 1) % 3;
  EXPECT_NEAR(twoSteps / n, 0.0, 0.006);
}
