// gridifs import-flame / export-flame on real .flame files: the imported genome rendered by
// `gridifs render --mode flame` against `flam3-render` of the same genome (metrics as in
// test_flam3_crosscheck.cpp), round trips, genome selection and bad input.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <array>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "flam3_compare.h"
#include "io/flame_genome.h"
#include "io/project_io.h"
#include "model/stack_evaluator.h"
#include "run_command.h"

using namespace gridifs;
using namespace gridifs::test_support;

namespace {

const std::filesystem::path kData = std::filesystem::path(GRIDIFS_TEST_DATA) / "flame";

/// Imports `genomeFile` (genome `which`), renders it with both renderers and compares alpha.
AlphaComparison crossCheckImported(const std::string& genomeFile, const std::string& which, const ScratchDir& dir) {
  const auto project = dir.path / "imported.gridifs", gridifsPng = dir.path / "gridifs.png",
             flam3Png = dir.path / "flam3.png", single = dir.path / "genome.flame";
  const CommandResult imported = runGridifs("import-flame " + quote((kData / genomeFile).string()) + " --genome " +
                                            quote(which) + " -o " + quote(project.string()));
  EXPECT_EQ(imported.exitCode, 0) << imported.err;
  // flam3-render renders every genome of a file: hand it the selected one alone.
  const auto genomes = loadFlameFile(kData / genomeFile);
  const std::string text = slurp(kData / genomeFile);
  const std::string name = selectGenome(genomes, which).name;
  const std::size_t start = text.find("<flame name=\"" + name + "\"");
  const std::size_t end = text.find("</flame>", start);
  EXPECT_NE(start, std::string::npos);
  { std::ofstream(single) << text.substr(start, end + 8 - start) << "\n"; }
  EXPECT_TRUE(renderWithFlam3(single, flam3Png));
  const CommandResult r = runGridifs("render " + quote(project.string()) + " -o " + quote(gridifsPng.string()) +
                                     " --mode flame --transparent --bit-depth 16 --threads 2");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const Project p = loadProject(project);
  return compareAlpha(flam3Png, gridifsPng, p.render.flame.gamma);
}

}  // namespace

TEST(FlameCli, ImportedSierpinskiMatchesFlam3) {
  if (!haveFlam3()) GTEST_SKIP() << "flam3-render (flam3-utils) is not installed";
  const ScratchDir dir("flame-import-sierpinski");
  const AlphaComparison c = crossCheckImported("sierpinski2d.flam3", "0", dir);
  ASSERT_TRUE(c.valid);
  std::printf("[import crosscheck sierpinski] %s\n", c.summary().c_str());
  EXPECT_GE(c.corrAlpha, 0.99);
  EXPECT_GE(c.corrLuma, 0.99);
  EXPECT_LE(std::fabs(c.median), 0.03);
  EXPECT_LE(c.abs90, 0.25);
  EXPECT_GE(c.coveredBoth, 0.97 * std::max(c.coveredF, c.coveredG));
}

TEST(FlameCli, ImportedFernMatchesFlam3) {
  if (!haveFlam3()) GTEST_SKIP() << "flam3-render (flam3-utils) is not installed";
  const ScratchDir dir("flame-import-fern");
  const AlphaComparison c = crossCheckImported("fern2d.flam3", "fern2d", dir);
  ASSERT_TRUE(c.valid);
  std::printf("[import crosscheck fern] %s\n", c.summary().c_str());
  EXPECT_GE(c.corrAlpha, 0.99);
  EXPECT_GE(c.corrLuma, 0.99);
  EXPECT_LE(std::fabs(c.median), 0.03);
  EXPECT_LE(c.abs90, 0.25);
}

TEST(FlameCli, ImportedRotatedViewMatchesFlam3) {
  // The genome's `rotate` turns the frame: the same picture as flam3's, not its mirror.
  if (!haveFlam3()) GTEST_SKIP() << "flam3-render (flam3-utils) is not installed";
  const ScratchDir dir("flame-import-rotated");
  const AlphaComparison c = crossCheckImported("fern_rotated.flam3", "0", dir);
  ASSERT_TRUE(c.valid);
  std::printf("[import crosscheck fern rotated 30°] %s\n", c.summary().c_str());
  EXPECT_GE(c.corrAlpha, 0.99);
  EXPECT_LE(std::fabs(c.median), 0.03);
}

