// Tone mapping of the flame display against Draves & Reckase 2003, §4 (log density) and §6 (gamma, vibrancy),
// with flam3's normalisation.
#include <gtest/gtest.h>

#include <cmath>

#include "tone/flame_tonemap.h"

using namespace gridifs;

TEST(FlameToneMap, LogDensityScaleIsFlam3sK1K2) {
  const LogDensityScale s = logDensityScale(4.0, 1e6, 100.0, 2);
  EXPECT_DOUBLE_EQ(s.k1, 4.0 * 268.0 / 256.0);
  EXPECT_DOUBLE_EQ(s.k2, (2.0 * 100.0) * (2.0 * 100.0) / 1e6);
  // Draves & Reckase 2003, §4: each channel is scaled by log(α)/α; flam3 writes it k1·log(1 + α·k2)/α.
  EXPECT_DOUBLE_EQ(s.alpha(50.0), s.k1 * std::log(1.0 + 50.0 * s.k2));
  EXPECT_DOUBLE_EQ(s.factor(50.0), s.alpha(50.0) / 50.0);
  EXPECT_EQ(s.factor(0.0), 0.0);
}

TEST(FlameToneMap, ExposureDoesNotDependOnSampleCountOrSupersampling) {
  // Twice the samples → twice the hits per bucket, and the same log-scaled alpha.
  const LogDensityScale a = logDensityScale(4.0, 1e6, 100.0, 1), b = logDensityScale(4.0, 2e6, 100.0, 1);
  EXPECT_NEAR(a.alpha(37.0), b.alpha(74.0), 1e-12);
  // 2× supersampling spreads the hits over 4 buckets; each bucket's alpha stays the same.
  const LogDensityScale c = logDensityScale(4.0, 1e6, 100.0, 2);
  EXPECT_NEAR(a.alpha(40.0), c.alpha(10.0), 1e-12);
  // The log compresses the dynamic range (Draves & Reckase 2003, §4): 10× the hits is far less than 10× brighter.
  EXPECT_LT(a.alpha(1000.0) / a.alpha(100.0), 4.0);
  EXPECT_LT(a.alpha(1e5) / a.alpha(1e4), 1.5);
}

TEST(FlameToneMap, GammaThresholdBlendsLinearIntoThePower) {
  const double g = 1.0 / 4.0, t = 0.01;
  EXPECT_DOUBLE_EQ(gammaAlpha(0.5, g, t), std::pow(0.5, g));
  EXPECT_DOUBLE_EQ(gammaAlpha(0.5, g, 0.0), std::pow(0.5, g));
  EXPECT_EQ(gammaAlpha(0.0, g, t), 0.0);
  // Continuous at the threshold, and linear (slope threshold^(g−1)) near zero.
  EXPECT_NEAR(gammaAlpha(t * (1 - 1e-9), g, t), std::pow(t, g), 1e-6);
  const double tiny = 1e-12;
  EXPECT_NEAR(gammaAlpha(tiny, g, t) / tiny, std::pow(t, g) / t, std::pow(t, g) / t * 1e-2);
  EXPECT_LT(gammaAlpha(tiny, g, t), std::pow(tiny, g));  // the pure power would amplify the noise
}

TEST(FlameToneMap, VibrancyOneAppliesTheAlphaGammaToAllChannels) {
  ToneMapParams p;
  p.gamma = 2.2;
  p.vibrancy = 1.0;
  p.gamma_threshold = 0.0;
  p.highlight_power = -1.0;
  const float in[4] = {0.2f, 0.1f, 0.05f, 0.25f};  // mean color (0.8, 0.4, 0.2), log-scaled alpha 0.25
  float out[4];
  toneMapPixel(in, p, out);
  const double alpha = std::pow(0.25, 1.0 / 2.2);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(out[c], 256.0 / 255.0 * alpha * in[c] / in[3], 1e-6);
  EXPECT_NEAR(out[0] / out[2], 4.0, 1e-5);  // hue and saturation kept (Draves & Reckase 2003, §6)
  EXPECT_EQ(out[3], 1.f);
}

TEST(FlameToneMap, VibrancyZeroIsPerChannelGammaAndWashesOut) {
  ToneMapParams p;
  p.gamma = 4.0;
  p.vibrancy = 0.0;
  p.gamma_threshold = 0.0;
  const float in[4] = {0.2f, 0.1f, 0.05f, 0.25f};
  float out[4];
  toneMapPixel(in, p, out);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(out[c], 256.0 / 255.0 * std::pow(in[c], 0.25), 1e-6);
  EXPECT_LT(out[0] / out[2], 4.0 * 0.5);  // less saturated than the vibrant version
}

