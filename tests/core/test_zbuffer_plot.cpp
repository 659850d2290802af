// The camera's plotter collects samples in chunks and projects eight at a time (render/chaos_kernel.h).
// Its buffers must be exactly those of plotting one sample at a time with the same float
// operations (Gröller & Wegenkittl 1994, §3.1: the nearest point per pixel, here with its packed
// colour as the tie-break, and the hit count; Draves & Reckase 2003, §5: the colour sums in sample
// order), whatever the chunk boundaries, and it must count exactly the samples that landed.
#include <gtest/gtest.h>
#include <algorithm>

#include <bit>
#include <cmath>
#include <cstring>
#include <memory>
#include <random>
#include <vector>

#include "model/project.h"
#include "render/camera.h"
#include "render/chaos_kernel.h"
#include "tone/palette.h"

namespace gridifs {
namespace {

using kernel::v4f;

constexpr int kPlotWidth = 96, kPlotHeight = 64;

/// Points around the origin, some behind the camera or outside the frame, a few not numbers.
std::vector<v4f> plotSamplePoints(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> near(-1.0f, 1.0f), far(-12.0f, 12.0f);
  std::vector<v4f> points;
  for (int i = 0; i < count; ++i) {
    if (i % 89 == 7)
      points.push_back(v4f{NAN, 0.0f, 0.0f, 0.0f});
    else if (i % 13 == 3)
      points.push_back(v4f{far(rng), far(rng), far(rng), 0.0f});
    else
      points.push_back(v4f{near(rng), near(rng), near(rng), 0.0f});
  }
  return points;
}

/// Colours in [0, 1], with exact 0 and 1 and a NaN now and then (a colour is packed, not checked).
std::vector<v4f> sampleColors(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<v4f> colors;
  for (int i = 0; i < count; ++i) {
    v4f c{unit(rng), unit(rng), unit(rng), unit(rng)};
    if (i % 17 == 2) c[0] = 0.0f;
    if (i % 19 == 4) c[3] = 1.0f;
    if (i % 101 == 9) c[1] = NAN;
    colors.push_back(c);
  }
  return colors;
}

struct Buffers {
  std::vector<kernel::PixelCell> cells;
  std::vector<std::uint64_t> sums;  // fixed point, 16 fraction bits
  std::int64_t plotted = 0;
};

Buffers emptyBuffers() {
  return {std::vector<kernel::PixelCell>(kPlotWidth * kPlotHeight),
          std::vector<std::uint64_t>(kPlotWidth * kPlotHeight * 4), 0};
}

/// One sample at a time: the projection and packing of the plotter, written out plainly.
Buffers referencePlot(const kernel::HotCamera& cam, const std::vector<v4f>& points, const std::vector<v4f>& colors,
                      const v4f* palette) {
  Buffers b = emptyBuffers();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const v4f q = points[i];
    const v4f r = cam.cx * q[0] + cam.cy * q[1] + cam.cz * q[2] + cam.c1;
    const float depth = r[3];
    if (!(depth > cam.nearPlane)) continue;
    const float inverse = 1.0f / r[2];
    const float x = r[0] * inverse, y = r[1] * inverse;
    if (!(x >= 0.0f && x < cam.size[0] && y >= 0.0f && y < cam.size[1])) continue;
    const std::size_t pixel = std::size_t(int(y)) * cam.stride + std::size_t(int(x));
    const std::uint64_t key = (std::uint64_t(std::bit_cast<std::uint32_t>(depth)) << 32) | kernel::packColor(colors[i]);
    kernel::PixelCell& cell = b.cells[pixel];
    if (key < cell.key) cell.key = key;
    ++cell.density;
    v4f add = colors[i];
    if (palette) {
      float c = colors[i][3] * 256.0f;
      c = c > 0.0f ? (c < 256.0f ? c : 256.0f) : 0.0f;
      const int entry = int(c) < 255 ? int(c) : 255;
      add = palette[entry] + (palette[entry + 1] - palette[entry]) * (c - float(entry));
      add[3] = colors[i][3];
    }
    // Each channel clamped to [0, 1] and rounded to 16 fraction bits (the GPU's fixed point).
    for (int k = 0; k < 4; ++k)
      b.sums[pixel * 4 + k] += std::uint64_t(std::min(1.0f, std::max(0.0f, add[k])) * 65536.0f + 0.5f);
    ++b.plotted;
  }
  return b;
}

template <bool kColor>
Buffers chunked(const kernel::HotCamera& cam, const std::vector<v4f>& points, const std::vector<v4f>& colors,
                const v4f* palette, std::size_t flushEvery) {
  Buffers b = emptyBuffers();
  auto plot = std::make_unique<kernel::ZBufferPlot<kColor>>(
      kernel::ZBufferPlot<kColor>{cam, b.cells.data(), b.sums.data(), palette});
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ((*plot)(points[i], colors[i]), 0) << "counted late, by takePlotted";
    if ((i + 1) % flushEvery == 0) plot->flush();
  }
  plot->flush();
  b.plotted = plot->takePlotted();
  EXPECT_EQ(plot->takePlotted(), 0);
  return b;
}