TEST(FlameCli, ChaosRowsMatchFlam3sXaos) {
  // Sierpinski with xform 0 never following itself: flam3 walks its chaos rows, GridIFS its
  // transition matrix.
  if (!haveFlam3()) GTEST_SKIP() << "flam3-render (flam3-utils) is not installed";
  const ScratchDir dir("flame-import-chaos");
  const AlphaComparison c = crossCheckImported("sierpinski_chaos.flam3", "0", dir);
  ASSERT_TRUE(c.valid);
  std::printf("[import crosscheck chaos] %s\n", c.summary().c_str());
  EXPECT_GE(c.corrAlpha, 0.99);
  EXPECT_LE(std::fabs(c.median), 0.05);
  const Project p = loadProject(dir.path / "imported.gridifs");
  EXPECT_EQ(p.transitions[0], (std::vector<double>{0, 1, 1}));
}

TEST(FlameCli, ImportedNonlinearGenomesMatchFlam3) {
  // Grids sample the maps (64×64 nodes), so the agreement is looser than for affine genomes.
  if (!haveFlam3()) GTEST_SKIP() << "flam3-render (flam3-utils) is not installed";
  for (const std::string which : {"swirl-spherical", "horseshoe-final"}) {
    const ScratchDir dir("flame-import-" + which);
    const AlphaComparison c = crossCheckImported("nonlinear.flame", which, dir);
    ASSERT_TRUE(c.valid);
    std::printf("[import crosscheck %s] %s\n", which.c_str(), c.summary().c_str());
    // Measured: swirl-spherical 0.989, horseshoe-final 0.980 (few pixels, so the density ratio
    // is noisy there).
    EXPECT_GE(c.corrAlpha, 0.95) << which;
    EXPECT_GE(c.corrLuma, 0.93) << which;
    EXPECT_LE(std::fabs(c.median), 0.1) << which;
  }
}

namespace {

/// The mean color (unassociated, alpha-weighted) of an RGBA PNG.
std::array<double, 3> meanColor(const std::filesystem::path& png) {
  const Planes p = readRgba(png);
  std::array<double, 3> sum{0, 0, 0};
  double alpha = 0;
  for (std::size_t i = 0; i < std::size_t(p.width) * p.height; ++i) {
    const float* px = &p.rgba[i * 4];
    for (int c = 0; c < 3; ++c) sum[std::size_t(c)] += px[3] * px[c];
    alpha += px[3];
  }
  for (double& c : sum) c /= std::max(alpha, 1e-9);
  return sum;
}

}  // namespace

TEST(FlameCli, HueRotationMatchesFlam3) {
  // flam3 turns the hue of a palette it takes from its collection by `hue` turns.
  if (!haveFlam3()) GTEST_SKIP() << "flam3-render (flam3-utils) is not installed";
  const ScratchDir dir("flame-import-hue");
  const AlphaComparison c = crossCheckImported("sierpinski_hue.flam3", "0", dir);
  ASSERT_TRUE(c.valid);
  std::printf("[import crosscheck hue 0.3] %s\n", c.summary().c_str());
  EXPECT_GE(c.corrLuma, 0.99);
  // The turn stays a setting on flam3's palette (render.flame.hue), not a turned copy.
  const Project imported = loadProject(dir.path / "imported.gridifs");
  EXPECT_EQ(imported.render.flame.palette.rfind("flam3:", 0), 0u) << imported.render.flame.palette;
  EXPECT_NEAR(imported.render.flame.hue, 0.3, 1e-9);
  EXPECT_FALSE(std::filesystem::exists(dir.path / "imported.palette.json"));
  const auto flam3 = meanColor(dir.path / "flam3.png"), gridifs = meanColor(dir.path / "gridifs.png");
  const ScratchDir plainDir("flame-import-hue-plain");
  const auto plainPng = plainDir.path / "plain.png";
  ASSERT_TRUE(renderWithFlam3(kData / "sierpinski2d.flam3", plainPng));
  const auto plain = meanColor(plainPng);
  double shift = 0;
  for (int k = 0; k < 3; ++k) {
    const std::size_t i = std::size_t(k);
    std::printf("[hue] channel %d: flam3 %.4f gridifs %.4f (hue 0: %.4f)\n", k, flam3[i], gridifs[i], plain[i]);
    EXPECT_NEAR(gridifs[i], flam3[i], 0.02) << k;
    shift = std::max(shift, std::fabs(plain[i] - flam3[i]));
  }
  EXPECT_GT(shift, 0.05);  // the rotation changes the picture's colors: the check can fail
}

