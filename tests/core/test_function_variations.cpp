// Functions with flame variations (Draves & Reckase 2003, §3): f(p) = post(Σ w_i V_i(g(p))) with
// the grid map g extrapolated beyond X — the file format, validation, the compiled map against
// the genome's own map, the camera of a native import against flam3's pixel mapping, bad values
// and determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "flame_seed_checks.h"
#include "io/flame_genome.h"
#include "io/flame_import.h"
#include "io/project_io.h"
#include "model/stack_evaluator.h"
#include "render/accumulation.h"
#include "render/camera.h"
#include "render/chaos_kernel.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "schema/validation.h"
#include "tone/palette.h"

using namespace gridifs;

namespace {

constexpr double kPiFunctions = 3.14159265358979323846;

/// A genome with deterministic, dependent and parametric variations and a post map.
const char* kGenome =
    R"(<flame name="mix" size="320 240" center="0.3 -0.2" scale="70" rotate="40" quality="10" palette="5">
  <xform weight="1" color="0" swirl="0.6" spherical="0.4" coefs="0.6 0.25 -0.25 0.6 0.3 0.1"/>
  <xform weight="0.8" color="0.5" popcorn="0.5" linear="0.5" coefs="0.5 -0.1 0.2 0.55 -0.4 0.2" post="0.9 0.1 -0.1 0.9 0.05 0"/>
  <xform weight="0.6" color="1" rings2="0.7" rings2_val="0.4" heart="0.3" coefs="0.7 0 0 0.7 0 -0.3"/>
</flame>)";

FlameImport importMix() { return importFlameGenome(parseFlameFile(kGenome)[0], {}); }

}  // namespace

TEST(FunctionVariations, ANativeImportKeepsTheVariationsByName) {
  const FlameImport imported = importMix();
  EXPECT_TRUE(imported.warnings.empty());
  const Function& f = imported.project.functions[2];
  EXPECT_EQ(f.variations, (std::map<std::string, double>{{"heart", 0.3}, {"rings2", 0.7}}));
  EXPECT_EQ(f.variation_params, (std::map<std::string, double>{{"rings2_val", 0.4}}));
  EXPECT_FALSE(f.sampling_error);
  EXPECT_EQ(f.resolution, (Index3{2, 2, 2}));
  ASSERT_TRUE(imported.project.functions[1].post);
  EXPECT_FALSE(f.post);
}

TEST(FunctionVariations, TheCompiledMapIsTheGenomesMapOnTheWholePlane) {
  const FlameGenome genome = parseFlameFile(kGenome)[0];
  const FlameImport imported = importFlameGenome(genome, {});
  const auto ifs = compileIfs(imported.project);
  ASSERT_EQ(ifs->functions.size(), 3u);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-4.0, 4.0);  // far beyond X: the grid extrapolates
  std::uint64_t random = 1;
  for (std::size_t i = 0; i < 3; ++i)
    for (int n = 0; n < 300; ++n) {
      const FlamePoint p{double(float(u(rng))), double(float(u(rng))), 0.0};
      const FlamePoint expected = genome.xforms[i].apply(p);
      const auto got = ifs->functions[i].evaluateMap({float(p.x), float(p.y), 0.0f}, random);
      // The chain's point is float and the grid interpolates in float: the map agrees to what a
      // relative change of 1e-6 in its input does (popcorn's tan(3y) amplifies it near its poles).
      double sensitivity = 0.0;
      for (const FlamePoint d :
           {FlamePoint{1e-6 * (1 + std::fabs(p.x)), 0}, FlamePoint{0, 1e-6 * (1 + std::fabs(p.y))}}) {
        const FlamePoint moved = genome.xforms[i].apply({p.x + d.x, p.y + d.y, 0.0});
        sensitivity = std::max(sensitivity, std::hypot(moved.x - expected.x, moved.y - expected.y));
      }
      const double tolerance = 1e-5 * (1.0 + std::hypot(expected.x, expected.y)) + 10.0 * sensitivity;
      EXPECT_NEAR(got[0], expected.x, tolerance) << i << " at " << p.x << ", " << p.y;
      EXPECT_NEAR(got[1], expected.y, tolerance) << i << " at " << p.x << ", " << p.y;
      EXPECT_EQ(got[2], 0.0f);
    }
}

