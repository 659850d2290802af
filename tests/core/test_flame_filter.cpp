// The flame display's filters (Draves & Reckase 2003, §8): supersampling with a Gaussian spatial filter, and
// density estimation whose kernel shrinks as density grows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>

#include "tone/density_filter.h"

using namespace gridifs;

TEST(FlameFilter, SpatialTapsAreNormalisedSymmetricAndMatchTheSupersamplingParity) {
  for (int ss : {1, 2, 3, 4})
    for (double radius : {0.0, 0.5, 1.0, 2.5}) {
      const auto taps = spatialFilterTaps(ss, radius);
      EXPECT_EQ(int(taps.size()) % 2, ss % 2) << ss << " " << radius;
      EXPECT_NEAR(std::accumulate(taps.begin(), taps.end(), 0.0), 1.0, 1e-12);
      for (std::size_t i = 0; i < taps.size(); ++i) EXPECT_NEAR(taps[i], taps[taps.size() - 1 - i], 1e-12);
      // flam3: width 2·1.5·ss·radius (+1, parity-adjusted).
      EXPECT_GE(double(taps.size()), 2.0 * 1.5 * ss * radius);
      EXPECT_LE(double(taps.size()), 2.0 * 1.5 * ss * radius + 2.0);
    }
  const auto t = spatialFilterTaps(1, 1.0);  // Gaussian: peaked in the middle
  EXPECT_GT(t[t.size() / 2], t.front());
  EXPECT_THROW(spatialFilterTaps(0, 0.5), std::invalid_argument);
}

TEST(FlameFilter, SpatialFilterKeepsAConstantFieldAndItsEnergy) {
  const int ss = 3, w = 20, h = 12;
  AccumBuffer flat(w * ss, h * ss);
  for (std::size_t i = 0; i < flat.data.size(); ++i) flat.data[i] = 0.25f;
  const AccumBuffer out = spatialFilterDown(flat, ss, 1.0, w, h, 2);
  ASSERT_EQ(out.width, w);
  for (int y = 3; y < h - 3; ++y)
    for (int x = 3; x < w - 3; ++x)
      for (int c = 0; c < 4; ++c) EXPECT_NEAR(out.at(x, y)[c], 0.25f, 1e-5);
  // An isolated bucket: the output's total is the bucket's value / ss² (one output pixel
  // averages ss² buckets).
  AccumBuffer dot(w * ss, h * ss);
  dot.at(30, 18)[3] = 9.0f;
  const AccumBuffer blurred = spatialFilterDown(dot, ss, 1.0, w, h, 1);
  double total = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) total += blurred.at(x, y)[3];
  EXPECT_NEAR(total, 9.0 / (ss * ss), 0.05);
  EXPECT_THROW(spatialFilterDown(dot, 2, 1.0, w, h), std::invalid_argument);
}