TEST(FlameCli, ZVariationsSeenFromAboveMatchFlam3) {
  // A genome with z variations and 3D affine parts, seen by a camera straight from above:
  // flam3-render, which ignores the 3D attributes, draws the same picture.
  if (!haveFlam3()) GTEST_SKIP() << "flam3-render (flam3-utils) is not installed";
  const ScratchDir dir("flame-import-z-topdown");
  const AlphaComparison c = crossCheckImported("zvariations_topdown.flame", "0", dir);
  ASSERT_TRUE(c.valid);
  std::printf("[import crosscheck z variations from above] %s\n", c.summary().c_str());
  EXPECT_GE(c.corrAlpha, 0.99);
  EXPECT_GE(c.corrLuma, 0.99);
  EXPECT_LE(std::fabs(c.median), 0.03);
  // Imported natively, in X = (x, y, −z), seen from below as a flat genome is: the z variations
  // kept by name, ztranslate's sign turned with X's z.
  const Project p = loadProject(dir.path / "imported.gridifs");
  EXPECT_EQ(p.camera.pitch, -90.0);
  EXPECT_EQ(p.functions[0].resolution, (Index3{2, 2, 2}));
  EXPECT_EQ(p.functions[0].variations,
            (std::map<std::string, double>{{"linear", 1.0}, {"zscale", -0.5}, {"ztranslate", -0.3}}));
}