void expectSamePlots(const Buffers& expected, const Buffers& actual, bool sums) {
  ASSERT_EQ(expected.cells.size(), actual.cells.size());
  EXPECT_EQ(expected.plotted, actual.plotted);
  int differing = 0;
  for (std::size_t p = 0; p < expected.cells.size(); ++p) {
    differing += expected.cells[p].key != actual.cells[p].key || expected.cells[p].density != actual.cells[p].density;
    if (sums)
      for (int k = 0; k < 4; ++k)
        differing += std::memcmp(&expected.sums[p * 4 + k], &actual.sums[p * 4 + k], sizeof(std::uint64_t)) != 0;
  }
  EXPECT_EQ(differing, 0);
}

kernel::HotCamera camera(bool ortho) {
  Camera c;
  c.yaw = 35.0;
  c.pitch = 25.0;
  c.distance = 3.5;
  c.projection = ortho ? CameraProjection::Orthographic : CameraProjection::Perspective;
  return kernel::makeHotCamera(OrbitCamera(c, kPlotWidth, kPlotHeight));
}

TEST(ZBufferPlot, ChunksPlotExactlyAsOneSampleAtATime) {
  const auto points = plotSamplePoints(5000, 3);
  const auto colors = sampleColors(5000, 4);
  for (bool ortho : {false, true}) {
    const kernel::HotCamera cam = camera(ortho);
    const Buffers expected = referencePlot(cam, points, colors, nullptr);
    EXPECT_GT(expected.plotted, 3000) << "most samples land in the frame";
    EXPECT_LT(expected.plotted, 5000) << "some fall outside";
    // Whole chunks, a partial last one, and flushes at odd places (runChain flushes per batch).
    for (std::size_t flushEvery : {std::size_t(1000000), std::size_t(1), std::size_t(7), std::size_t(300)}) {
      SCOPED_TRACE(testing::Message() << "ortho " << ortho << ", flush every " << flushEvery);
      expectSamePlots(expected, chunked<false>(cam, points, colors, nullptr, flushEvery), false);
      expectSamePlots(expected, chunked<true>(cam, points, colors, nullptr, flushEvery), true);
    }
  }
}

TEST(ZBufferPlot, PaletteColourSumsMatchOneSampleAtATime) {
  std::vector<v4f> palette;
  for (const Rgb& c : builtinPalette("ember").colors) palette.push_back(v4f{c.r, c.g, c.b, 0.0f});
  palette.push_back(palette.back());
  const auto points = plotSamplePoints(3000, 5);
  const auto colors = sampleColors(3000, 6);
  const kernel::HotCamera cam = camera(false);
  expectSamePlots(referencePlot(cam, points, colors, palette.data()),
                  chunked<true>(cam, points, colors, palette.data(), 1000000), true);
}

TEST(ZBufferPlot, PointsThatAreNotNumbersLandNowhere) {
  const kernel::HotCamera cam = camera(false);
  const std::vector<v4f> points(40, v4f{NAN, NAN, NAN, 0.0f});
  const std::vector<v4f> colors(points.size(), v4f{0.5f, 0.5f, 0.5f, 0.5f});
  const Buffers b = chunked<true>(cam, points, colors, nullptr, 1000000);
  EXPECT_EQ(b.plotted, 0);
  for (const kernel::PixelCell& cell : b.cells) {
    EXPECT_EQ(cell.key, kernel::kEmptyKey);
    EXPECT_EQ(cell.density, 0u);
  }
}

// A key's colour bytes: round(v · 255) clamped to [0, 255] per channel, red in the low byte, and 0
// for a channel that is not a number (packColor leans on the saturating packs for the clamp).
TEST(ZBufferPlot, PackedColoursRoundAndClampEachChannel) {
  auto byteOf = [](float v) -> std::uint32_t {
    if (!(v * 255.0f + 0.5f > 0.0f)) return 0;  // NaN and negatives
    return std::uint32_t(std::min(v * 255.0f + 0.5f, 255.0f));
  };
  const float values[] = {0.0f,    -0.0f, 1.0f,  0.5f,      0.25f, 1.0f / 255.0f, 0.999f,  1.5f,  7.0f,
                          -0.001f, -1.0f, -1e9f, -INFINITY, NAN,   0.0019f,       0.0021f, 1e-30f};
  for (float r : values)
    for (float b : values) {
      const v4f c{r, 0.3f, b, 0.7f};
      const std::uint32_t expected = byteOf(r) | byteOf(0.3f) << 8 | byteOf(b) << 16 | byteOf(0.7f) << 24;
      EXPECT_EQ(kernel::packColor(c), expected) << "r " << r << " b " << b;
    }
}

}  // namespace
}  // namespace gridifs