TEST(FlameFilter, DensityEstimatorKernelsShrinkAsDensityGrows) {
  const double radius = 9.0, curve = 0.4;
  for (int ss : {1, 2}) {
    const DensityEstimator de(radius, 0.0, curve, ss);
    // One hit: the widest kernel, R·ss + 1 buckets.
    EXPECT_EQ(de.kernelIndex(1.0), 0);
    EXPECT_DOUBLE_EQ(de.kernelWidth(0), radius * ss + 1.0);
    // Below flam3's threshold, width = (R·ss + 1)/hits^curve (Draves & Reckase 2003, §8: inversely related to density).
    for (int hits : {2, 5, 20, 50}) {
      const int k = de.kernelIndex(hits);
      EXPECT_EQ(k, hits - 1);
      EXPECT_NEAR(de.kernelWidth(k), std::max(1.0, (radius * ss + 1.0) / std::pow(hits, curve)), 1e-9);
    }
    double previous = 1e9;
    for (int k = 0; k < de.kernelCount(); ++k) {
      EXPECT_LE(de.kernelWidth(k), previous);
      previous = de.kernelWidth(k);
      double sum = 0;
      const int reach = int(std::ceil(de.kernelWidth(k))) - 1;
      for (const auto& t : de.taps(k)) {
        sum += t.weight;
        EXPECT_LE(std::hypot(t.dx, t.dy), de.kernelWidth(k) + 1e-9);
        EXPECT_LE(std::max(std::abs(t.dx), std::abs(t.dy)), reach);
      }
      // flam3 normalises over |d| <= h but applies offsets up to ceil(h) - 1 only.
      EXPECT_LE(sum, 1.0 + 1e-5);
      EXPECT_GT(sum, 0.95);
      if (de.kernelWidth(k) >= 3.0) {
        EXPECT_NEAR(sum, 1.0, 2e-3);
      }
    }
    // Very dense buckets get the narrowest kernel (minimum 0 → width 1): the bucket alone.
    EXPECT_EQ(de.kernelIndex(1e9), de.kernelCount() - 1);
    EXPECT_DOUBLE_EQ(de.kernelWidth(de.kernelCount() - 1), 1.0);
    ASSERT_EQ(de.taps(de.kernelCount() - 1).size(), 1u);
    EXPECT_NEAR(de.taps(de.kernelCount() - 1)[0].weight, 1.0 / (1.0 + 4.0 * std::exp(-4.5)), 1e-6);
  }
  const DensityEstimator withMinimum(9.0, 2.0, 0.4, 1);
  EXPECT_DOUBLE_EQ(withMinimum.kernelWidth(withMinimum.kernelIndex(1e9)), 3.0);
  EXPECT_THROW(DensityEstimator(1.0, 2.0, 0.4, 1), std::invalid_argument);
  EXPECT_THROW(DensityEstimator(9.0, 0.0, 0.0, 1), std::invalid_argument);
}

TEST(FlameFilter, DensityEstimationSmoothsSparseBucketsAndKeepsDenseOnesSharp) {
  const int w = 64, h = 64;
  FlameHistogram hist(w, h);
  const Rgb white{1, 1, 1};
  hist.add(16, 32, white);                                 // one lonely sample
  for (int n = 0; n < 5000; ++n) hist.add(48, 32, white);  // a dense bucket
  const LogDensityScale scale = logDensityScale(4.0, 1e5, 20.0, 1);
  const DensityEstimator de(9.0, 0.0, 0.4, 1);
  const AccumBuffer plain = logScaleAndEstimate(hist, scale, nullptr);
  const AccumBuffer est = logScaleAndEstimate(hist, scale, &de);
  auto total = [&](const AccumBuffer& b, int x0, int x1) {
    double t = 0;
    for (int y = 0; y < h; ++y)
      for (int x = x0; x < x1; ++x) t += b.at(x, y)[3];
    return t;
  };
  // Energy is conserved by the wide kernels, and kept within flam3's ~4% by the narrowest one.
  EXPECT_NEAR(total(est, 0, 32), total(plain, 0, 32), 2e-3 * total(plain, 0, 32));
  EXPECT_NEAR(total(est, 32, 64), total(plain, 32, 64), 0.05 * total(plain, 32, 64));
  // The lonely sample is spread wide: its centre keeps a small fraction, a pixel 6 away gets some.
  EXPECT_LT(est.at(16, 32)[3], 0.05 * plain.at(16, 32)[3]);
  EXPECT_GT(est.at(22, 32)[3], 0.0f);
  // The dense bucket stays sharp: it stays in place, nothing reaches its neighbours.
  EXPECT_GT(est.at(48, 32)[3], 0.9 * plain.at(48, 32)[3]);
  EXPECT_EQ(est.at(49, 32)[3], 0.0f);
  // Colors keep their ratio to alpha.
  EXPECT_NEAR(est.at(48, 32)[0], est.at(48, 32)[3], 1e-4);
}
