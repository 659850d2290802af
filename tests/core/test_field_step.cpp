// The per-time-step evaluation of a fractal field over many nodes (collapsed meshes, per-node
// hashing, interpolation one dimension at a time over tensor grids) gives the values of the
// point-by-point evaluation, up to rounding, on scattered points, on grids and under a mask.
// The step sums the tensor passes and the per-node weights in single precision, so "up to
// rounding" means about 1e-7 of the amplitude (the point-by-point field is in double).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#include "field/fractal_field.h"
#include "model/grid.h"

using namespace gridifs;

namespace {

// Enough octaves that the coarse meshes are collapsed into a box and the fine ones hashed per
// node; wind and periods in space and time so wrapped vertices are read too.
FractalFieldParams windyField(FieldInterpolation interpolation, std::uint64_t seed = 41) {
  FractalFieldParams p;
  p.amplitude = {1.0, 0.5, 2.0};
  p.scale = 0.5;
  p.ratio = 0.5;
  p.octaves = 8;
  p.gain = 0.7;
  p.interpolation = interpolation;
  p.seed = seed;
  p.wind = {0.3, -0.2, 0.15};
  p.period = {1.7, 0.0, 2.3, 3.0};
  return p;
}

// The largest difference between displaceNodes and displacement node by node.
double largestDeviation(const FractalField& field, const std::vector<Vec3>& points,
                        const std::vector<unsigned char>& mask, double t, int threads) {
  std::vector<Vec3> fast = points;
  field.displaceNodes(fast, mask, t, threads);
  double worst = 0.0;
  for (std::size_t n = 0; n < points.size(); ++n) {
    const Vec3 expected = mask[n] ? points[n] + field.displacement(points[n], t) : points[n];
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(fast[n][c] - expected[c]));
  }
  return worst;
}

const FieldInterpolation kBoth[] = {FieldInterpolation::Linear, FieldInterpolation::Cubic};

// Single-precision sums: a few units of 2^-24 of each level's values, weighted, over the largest
// amplitude (2); 2^-20 of it leaves an order of magnitude of margin, and is still far below any
// displacement one could see.
constexpr double kRounding = 2.0 * 0x1.0p-20;
const double kTimes[] = {0.0, 0.37, -1.3, 5.1};

}  // namespace

TEST(FieldStep, EqualsThePointByPointFieldOnScatteredPoints) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(-1.2, 1.2);
  std::vector<Vec3> points(3000);
  for (Vec3& q : points) q = {coordinate(random), coordinate(random), coordinate(random)};
  const std::vector<unsigned char> mask(points.size(), 1);
  // An odd seed reads the lower half of its pair's hash for the first axis, an even one the upper.
  for (std::uint64_t seed : {41u, 40u})
    for (FieldInterpolation interpolation : kBoth) {
      const FractalField field(windyField(interpolation, seed));
      for (double t : kTimes)
        EXPECT_LE(largestDeviation(field, points, mask, t, 2), kRounding)
            << toString(interpolation) << t << " " << seed;
    }
}

TEST(FieldStep, EqualsThePointByPointFieldOnGrids) {
  for (FieldInterpolation interpolation : kBoth) {
    const FractalField field(windyField(interpolation));
    for (const Index3& resolution : {Index3{20, 17, 23}, Index3{33, 29, 2}, Index3{40, 3, 40}, Index3{64, 6, 5}}) {
      const Grid grid(resolution);
      const std::vector<unsigned char> mask(grid.nodes().size(), 1);
      for (double t : kTimes)
        EXPECT_LE(largestDeviation(field, grid.nodes(), mask, t, 2), kRounding)
            << toString(interpolation) << " " << resolution[0] << "x" << resolution[1] << "x" << resolution[2] << " "
            << t;
    }
  }
}

TEST(FieldStep, MovesOnlyTheSelectedNodes) {
  const Grid grid({24, 20, 16});
  std::vector<unsigned char> mask(grid.nodes().size(), 0);
  for (std::size_t n = 0; n < mask.size(); n += 3) mask[n] = 1;
  for (FieldInterpolation interpolation : kBoth) {
    const FractalField field(windyField(interpolation));
    EXPECT_LE(largestDeviation(field, grid.nodes(), mask, 0.8, 2), kRounding) << toString(interpolation);
  }
}

TEST(FieldStep, DistortedGridsTakeTheGeneralPath) {
  // A grid whose nodes are not an axis-aligned tensor grid any more (after a twist, say).
  Grid grid({18, 18, 18});
  for (Vec3& q : grid.nodes()) q = {q.x + 0.1 * q.y * q.z, q.y - 0.05 * q.x, q.z + 0.02 * q.x * q.y};
  const std::vector<unsigned char> mask(grid.nodes().size(), 1);
  for (FieldInterpolation interpolation : kBoth) {
    const FractalField field(windyField(interpolation));
    EXPECT_LE(largestDeviation(field, grid.nodes(), mask, 2.2, 1), kRounding) << toString(interpolation);
  }
}

TEST(FieldStep, NodesThatBlewUpDoNotDisturbTheOthers) {
  // A previous op may leave infinite or undefined nodes, or nodes very far away.
  Grid grid({12, 12, 12});
  std::vector<Vec3> points = grid.nodes();
  points[5] = {std::numeric_limits<double>::infinity(), 0.0, 0.0};
  points[77] = {0.0, std::nan(""), 0.0};
  points[300] = {1e15, -1e15, 3.0};
  const std::vector<unsigned char> mask(points.size(), 1);
  for (FieldInterpolation interpolation : kBoth) {
    const FractalField field(windyField(interpolation));
    std::vector<Vec3> fast = points;
    field.displaceNodes(fast, mask, 0.4, 2);
    for (std::size_t n = 0; n < points.size(); ++n) {
      if (n == 5 || n == 77 || n == 300) continue;
      const Vec3 expected = points[n] + field.displacement(points[n], 0.4);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(fast[n][c], expected[c], kRounding) << n;
    }
  }
}

TEST(FieldStep, GivesTheSameBitsOnEveryProcessor) {
  // The step's kernels are built for AVX-512, AVX2 and plain x86-64, and the loader picks one by
  // the processor; each does the same single-precision operations in the same order, fusing only
  // where std::fma says so (correctly rounded in hardware and in the C library alike). So the
  // displaced nodes must hash to the digest recorded on an AVX-512 machine, which the AVX2 build
  // (under valgrind) and a build without the clones gave too. A change here changes every saved
  // animation by rounding.
  std::uint64_t digest = 1469598103934665603ull;  // FNV-1a over the nodes' bits
  for (FieldInterpolation interpolation : kBoth) {
    const FractalField field(windyField(interpolation));
    const Grid grid({20, 17, 23});
    std::vector<Vec3> distorted = grid.nodes();
    for (std::size_t n = 0; n < distorted.size(); n += 7) distorted[n].x += 0.001 * double(n % 13);
    const std::vector<unsigned char> mask(distorted.size(), 1);
    for (const std::vector<Vec3>& start : {grid.nodes(), distorted}) {
      std::vector<Vec3> nodes = start;
      field.displaceNodes(nodes, mask, 0.37, 1);
      for (const Vec3& q : nodes)
        for (int c = 0; c < 3; ++c) {
          std::uint64_t bits = 0;
          std::memcpy(&bits, &q[c], sizeof bits);
          digest = (digest ^ bits) * 1099511628211ull;
        }
    }
  }
  EXPECT_EQ(digest, 0x1bd92bdbcce989e4ull) << std::hex << digest;
}
