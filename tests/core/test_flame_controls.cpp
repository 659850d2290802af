// The flame controls artists reach for: hue rotation, palette gradients, quality, the linear and
// binary displays of Draves & Reckase 2003 (figure 3), the density histogram (figure 4) and the
// directional motion blur (§9), with the project file's new fields.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "io/project_io.h"
#include "render/motion_blur.h"
#include "schema/settings_tables.h"
#include "tone/density_histogram.h"
#include "tone/flame_tonemap.h"
#include "tone/palette_gradient.h"

using namespace gridifs;

namespace {

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("gridifs-flame-controls-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace

TEST(FlameHue, TurnsAKnownColourAThirdOfACircle) {
  FlameSettings f;
  f.palette_keys = "0:#ff0000 1:#ff0000";  // pure red everywhere
  f.hue = 1.0 / 3.0;                       // red → green (120°)
  const Palette p = resolveFlamePalette(f);
  EXPECT_NEAR(p.colors[0].r, 0.f, 1e-6);
  EXPECT_NEAR(p.colors[0].g, 1.f, 1e-6);
  EXPECT_NEAR(p.colors[0].b, 0.f, 1e-6);
  f.hue = 0.5;  // orange (hue 30.1°) → azure (210.1°): the green channel mirrors, 128 → 127
  f.palette_keys = "0:#ff8000 1:#ff8000";
  const Rgb c = resolveFlamePalette(f).colors[10];
  EXPECT_NEAR(c.r, 0.f, 1e-6);
  EXPECT_NEAR(c.g, 127.f / 255.f, 1e-6);
  EXPECT_NEAR(c.b, 1.f, 1e-6);
  f.hue = 0.0;  // no turn: the palette as it is
  EXPECT_EQ(resolveFlamePalette(f).colors, paletteFromKeys(*parsePaletteKeys(f.palette_keys)).colors);
}

TEST(PaletteGradient, InterpolatesLinearlyBetweenKeys) {
  const Palette p = paletteFromKeys({{0.0, 0.f, 0.f, 0.f}, {1.0, 1.f, 1.f, 1.f}});
  for (int i : {0, 1, 64, 128, 255}) EXPECT_NEAR(p.colors[std::size_t(i)].g, i / 255.f, 1e-6) << i;
  // Unsorted keys, colour held beyond the ends, a key in the middle.
  const Palette q = paletteFromKeys({{0.75, 0.f, 0.f, 1.f}, {0.25, 1.f, 0.f, 0.f}, {0.5, 0.f, 1.f, 0.f}});
  EXPECT_EQ(q.colors[0], (Rgb{1.f, 0.f, 0.f}));
  EXPECT_EQ(q.colors[255], (Rgb{0.f, 0.f, 1.f}));
  const double t = 100 / 255.0;  // between 0.25 and 0.5
  const float f = float((t - 0.25) / 0.25);
  EXPECT_NEAR(q.colors[100].r, 1.f - f, 1e-6);
  EXPECT_NEAR(q.colors[100].g, f, 1e-6);
  // Keys sampled from a palette give the palette back where they sit.
  const std::vector<PaletteKey> keys = keysFromPalette(q, 5);
  ASSERT_EQ(keys.size(), 5u);
  EXPECT_DOUBLE_EQ(keys[2].position, 0.5);
  EXPECT_EQ((Rgb{keys[4].r, keys[4].g, keys[4].b}), q.colors[255]);
}

TEST(PaletteGradient, KeysTextRoundTripsAndRefusesNonsense) {
  const std::vector<PaletteKey> keys = {{0.0, 0.f, 0.f, 0.f}, {0.5, 1.f, 128.f / 255.f, 0.f}, {1.0, 1.f, 1.f, 1.f}};
  const std::string text = formatPaletteKeys(keys);
  EXPECT_EQ(text, "0:#000000 0.5:#ff8000 1:#ffffff");
  EXPECT_EQ(parsePaletteKeys(text), keys);
  for (const char* bad : {"", "0:#000000", "0:#00000 1:#ffffff", "2:#000000 1:#ffffff", "a:#000000 1:#fff",
                          "0:000000 1:#ffffff", "0:#gg0000 1:#ffffff"})
    EXPECT_FALSE(parsePaletteKeys(bad)) << bad;
  EXPECT_TRUE(isPaletteKeysSyntax(""));
}

TEST(PaletteGradient, SavedFileLoadsAsTheSamePaletteAndKeys) {
  const auto dir = scratch("save");
  const std::vector<PaletteKey> keys = {{0.0, 0.1f, 0.2f, 0.3f}, {0.4, 1.f, 0.5f, 0.f}, {1.0, 0.f, 0.f, 1.f}};
  const std::string reference = savePaletteGradient(dir, "sunrise", keys);
  EXPECT_EQ(reference, "file:sunrise.palette.json");
  ASSERT_TRUE(std::filesystem::exists(dir / "sunrise.palette.json"));
  const Palette loaded = resolvePalette(reference, dir);
  const Palette expected = paletteFromKeys(keys);
  for (int i = 0; i < Palette::kSize; ++i) {
    EXPECT_NEAR(loaded.colors[std::size_t(i)].r, expected.colors[std::size_t(i)].r, 1e-4);
    EXPECT_NEAR(loaded.colors[std::size_t(i)].b, expected.colors[std::size_t(i)].b, 1e-4);
  }
  FlameSettings f;
  f.palette = reference;
  const std::vector<PaletteKey> reopened = keysToEdit(f, dir);
  ASSERT_EQ(reopened.size(), keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) {
    EXPECT_NEAR(reopened[i].position, keys[i].position, 1e-6);
    EXPECT_NEAR(reopened[i].g, keys[i].g, 1e-4);
  }
  EXPECT_THROW(savePaletteGradient(dir, "../escape", keys), PaletteError);
  EXPECT_THROW(savePaletteGradient(dir, "one", {keys[0]}), PaletteError);
  // A palette without keys starts the editor from 16 keys sampled from it.
  f.palette = "ember";
  EXPECT_EQ(keysToEdit(f).size(), 16u);
  std::filesystem::remove_all(dir);
}

TEST(DensityDisplay, LinearAndBinaryValues) {
  FlameSettings f;
  f.brightness = 2.0;
  f.density_display = "linear";
  const LogDensityScale linear = densityScale(f, 1e6, 100.0, 400.0);
  EXPECT_EQ(linear.display, DensityDisplay::Linear);
  // Draves & Reckase 2003, figure 3b: hits over the densest bucket's, times the brightness.
  EXPECT_DOUBLE_EQ(linear.alpha(400.0), 2.0);
  EXPECT_DOUBLE_EQ(linear.alpha(100.0), 0.5);
  EXPECT_DOUBLE_EQ(linear.factor(100.0), 0.5 / 100.0);
  EXPECT_EQ(linear.alpha(0.0), 0.0);
  f.density_display = "binary";
  const LogDensityScale binary = densityScale(f, 1e6, 100.0, 400.0);
  // Figure 3a: membership only.
  for (double hits : {1.0, 3.0, 400.0}) EXPECT_DOUBLE_EQ(binary.alpha(hits), 1.0);
  EXPECT_EQ(binary.alpha(0.0), 0.0);
  f.density_display = "log";
  const LogDensityScale log = densityScale(f, 1e6, 100.0, 400.0);
  EXPECT_DOUBLE_EQ(log.alpha(50.0), logDensityScale(2.0, 1e6, 100.0, 1).alpha(50.0));
}

TEST(DensityDisplay, BinaryDevelopsEveryHitPixelToFullAlpha) {
  FlameHistogram h(4, 1);
  h.add(0, 0, {1.f, 0.f, 0.f});
  for (int i = 0; i < 1000; ++i) h.add(2, 0, {0.f, 1.f, 0.f});
  FlameSettings f;
  f.estimator_radius = 0.0;
  f.filter_radius = 0.0;
  f.density_display = "binary";
  const FlameImage binary = developFlame(h, f, Vec3(0.0), true, 1001.0, 1.0);
  EXPECT_NEAR(binary.pixel(0, 0)[3], 1.f, 1e-3);
  EXPECT_NEAR(binary.pixel(2, 0)[3], 1.f, 1e-3);
  EXPECT_EQ(binary.pixel(1, 0)[3], 0.f);
  f.density_display = "linear";
  f.brightness = 1.0;
  f.gamma = 1.0;
  const FlameImage linear = developFlame(h, f, Vec3(0.0), true, 1001.0, 1.0);
  EXPECT_NEAR(linear.pixel(2, 0)[3], 1.f, 1e-3);           // the densest pixel is white
  EXPECT_NEAR(linear.pixel(0, 0)[3], 1.f / 1000.f, 2e-4);  // 1 hit of 1000: nearly black
}

TEST(DensityHistogramTest, CountsPixelsInPowerOfTwoBins) {
  const std::vector<std::uint32_t> hits = {0, 0, 1, 2, 3, 4, 7, 8, 1000};
  const DensityHistogram h = densityHistogram(hits);
  EXPECT_EQ(h.empty, 2);
  EXPECT_EQ(h.maxHits, 1000u);
  ASSERT_EQ(h.bins.size(), 10u);  // 1000 is in [512, 1024)
  EXPECT_EQ(h.bins[0], 1);        // 1
  EXPECT_EQ(h.bins[1], 2);        // 2, 3
  EXPECT_EQ(h.bins[2], 2);        // 4, 7
  EXPECT_EQ(h.bins[3], 1);        // 8
  EXPECT_EQ(h.bins[9], 1);        // 1000
  EXPECT_EQ(h.total(), std::int64_t(hits.size()));
  EXPECT_TRUE(densityHistogram(std::vector<std::uint32_t>{0, 0}).bins.empty());
}

TEST(DensityHistogramTest, ThresholdAndSaturationOnTheDensityAxis) {
  const LogDensityScale s = logDensityScale(4.0, 1e6, 100.0, 1);
  for (double a : {0.01, 0.5, 1.0, 3.0}) EXPECT_NEAR(s.alpha(hitsForAlpha(s, a)), a, 1e-9) << a;
  // The tone curve reaches 1 where alpha reaches 1, and is the gamma power above the threshold.
  EXPECT_NEAR(toneCurve(s, 4.0, 0.01, hitsForAlpha(s, 1.0)), 1.0, 1e-9);
  const double h = hitsForAlpha(s, 0.5);
  EXPECT_NEAR(toneCurve(s, 4.0, 0.01, h), std::pow(0.5, 0.25), 1e-9);
  FlameSettings f;
  f.density_display = "linear";
  const LogDensityScale linear = densityScale(f, 1e6, 100.0, 800.0);
  EXPECT_NEAR(hitsForAlpha(linear, 1.0), 200.0, 1e-9);  // brightness 4: a quarter of the densest
}

TEST(DirectionalMotionBlur, WeightsGrowTowardTheLatestTimeAndAverageOne) {
  for (double w : motionBlurWeights(4, 0.0)) EXPECT_DOUBLE_EQ(w, 1.0);
  const std::vector<double> w = motionBlurWeights(4, 1.0);  // ∝ 1, 2, 3, 4
  ASSERT_EQ(w.size(), 4u);
  EXPECT_NEAR(w[0], 0.4, 1e-12);
  EXPECT_NEAR(w[3], 1.6, 1e-12);
  const std::vector<double> steep = motionBlurWeights(5, 3.0);
  double sum = 0.0;
  for (std::size_t i = 0; i < steep.size(); ++i) {
    sum += steep[i];
    if (i > 0) {
      EXPECT_LT(steep[i - 1], steep[i]);
    }
  }
  EXPECT_NEAR(sum / 5.0, 1.0, 1e-12);
  EXPECT_EQ(motionBlurWeights(1, 5.0), std::vector<double>{1.0});
}

TEST(DirectionalMotionBlur, EarlierSamplesAreDimmerAndStillShapesUnchanged) {
  RenderImage a;
  a.width = 2, a.height = 1;
  a.rgba = {100, 100, 100, 255, 0, 0, 0, 0};
  a.depth = {1.f, INFINITY};
  a.density = {10, 0};
  a.colorSums = {10.f, 5.f, 2.f, 3.f, 0.f, 0.f, 0.f, 0.f};
  RenderImage b = a;  // the same pixel in the later sample: a shape that does not move
  b.density = {10, 4};
  b.colorSums = {10.f, 5.f, 2.f, 3.f, 4.f, 4.f, 4.f, 1.f};  // plus a pixel only the later sample hits
  const std::vector<double> w = motionBlurWeights(2, 2.0);  // 0.4, 1.6
  TimeSampleSum sum;
  addTimeSample(sum, a, w[0]);
  addTimeSample(sum, b, w[1]);
  const RenderImage image = finishTimeSamples(std::move(sum));
  EXPECT_EQ(image.density[0], 20u);                   // hits add up, unweighted
  EXPECT_NEAR(image.colorSums[0], 20.f, 1e-5);        // still: the weights average 1
  EXPECT_NEAR(image.colorSums[3], 6.f, 1e-5);         // the palette coordinate is not a colour
  EXPECT_NEAR(image.colorSums[4], 4.f * 1.6f, 1e-5);  // the later sample is drawn brighter
  EXPECT_EQ(image.rgba[0], 100);
  EXPECT_EQ(image.hitPixels, 1);
}

TEST(MotionBlur, OneTimeSampleIsTheSampleAndThreeAverageTheirColours) {
  RenderImage a;
  a.width = 2;
  a.height = 1;
  a.rgba = {90, 30, 0, 255, 0, 0, 0, 0};
  a.depth = {2.f, INFINITY};
  a.density = {3, 0};
  a.colorSums = {1.f, 2.f, 3.f, 4.f, 0.f, 0.f, 0.f, 0.f};
  a.hitPixels = 1;
  {
    TimeSampleSum one;
    addTimeSample(one, RenderImage(a), 1.0);  // moved in: no copy of the buffers
    EXPECT_TRUE(one.rgbaSum.empty());
    const RenderImage image = finishTimeSamples(std::move(one));
    EXPECT_EQ(image.rgba, a.rgba);
    EXPECT_EQ(image.depth, a.depth);
    EXPECT_EQ(image.density, a.density);
    EXPECT_EQ(image.colorSums, a.colorSums);
  }
  RenderImage b = a, c = a;
  b.rgba = {30, 30, 30, 255, 0, 0, 0, 0};
  b.depth = {1.f, INFINITY};
  c.rgba = {0, 0, 0, 0, 60, 60, 60, 255};  // only the second pixel
  c.depth = {INFINITY, 5.f};
  c.density = {0, 2};
  TimeSampleSum three;
  addTimeSample(three, a, 1.0);
  addTimeSample(three, std::move(b), 1.0);
  addTimeSample(three, c, 1.0);
  const RenderImage image = finishTimeSamples(std::move(three));
  EXPECT_EQ(image.rgba, (std::vector<std::uint8_t>{40, 20, 10, 255, 20, 20, 20, 255}));
  EXPECT_EQ(image.depth, (std::vector<float>{1.f, 5.f}));
  EXPECT_EQ(image.density, (std::vector<std::uint32_t>{6, 2}));
  EXPECT_EQ(image.hitPixels, 2);
}

TEST(RenderQuality, SetsTheSampleCountFromTheImageSize) {
  RenderSettings r;
  r.width = 100, r.height = 80, r.samples = 12345;
  EXPECT_EQ(renderSampleCount(r), 12345);
  r.quality = 50.0;  // flam3's quality: samples per output pixel
  EXPECT_EQ(renderSampleCount(r), 400000);
  r.quality = 1e6;
  r.width = r.height = 16384;
  EXPECT_EQ(renderSampleCount(r), std::int64_t(1e11));
}

TEST(FlameControlsJson, NewFieldsRoundTripAndOldFilesSaveAsBefore) {
  Project p = defaultNewProject();
  const std::string plain = serializeProject(p);
  for (const char* key : {"\"hue\"", "\"palette_keys\"", "\"density_display\"", "\"quality\"", "\"motion_fade\""})
    EXPECT_EQ(plain.find(key), std::string::npos) << key;
  EXPECT_EQ(serializeProject(parseProject(plain)), plain);
  p.render.quality = 50.0;
  p.render.flame.hue = 0.25;
  p.render.flame.palette_keys = "0:#000000 0.5:#ff8000 1:#ffffff";
  p.render.flame.density_display = "linear";
  AnimationSettings a;
  a.motion_blur = 4;
  a.motion_fade = 1.5;
  p.animation = a;
  const std::string text = serializeProject(p);
  const Project back = parseProject(text);
  EXPECT_EQ(back, p);
  EXPECT_EQ(serializeProject(back), text);
}

TEST(FlameControlsJson, BadValuesNameTheirPath) {
  auto error = [](const std::string& render, const std::string& extra = "") {
    const std::string text = R"({"format": "gridifs", "version": 1, "render": )" + render + extra +
                             R"(, "functions": [{"name": "f", "resolution": [2, 2, 2]}]})";
    try {
      parseProject(text);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("loaded");
  };
  EXPECT_NE(error(R"({"flame": {"density_display": "cubic"}})").find("render.flame.density_display"),
            std::string::npos);
  EXPECT_NE(error(R"({"flame": {"hue": 2}})").find("render.flame.hue"), std::string::npos);
  EXPECT_NE(error(R"({"flame": {"palette_keys": "0:#zz0000 1:#ffffff"}})").find("render.flame.palette_keys"),
            std::string::npos);
  EXPECT_NE(error(R"({"quality": -1})").find("render.quality"), std::string::npos);
  EXPECT_NE(error("{}", R"(, "animation": {"motion_blur": 0})").find("animation"), std::string::npos);
}