TEST(FlameCli, ImportsThreeDimensionalGenomes) {
  const ScratchDir dir("flame-import-3d");
  const auto out = dir.path / "tetra.gridifs";
  const CommandResult r = runGridifs("import-flame " + quote((kData / "tetrahedron3d.flame").string()) +
                                     " --genome tetrahedron-perspective -o " + quote(out.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err.find("2D"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("sampled"), std::string::npos) << r.err;  // imported natively, cam_dof kept
  const Project p = loadProject(out);
  EXPECT_FALSE(p.camera.orthographic());
  EXPECT_DOUBLE_EQ(p.camera.lens_blur, 0.1);
  for (const Function& f : p.functions) {
    EXPECT_EQ(f.resolution, (Index3{2, 2, 2}));
    EXPECT_FALSE(f.sampling_error);
  }
  // Sampled onto grids (--grids), cam_dof has no plane to keep sharp and is left out.
  const auto grids = dir.path / "tetra-grids.gridifs";
  const CommandResult g = runGridifs("import-flame " + quote((kData / "tetrahedron3d.flame").string()) +
                                     " --genome tetrahedron-perspective --grids -o " + quote(grids.string()));
  ASSERT_EQ(g.exitCode, 0) << g.err;
  EXPECT_NE(g.err.find("cam_dof"), std::string::npos) << g.err;
  for (const char* mode : {"zbuffer", "flame"}) {
    const CommandResult render = runGridifs("render " + quote(out.string()) + " -o " +
                                            quote((dir.path / (std::string(mode) + ".png")).string()) + " --mode " +
                                            mode + " --samples 200000 --threads 2");
    EXPECT_EQ(render.exitCode, 0) << render.err;
  }
  const auto swirl = dir.path / "swirl.gridifs";
  const CommandResult s = runGridifs("import-flame " + quote((kData / "tetrahedron3d.flame").string()) +
                                     " --genome 1 --grids --resolution 16 -o " + quote(swirl.string()));
  ASSERT_EQ(s.exitCode, 0) << s.err;
  EXPECT_NE(s.err.find("blur3D"), std::string::npos) << s.err;
  EXPECT_EQ(loadProject(swirl).functions[0].resolution, (Index3{16, 8, 16}));
}

TEST(FlameCli, ListAndSelectGenomes) {
  const CommandResult list = runGridifs("import-flame " + quote((kData / "nonlinear.flame").string()) + " --list");
  ASSERT_EQ(list.exitCode, 0) << list.err;
  EXPECT_NE(list.out.find("2 genomes"), std::string::npos);
  EXPECT_NE(list.out.find("0   swirl-spherical"), std::string::npos);
  EXPECT_NE(list.out.find("1   horseshoe-final"), std::string::npos);
  EXPECT_NE(list.out.find("+ final"), std::string::npos);
  const ScratchDir dir("flame-select");
  const auto out = dir.path / "h.gridifs";
  // --grids samples the xforms onto grids to sculpt (the import of 3D genomes).
  const CommandResult byName =
      runGridifs("import-flame " + quote((kData / "nonlinear.flame").string()) +
                 " --genome horseshoe-final --grids --resolution 24 -o " + quote(out.string()));
  ASSERT_EQ(byName.exitCode, 0) << byName.err;
  const Project p = loadProject(out);
  ASSERT_EQ(p.functions.size(), 3u);
  EXPECT_TRUE(p.final_function.has_value());
  EXPECT_EQ(p.functions[0].resolution, (Index3{24, 24, 2}));
  EXPECT_EQ(p.functions[2].resolution, (Index3{2, 2, 2}));  // a linear xform
  EXPECT_EQ(p.render.width, 400);
  EXPECT_EQ(p.render.height, 300);
  // info reports the sampling error per function.
  const CommandResult info = runGridifs("info " + quote(out.string()) + " --json");
  ASSERT_EQ(info.exitCode, 0) << info.err;
  const auto j = nlohmann::json::parse(info.out);
  EXPECT_GT(j["functions"][0]["sampling_error"].get<double>(), 0.0);
  EXPECT_LT(j["functions"][2]["sampling_error"].get<double>(), 1e-12);
  // Without --grids the variations are kept by name: nothing is sampled.
  const auto native = dir.path / "native.gridifs";
  const CommandResult kept = runGridifs("import-flame " + quote((kData / "nonlinear.flame").string()) +
                                        " --genome horseshoe-final -o " + quote(native.string()));
  ASSERT_EQ(kept.exitCode, 0) << kept.err;
  EXPECT_EQ(kept.err, "");
  const Project n = loadProject(native);
  EXPECT_EQ(n.functions[0].variations, (std::map<std::string, double>{{"horseshoe", 0.7}, {"linear", 0.3}}));
  EXPECT_FALSE(n.functions[0].sampling_error);
  ASSERT_TRUE(n.final_function);
  EXPECT_EQ(n.final_function->variations, (std::map<std::string, double>{{"bubble", 1.0}}));
}

TEST(FlameCli, PalettesRandomVariationsAndWarnings) {
  const ScratchDir dir("flame-palettes");
  const auto out = dir.path / "inline.gridifs";
  const CommandResult r =
      runGridifs("import-flame " + quote((kData / "inline_palette.flame").string()) + " -o " + quote(out.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir.path / "inline.palette.json"));
  const Project p = loadProject(out);
  EXPECT_EQ(p.render.flame.palette, "file:inline.palette.json");
  ASSERT_EQ(p.transitions.size(), 2u);
  EXPECT_EQ(p.transitions[0], (std::vector<double>{1, 1}));
  EXPECT_EQ(p.transitions[1], (std::vector<double>{2, 0.5}));
  EXPECT_DOUBLE_EQ(p.functions[0].color_speed, 0.0);  // symmetry 1
  // The project renders with its palette file.
  const CommandResult render =
      runGridifs("render " + quote(out.string()) + " -o " + quote((dir.path / "i.png").string()) + " --samples 20000");
  EXPECT_EQ(render.exitCode, 0) << render.err;
  const auto out2 = dir.path / "entries.gridifs";
  const CommandResult w =
      runGridifs("import-flame " + quote((kData / "color_entries.flame").string()) + " -o " + quote(out2.string()));
  ASSERT_EQ(w.exitCode, 0) << w.err;
  // Random variations are kept like the others; an unknown attribute is named.
  EXPECT_EQ(w.err.find("random variations"), std::string::npos) << w.err;
  EXPECT_NE(w.err.find("hemisphere"), std::string::npos) << w.err;
  bool blur = false, julia = false;
  for (const Function& f : loadProject(out2).functions) {
    blur |= f.variations.count("blur") > 0;
    julia |= f.variations.count("julia") > 0;
  }
  EXPECT_TRUE(blur && julia);
  // Sampled onto grids, a random variation has no map: it is left out, with a warning.
  const CommandResult sampled = runGridifs("import-flame " + quote((kData / "color_entries.flame").string()) +
                                           " --grids -o " + quote((dir.path / "grids.gridifs").string()));
  ASSERT_EQ(sampled.exitCode, 0) << sampled.err;
  EXPECT_NE(sampled.err.find("random variations blur, julia"), std::string::npos) << sampled.err;
}

TEST(FlameCli, ExportThenImportIsTheIdentityForAffineProjects) {
  const ScratchDir dir("flame-roundtrip");
  const auto flame = dir.path / "s.flame", back = dir.path / "back.gridifs";
  const auto source = kData / "sierpinski2d.gridifs";
  const CommandResult e = runGridifs("export-flame " + quote(source.string()) + " -o " + quote(flame.string()));
  ASSERT_EQ(e.exitCode, 0) << e.err;
  EXPECT_EQ(e.err, "");  // affine: no fit warning
  const CommandResult i = runGridifs("import-flame " + quote(flame.string()) + " -o " + quote(back.string()));
  ASSERT_EQ(i.exitCode, 0) << i.err;
  const Project a = loadProject(source), b = loadProject(back);
  ASSERT_EQ(a.functions.size(), b.functions.size());
  for (std::size_t f = 0; f < a.functions.size(); ++f) {
    const auto ga = evaluateFunctionAt(a.functions[f], ""), gb = evaluateFunctionAt(b.functions[f], "");
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int n = 0; n < 2; ++n) {
          const Vec3 d = ga->node(n, j, k) - gb->node(n, j, k);
          EXPECT_LT(std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z), 1e-9);
        }
    EXPECT_EQ(a.functions[f].weight, b.functions[f].weight);
    EXPECT_EQ(a.functions[f].palette_index, b.functions[f].palette_index);
  }
  EXPECT_EQ(a.render.flame.brightness, b.render.flame.brightness);
  EXPECT_EQ(a.render.samples, b.render.samples);
  // flam3 renders the exported genome.
  if (haveFlam3()) {
    EXPECT_TRUE(renderWithFlam3(flame, dir.path / "f.png"));
  }
}

