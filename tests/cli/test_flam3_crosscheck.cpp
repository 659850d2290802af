// Cross-check of the flame display against the reference renderer: the same 2D linear
// IFS rendered by `flam3-render` (Debian flam3-utils) from a flam3 genome and by
// `gridifs render --mode flame` from a .gridifs project (affine 2×2×2 grids seen straight down z
// through an orthographic camera) at the same size, quality, palette and tone-mapping settings.
// tests/data/flame/make_crosscheck.py writes both files.
//
// Metrics on the alpha channel (alpha = min(1, density^(1/gamma)), density = k1·log(1 + hits·k2)
// after density estimation and the spatial filter; 16-bit PNGs):
//  - Pearson correlation of the two alpha images and of their premultiplied luminance;
//  - the per-pixel log-density ratio r = gamma·ln(alpha_gridifs/alpha_flam3) where both pixels are
//    above the gamma threshold and below saturation: its median (exposure bias) and 90% spread.
// Both renders are Monte-Carlo estimates from independent random streams (different RNGs; flam3
// has a gutter outside the frame and 100 fuse iterations, GridIFS skips 20 and iterates in float),
// so they agree only up to sampling noise: at ~1000 hits per pixel the relative density noise is
// ~3% per render, and the density estimator spreads the sparse edge pixels differently from one
// sample set to the next, which gives a 90% spread of |r| of about 0.12–0.16 (measured
// 2026-11: Sierpinski corr 0.9998, median r +0.001, 90% |r| ≤ 0.16; fern corr 0.9997, median r
// −0.001, 90% |r| ≤ 0.12). Tolerances: correlations ≥ 0.99; |median r| ≤ 0.03 (a systematic
// exposure error of 3% in density would show here; the normalisation makes it ~0); 90% of
// |r| ≤ 0.25; the pixels covered (alpha > 0.05) agree to 3%.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "flam3_compare.h"
#include "run_command.h"

using namespace gridifs::test_support;

namespace {

void crossCheck(const std::string& name) {
  if (!haveFlam3()) GTEST_SKIP() << "flam3-render (flam3-utils) is not installed";
  const ScratchDir dir("flam3-" + name);
  const std::filesystem::path data = std::filesystem::path(GRIDIFS_TEST_DATA) / "flame";
  const auto flam3Png = dir.path / "flam3.png", gridifsPng = dir.path / "gridifs.png";
  const std::string cmd = "env out=" + quote(flam3Png.string()) +
                          " transparency=1 bpc=16 isaac_seed=gridifs nthreads=2 verbose=0 timeout 60 flam3-render < " +
                          quote((data / (name + ".flam3")).string()) + " > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const CommandResult r =
      runGridifs("render " + quote((data / (name + ".gridifs")).string()) + " -o " + quote(gridifsPng.string()) +
                 " --mode flame --transparent --bit-depth 16 --threads 2");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const AlphaComparison c = compareAlpha(flam3Png, gridifsPng, 2.0);  // gamma of make_crosscheck.py SETTINGS
  ASSERT_TRUE(c.valid);
  ASSERT_GT(c.ratioPixels, 500u);
  std::printf("[crosscheck %s] %s\n", name.c_str(), c.summary().c_str());
  EXPECT_GE(c.corrAlpha, 0.99);
  EXPECT_GE(c.corrLuma, 0.99);
  EXPECT_LE(std::fabs(c.median), 0.03);
  EXPECT_LE(c.abs90, 0.25);
  EXPECT_GE(c.coveredBoth, 0.97 * std::max(c.coveredF, c.coveredG));
}

}  // namespace

TEST(Flam3CrossCheck, SierpinskiTriangle) { crossCheck("sierpinski2d"); }
TEST(Flam3CrossCheck, BarnsleyFern) { crossCheck("fern2d"); }
