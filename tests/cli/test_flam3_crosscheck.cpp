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

#include "run_command.h"

using namespace gridifs::test_support;

namespace {

struct Planes {
  int width = 0, height = 0;
  std::vector<float> rgba;
};

Planes readRgba(const std::filesystem::path& file) {
  Planes p;
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) return p;
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels != 4) return p;
  p.width = spec.width;
  p.height = spec.height;
  p.rgba.resize(std::size_t(p.width) * p.height * 4);
  if (!in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, p.rgba.data())) p.width = p.height = 0;
  in->close();
  return p;
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
  ma /= a.size();
  mb /= b.size();
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return sab / std::sqrt(saa * sbb);
}

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, std::size_t(q * (v.size() - 1) + 0.5))];
}

bool haveFlam3() { return std::system("command -v flam3-render > /dev/null 2>&1") == 0; }

void crossCheck(const std::string& name) {
  if (!haveFlam3()) GTEST_SKIP() << "flam3-render (flam3-utils) is not installed";
  const ScratchDir dir("flam3-" + name);
  const std::filesystem::path data = std::filesystem::path(GRIDIFS_TEST_DATA) / "flame";
  const auto flam3Png = dir.path / "flam3.png", gridifsPng = dir.path / "gridifs.png";
  const std::string cmd = "env out=" + quote(flam3Png.string()) +
                          " transparency=1 bpc=16 isaac_seed=gridifs nthreads=2 verbose=0 timeout 60 flam3-render < " +
                          quote((data / (name + ".flam3")).string()) + " > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const CommandResult r = runGridifs("render " + quote((data / (name + ".gridifs")).string()) + " -o " +
                                     quote(gridifsPng.string()) + " --mode flame --transparent --bit-depth 16 --threads 2");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Planes f = readRgba(flam3Png), g = readRgba(gridifsPng);
  ASSERT_GT(f.width, 0);
  ASSERT_EQ(f.width, g.width);
  ASSERT_EQ(f.height, g.height);
  const double gamma = 2.0;  // make_crosscheck.py SETTINGS
  std::vector<double> af, ag, lf, lg, ratio;
  int coveredF = 0, coveredG = 0, coveredBoth = 0;
  for (std::size_t i = 0; i < std::size_t(f.width) * f.height; ++i) {
    const float* pf = &f.rgba[i * 4];
    const float* pg = &g.rgba[i * 4];
    af.push_back(pf[3]);
    ag.push_back(pg[3]);
    // PNG stores unassociated color: premultiply for the luminance.
    lf.push_back(pf[3] * (0.2126 * pf[0] + 0.7152 * pf[1] + 0.0722 * pf[2]));
    lg.push_back(pg[3] * (0.2126 * pg[0] + 0.7152 * pg[1] + 0.0722 * pg[2]));
    coveredF += pf[3] > 0.05f;
    coveredG += pg[3] > 0.05f;
    coveredBoth += pf[3] > 0.05f && pg[3] > 0.05f;
    // Density above the gamma threshold (0.01 → alpha 0.1) and below saturation.
    if (pf[3] > 0.15f && pg[3] > 0.15f && pf[3] < 0.98f && pg[3] < 0.98f)
      ratio.push_back(gamma * std::log(double(pg[3]) / double(pf[3])));
  }
  const double corrAlpha = correlation(af, ag), corrLuma = correlation(lf, lg);
  ASSERT_GT(ratio.size(), 500u);
  std::vector<double> absRatio;
  for (double x : ratio) absRatio.push_back(std::fabs(x));
  const double median = quantile(ratio, 0.5), p05 = quantile(ratio, 0.05), p95 = quantile(ratio, 0.95);
  const double abs90 = quantile(absRatio, 0.9);
  std::printf("[crosscheck %s] %dx%d: corr(alpha) = %.4f, corr(luminance) = %.4f, coverage flam3 %d / gridifs %d / both %d; "
              "log-density ratio over %zu pixels: median %+.4f, 5%% %+.4f, 95%% %+.4f, 90%% of |r| <= %.4f\n",
              name.c_str(), f.width, f.height, corrAlpha, corrLuma, coveredF, coveredG, coveredBoth, ratio.size(), median,
              p05, p95, abs90);
  EXPECT_GE(corrAlpha, 0.99);
  EXPECT_GE(corrLuma, 0.99);
  EXPECT_LE(std::fabs(median), 0.03);
  EXPECT_LE(abs90, 0.25);
  EXPECT_GE(coveredBoth, 0.97 * std::max(coveredF, coveredG));
}

}  // namespace

TEST(Flam3CrossCheck, SierpinskiTriangle) { crossCheck("sierpinski2d"); }
TEST(Flam3CrossCheck, BarnsleyFern) { crossCheck("fern2d"); }