TEST(FlameToneMap, BackgroundAndTransparency) {
  ToneMapParams p;
  p.background = {0.2, 0.4, 0.6};
  const float empty[4] = {0, 0, 0, 0};
  float out[4];
  toneMapPixel(empty, p, out);
  EXPECT_FLOAT_EQ(out[0], 0.2f);
  EXPECT_FLOAT_EQ(out[1], 0.4f);
  EXPECT_FLOAT_EQ(out[2], 0.6f);
  EXPECT_EQ(out[3], 1.f);
  p.transparent = true;
  toneMapPixel(empty, p, out);
  EXPECT_EQ(out[0], 0.f);
  EXPECT_EQ(out[3], 0.f);
  // A faint pixel: partial alpha, color premultiplied (never above alpha), no background.
  const float faint[4] = {0.001f, 0.0005f, 0.0005f, 0.001f};
  toneMapPixel(faint, p, out);
  EXPECT_GT(out[3], 0.f);
  EXPECT_LT(out[3], 1.f);
  for (int c = 0; c < 3; ++c) EXPECT_LE(out[c], out[3]);
  // Opaque: the same pixel is composited over the background with weight 1 − alpha.
  p.transparent = false;
  float opaque[4];
  toneMapPixel(faint, p, opaque);
  const float a = out[3];
  EXPECT_NEAR(opaque[2], out[2] + (1 - a) * 0.6f, 1e-5);
}

TEST(FlameToneMap, HighlightPowerDesaturatesInsteadOfShiftingHue) {
  const float hot[4] = {3.0f, 1.5f, 0.3f, 3.0f};  // a dense orange pixel: would exceed 1
  ToneMapParams clip;
  clip.highlight_power = -1.0;
  float clipped[4];
  toneMapPixel(hot, clip, clipped);
  EXPECT_FLOAT_EQ(clipped[0], 1.f);  // red clipped: the hue shifts toward yellow
  ToneMapParams soft;
  soft.highlight_power = 1.0;
  float softened[4];
  toneMapPixel(hot, soft, softened);
  EXPECT_NEAR(std::max({softened[0], softened[1], softened[2]}), 1.0, 1e-5);
  // Less saturated than the input color (toward white) but the same hue order.
  EXPECT_GT(softened[0], softened[1]);
  EXPECT_GT(softened[1], softened[2]);
  EXPECT_GT(softened[2] / softened[0], 0.3f / 3.0f);
  ToneMapParams none;
  none.highlight_power = 0.0;  // power 0: max-value color, saturation kept
  float kept[4];
  toneMapPixel(hot, none, kept);
  EXPECT_NEAR(kept[2] / kept[0], 0.1, 1e-4);
}

TEST(FlameToneMap, DevelopIsInvariantUnderMoreSamplesAndSupersampling) {
  // A synthetic histogram: a dense blob and a sparse tail.
  const int w = 24, h = 16;
  FlameHistogram a(w, h), twice(w, h), fine(2 * w, 2 * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int hits = (x * 7 + y * 3) % 11 == 0 ? 0 : (x + 1) * (y + 1);
      for (int n = 0; n < hits; ++n) {
        const Rgb c{0.9f, 0.5f * (x % 2), 0.2f};
        a.add(x, y, c);
        twice.add(x, y, c);
        twice.add(x, y, c);
      }
      // The same hits spread evenly over the 4 sub-buckets of a 2× supersampled histogram.
      for (int n = 0; n < hits; ++n) fine.add(2 * x + (n % 2), 2 * y + (n / 2) % 2, Rgb{0.9f, 0.5f * (x % 2), 0.2f});
    }
  FlameSettings s;
  s.estimator_radius = 0.0;
  s.filter_radius = 0.0;  // a single-tap box over the block: the comparison is exact
  const FlameImage one = developFlame(a, s, Vec3{0.0}, true, 1e4, 10.0);
  const FlameImage two = developFlame(twice, s, Vec3{0.0}, true, 2e4, 10.0);
  ASSERT_EQ(one.rgba.size(), two.rgba.size());
  for (std::size_t i = 0; i < one.rgba.size(); ++i) EXPECT_NEAR(one.rgba[i], two.rgba[i], 1e-5);
  FlameSettings s2 = s;
  s2.supersample = 2;
  const FlameImage sup = developFlame(fine, s2, Vec3{0.0}, true, 1e4, 10.0);
  ASSERT_EQ(sup.width, w);
  double sumA = 0, sumB = 0;
  for (std::size_t i = 3; i < one.rgba.size(); i += 4) sumA += one.rgba[i], sumB += sup.rgba[i];
  // Not identical (the log of 4 sub-buckets is not the log of their sum) but close in exposure.
  EXPECT_NEAR(sumB / sumA, 1.0, 0.15);
}