TEST(FlameCli, ExportOfANonAffineProjectWarnsAndFits) {
  const ScratchDir dir("flame-export-fit");
  const auto project = dir.path / "n.gridifs", flame = dir.path / "n.flame";
  ASSERT_EQ(runGridifs("import-flame " + quote((kData / "nonlinear.flame").string()) + " --grids --resolution 16 -o " +
                       quote(project.string()))
                .exitCode,
            0);
  const CommandResult e = runGridifs("export-flame " + quote(project.string()) + " -o " + quote(flame.string()));
  ASSERT_EQ(e.exitCode, 0) << e.err;
  EXPECT_NE(e.err.find("least-squares affine fit"), std::string::npos) << e.err;
  const auto genomes = loadFlameFile(flame);
  ASSERT_EQ(genomes.size(), 1u);
  EXPECT_EQ(genomes[0].xforms.size(), 3u);
}

TEST(FlameCli, ExportThenImportIsTheIdentityForProjectsWithVariations) {
  const ScratchDir dir("flame-export-variations");
  const auto project = dir.path / "v.gridifs", flame = dir.path / "v.flame", back = dir.path / "back.gridifs";
  ASSERT_EQ(runGridifs("import-flame " + quote((kData / "nonlinear.flame").string()) + " --genome 1 -o " +
                       quote(project.string()))
                .exitCode,
            0);
  const CommandResult e = runGridifs("export-flame " + quote(project.string()) + " -o " + quote(flame.string()));
  ASSERT_EQ(e.exitCode, 0) << e.err;
  EXPECT_EQ(e.err, "");  // the variations are written as they are: nothing to fit
  const CommandResult i = runGridifs("import-flame " + quote(flame.string()) + " -o " + quote(back.string()));
  ASSERT_EQ(i.exitCode, 0) << i.err;
  const Project a = loadProject(project), b = loadProject(back);
  ASSERT_EQ(a.functions.size(), b.functions.size());
  for (std::size_t f = 0; f < a.functions.size(); ++f) {
    EXPECT_EQ(a.functions[f].variations, b.functions[f].variations);
    EXPECT_EQ(a.functions[f].variation_params, b.functions[f].variation_params);
    EXPECT_EQ(a.functions[f].post, b.functions[f].post);
    EXPECT_EQ(a.functions[f].weight, b.functions[f].weight);
    EXPECT_EQ(a.functions[f].palette_index, b.functions[f].palette_index);
    // The pre-affine grid comes back to the last bits of its coefficients.
    const auto ga = evaluateFunctionAt(a.functions[f], ""), gb = evaluateFunctionAt(b.functions[f], "");
    for (std::size_t n = 0; n < ga->nodeCount(); ++n) EXPECT_LT(glm::length(ga->nodes()[n] - gb->nodes()[n]), 1e-12);
  }
  EXPECT_EQ(a.camera.yaw, b.camera.yaw);
  EXPECT_NEAR(a.camera.target.x, b.camera.target.x, 1e-12);
  EXPECT_NEAR(a.camera.distance, b.camera.distance, 1e-12);
  ASSERT_TRUE(b.final_function);
  EXPECT_EQ(a.final_function->variations, b.final_function->variations);
}