TEST(FunctionVariations, AnAffineGridMapsAsItsAffineMapInTheKernelAndTheReference) {
  const Project imported = importFlameGenome(parseFlameFile(kGenome)[0], {}).project;
  // The same project with one node of the first grid moved: no longer affine.
  nlohmann::json j = nlohmann::json::parse(serializeProject(imported));
  ASSERT_EQ(j["functions"][0]["ops"][0]["type"], "nodes");
  j["functions"][0]["ops"][0]["moves"][0][3][0] = j["functions"][0]["ops"][0]["moves"][0][3][0].get<double>() + 0.3;
  const Project bent = parseProject(j.dump());
  const auto affine = compileIfs(imported), notAffine = compileIfs(bent);
  for (const CompiledFunction& f : affine->functions) EXPECT_TRUE(f.affine);  // every xform is affine
  EXPECT_FALSE(notAffine->functions[0].affine);
  EXPECT_TRUE(notAffine->functions[1].affine);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f);
  for (const auto* ifs : {affine.get(), notAffine.get()})
    for (const CompiledFunction& f : ifs->functions) {
      const kernel::HotFunction hot = kernel::makeHot(f);
      for (int n = 0; n < 200; ++n) {
        const std::array<float, 3> p{u(rng), u(rng), u(rng)};
        const kernel::v4f q = kernel::applyExtrapolated(hot, kernel::v4f{p[0], p[1], p[2], 0.0f});
        const std::array<float, 3> expected = f.evaluateExtrapolated(p);
        for (int d = 0; d < 3; ++d) EXPECT_EQ(q[d], expected[d]) << "the kernel's float operations, bit for bit";
      }
    }
  // The affine map is the trilinear one: at the grid's nodes (and beyond X) within float rounding.
  const CompiledFunction& f = affine->functions[2];
  const Grid evaluated = evaluateFunction(imported.functions[2]);
  for (int k = 0; k < 2; ++k)
    for (int jj = 0; jj < 2; ++jj)
      for (int i = 0; i < 2; ++i) {
        const std::array<float, 3> at{i ? 1.0f : -1.0f, jj ? 1.0f : -1.0f, k ? 1.0f : -1.0f};
        const std::array<float, 3> q = f.evaluateExtrapolated(at);
        for (int d = 0; d < 3; ++d) EXPECT_NEAR(q[d], evaluated.node(i, jj, k)[d], 1e-5);
      }
}

TEST(FunctionVariations, TheCameraOfANativeImportPlacesPointsWhereFlam3Does) {
  const FlameGenome genome = parseFlameFile(kGenome)[0];
  const Project p = importFlameGenome(genome, {}).project;
  const OrbitCamera camera(p.camera, p.render.width, p.render.height);
  const double t = genome.rotate * kPiFunctions / 180.0, ppu = genome.pixelsPerUnit();
  for (const FlamePoint q : {FlamePoint{0.3, -0.2}, FlamePoint{1.0, 0.5}, FlamePoint{-0.7, 0.9}}) {
    // flam3 plots R(rotate)·(p − centre) with x to the right and y down, ppu pixels per unit.
    const double dx = q.x - genome.centerX, dy = q.y - genome.centerY;
    const double rx = std::cos(t) * dx - std::sin(t) * dy, ry = std::sin(t) * dx + std::cos(t) * dy;
    const ProjectedPoint pixel = camera.project({q.x, q.y, 0.0});
    EXPECT_TRUE(pixel.inFront);
    EXPECT_NEAR(pixel.x, 0.5 * genome.width + ppu * rx, 0.05);
    EXPECT_NEAR(pixel.y, 0.5 * genome.height + ppu * ry, 0.05);
  }
}

