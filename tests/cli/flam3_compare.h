#pragma once
// Shared by the flam3 cross-checks: reading 16-bit RGBA PNGs, Pearson correlation, quantiles.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "run_command.h"

namespace gridifs::test_support {

struct Planes {
  int width = 0, height = 0;
  std::vector<float> rgba;
};

inline Planes readRgba(const std::filesystem::path& file) {
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

inline double correlation(const std::vector<double>& a, const std::vector<double>& b) {
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

inline double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, std::size_t(q * (v.size() - 1) + 0.5))];
}

inline bool haveFlam3() { return std::system("command -v flam3-render > /dev/null 2>&1") == 0; }

/// The metrics of the flam3 cross-checks on two RGBA renders of the same genome (see
/// test_flam3_crosscheck.cpp for what they measure and why).
struct AlphaComparison {
  bool valid = false;
  int width = 0, height = 0;
  double corrAlpha = 0, corrLuma = 0, median = 0, p05 = 0, p95 = 0, abs90 = 0;
  int coveredF = 0, coveredG = 0, coveredBoth = 0;
  std::size_t ratioPixels = 0;
  std::string summary() const {
    char b[512];
    std::snprintf(b, sizeof b,
                  "%dx%d: corr(alpha) = %.4f, corr(luminance) = %.4f, coverage flam3 %d / gridifs %d / both %d; "
                  "log-density ratio over %zu pixels: median %+.4f, 5%% %+.4f, 95%% %+.4f, 90%% of |r| <= %.4f",
                  width, height, corrAlpha, corrLuma, coveredF, coveredG, coveredBoth, ratioPixels, median, p05, p95,
                  abs90);
    return b;
  }
};

inline AlphaComparison compareAlpha(const std::filesystem::path& flam3Png, const std::filesystem::path& gridifsPng,
                                    double gamma) {
  AlphaComparison c;
  const Planes f = readRgba(flam3Png), g = readRgba(gridifsPng);
  if (f.width == 0 || f.width != g.width || f.height != g.height) return c;
  c.width = f.width;
  c.height = f.height;
  std::vector<double> af, ag, lf, lg, ratio;
  for (std::size_t i = 0; i < std::size_t(f.width) * f.height; ++i) {
    const float* pf = &f.rgba[i * 4];
    const float* pg = &g.rgba[i * 4];
    af.push_back(pf[3]);
    ag.push_back(pg[3]);
    // PNG stores unassociated color: premultiply for the luminance.
    lf.push_back(pf[3] * (0.2126 * pf[0] + 0.7152 * pf[1] + 0.0722 * pf[2]));
    lg.push_back(pg[3] * (0.2126 * pg[0] + 0.7152 * pg[1] + 0.0722 * pg[2]));
    c.coveredF += pf[3] > 0.05f;
    c.coveredG += pg[3] > 0.05f;
    c.coveredBoth += pf[3] > 0.05f && pg[3] > 0.05f;
    // Density above the gamma threshold (0.01 → alpha 0.1) and below saturation.
    if (pf[3] > 0.15f && pg[3] > 0.15f && pf[3] < 0.98f && pg[3] < 0.98f)
      ratio.push_back(gamma * std::log(double(pg[3]) / double(pf[3])));
  }
  c.corrAlpha = correlation(af, ag);
  c.corrLuma = correlation(lf, lg);
  c.ratioPixels = ratio.size();
  if (ratio.empty()) return c;
  std::vector<double> absRatio;
  for (double x : ratio) absRatio.push_back(std::fabs(x));
  c.median = quantile(ratio, 0.5);
  c.p05 = quantile(ratio, 0.05);
  c.p95 = quantile(ratio, 0.95);
  c.abs90 = quantile(absRatio, 0.9);
  c.valid = true;
  return c;
}

/// Renders `genome` with flam3-render (16-bit RGBA PNG) from its random stream `seed`; false when it fails.
inline bool renderWithFlam3(const std::filesystem::path& genome, const std::filesystem::path& png,
                            const std::string& seed = "gridifs") {
  const std::string cmd = "env out=" + quote(png.string()) + " transparency=1 bpc=16 isaac_seed=" + seed +
                          " nthreads=2 verbose=0 timeout 120 flam3-render < " + quote(genome.string()) +
                          " > /dev/null 2>&1";
  return std::system(cmd.c_str()) == 0;
}

/// flam3-render draws `reference` from two random streams and `gridifs render --mode flame` draws
/// `project` (16-bit RGBA PNGs in `dir`): `self` compares the two flam3 images, `cross` the first
/// with GridIFS's. `error` says which render failed, empty when all three ran.
struct Flam3Agreement {
  AlphaComparison self, cross;
  std::string error;
};

inline Flam3Agreement agreementWithFlam3(const std::filesystem::path& reference, const std::filesystem::path& project,
                                         const std::filesystem::path& dir) {
  Flam3Agreement a;
  const auto flam3A = dir / "flam3-a.png", flam3B = dir / "flam3-b.png", ours = dir / "gridifs.png";
  if (!renderWithFlam3(reference, flam3A, "first") || !renderWithFlam3(reference, flam3B, "second")) {
    a.error = "flam3-render failed on " + reference.string();
    return a;
  }
  const CommandResult r = runGridifs("render " + quote(project.string()) + " -o " + quote(ours.string()) +
                                     " --mode flame --transparent --bit-depth 16 --threads 2");
  if (r.exitCode != 0) {
    a.error = "gridifs render failed: " + r.err;
    return a;
  }
  a.self = compareAlpha(flam3A, flam3B, 2.0);
  a.cross = compareAlpha(flam3A, ours, 2.0);
  return a;
}

}  // namespace gridifs::test_support