TEST(FlameCli, BadInputExitsTwoAndWritesNothing) {
  const ScratchDir dir("flame-bad");
  const auto out = dir.path / "out.gridifs";
  for (const auto& entry : std::filesystem::directory_iterator(kData / "bad")) {
    const CommandResult r = runGridifs("import-flame " + quote(entry.path().string()) + " -o " + quote(out.string()));
    EXPECT_EQ(r.exitCode, 2) << entry.path();
    EXPECT_NE(r.err.find(entry.path().filename().string()), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << entry.path();
  }
  // An unknown genome, a missing file, a bad resolution: exit 2, and a good file is not touched.
  { std::ofstream(out) << "keep"; }
  for (const std::string args : {"--genome nope", "--genome 7", "--resolution 1", "--resolution 500"}) {
    const CommandResult r = runGridifs("import-flame " + quote((kData / "sierpinski2d.flam3").string()) + " " + args +
                                       " -o " + quote(out.string()));
    EXPECT_EQ(r.exitCode, 2) << args;
    EXPECT_EQ(slurp(out), "keep") << args;
  }
  EXPECT_EQ(runGridifs("import-flame " + quote((dir.path / "missing.flame").string()) + " -o " + quote(out.string()))
                .exitCode,
            2);
  EXPECT_EQ(runGridifs("export-flame " + quote((kData / "bad" / "malformed.flame").string()) + " -o " +
                       quote((dir.path / "x.flame").string()))
                .exitCode,
            2);
  EXPECT_EQ(runGridifs("export-flame " + quote((kData / "sierpinski2d.gridifs").string()) + " -o " +
                       quote((dir.path / "x.png").string()))
                .exitCode,
            2);
  EXPECT_FALSE(std::filesystem::exists(dir.path / "x.flame"));
}