TEST(FunctionVariations, FilesRoundTripAndTheFieldsAreOptional) {
  Project p = importMix().project;
  p.functions[0].post = PostTransform{};
  p.functions[0].post->placement.rotate = Vec3(0, 0, 15);
  p.functions[0].post->placement.translate = Vec3(0.1, 0, 0);
  const std::string text = serializeProject(p);
  const Project back = parseProject(text);
  EXPECT_EQ(back, p);
  EXPECT_EQ(serializeProject(back), text);
  EXPECT_NE(text.find("\"variations\""), std::string::npos);
  EXPECT_NE(text.find("\"variation_params\""), std::string::npos);
  EXPECT_NE(text.find("\"matrix\""), std::string::npos);  // the genome's post map may shear
  EXPECT_NE(text.find("\"rotate\""), std::string::npos);
  // A function without variations writes none of the fields.
  Project plain = p;
  for (Function& f : plain.functions) {
    f.variations.clear();
    f.variation_params.clear();
    f.post.reset();
  }
  EXPECT_EQ(serializeProject(plain).find("variation"), std::string::npos);
  // The post map in placement form is T + R·(S·q).
  const auto m = p.functions[0].post->affine();
  EXPECT_NEAR(m[0][0], std::cos(15 * kPiFunctions / 180), 1e-12);
  EXPECT_NEAR(m[1][0], std::sin(15 * kPiFunctions / 180), 1e-12);
  EXPECT_NEAR(m[0][3], 0.1, 1e-15);
}

TEST(FunctionVariations, BadVariationsAreRefusedWithTheirPath) {
  Project p = importMix().project;
  auto refused = [](const Project& bad, const std::string& path) {
    try {
      validateProject(bad);
      ADD_FAILURE() << "accepted " << path;
    } catch (const ModelError& e) {
      EXPECT_EQ(e.path(), path) << e.what();
    }
  };
  Project unknown = p;
  unknown.functions[1].variations["swril"] = 0.5;
  refused(unknown, "functions[1].variations.swril");
  Project parameter = p;
  parameter.functions[0].variation_params["rings2_value"] = 0.5;
  refused(parameter, "functions[0].variation_params.rings2_value");
  Project infinite = p;
  infinite.functions[0].variations["swirl"] = std::numeric_limits<double>::infinity();
  refused(infinite, "functions[0].variations.swirl");
  EXPECT_THROW(parseProject(R"({"format": "gridifs", "version": 1, "functions": [{"variations": {"swirl": "x"}}]})"),
               ModelError);
}

TEST(FunctionVariations, BadValuesAreReplacedCountedAndKeptOutOfEveryBuffer) {
  // log at the origin is −∞: f1 collapses every point onto the origin and takes its log; f2 is a
  // contraction. flam3 replaces such points with fresh random ones and goes on; so does the chaos game.
  Project p = importMix().project;
  p.functions.resize(2);
  p.functions[0].variations = {{"log", 1.0}};
  p.functions[0].variation_params.clear();
  p.functions[0].post.reset();
  p.functions[0].ops.clear();
  p.functions[0].placement.scale = Vec3(0.0);
  const auto ifs = compileIfs(p);
  RenderJob job = RenderJob::fromProject(p, 2);
  job.width = 64;
  job.height = 48;
  job.samples = 200'000;
  job.accumulateColor = true;
  job.palette = std::make_shared<const Palette>(builtinPalette("ember"));
  const Accumulation a = accumulateToCompletion(ifs, job);
  EXPECT_GT(a.badSamples, 20'000);  // about f1's share (0.55) of the samples past a restart
  EXPECT_LT(a.badSamples, 200'000);
  EXPECT_GT(a.plotted, 1'000);
  RenderImage image;
  toRenderImage(a, DisplaySettings::fromProject(p), image);
  for (float v : image.colorSums) ASSERT_TRUE(std::isfinite(v));
  for (float d : image.depth) ASSERT_FALSE(std::isnan(d));
}

TEST(FunctionVariations, RandomVariationsAreDeterministicPerSeedForAnyThreadCount) {
  const FlameGenome genome = parseFlameFile(R"(<flame name="r" size="100 80" scale="30" palette="1">
    <xform weight="1" color="0" julia="0.7" blur="0.3" coefs="0.6 0.2 -0.2 0.6 0.2 0"/>
    <xform weight="1" color="1" julian="1" julian_power="4" pre_blur="0.2" coefs="0.5 0 0 0.5 -0.3 0.1"/>
  </flame>)")[0];
  test::expectAFunctionOfTheSeedForAnyThreadCount(importFlameGenome(genome, {}).project, 300'000);
}
