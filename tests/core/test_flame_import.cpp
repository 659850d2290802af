// Flame genomes (Draves & Reckase, "The Fractal Flame Algorithm"): the variations against their
// closed forms written out here independently, the .flame parser, the sampling of xforms into
// grids (exact for affine xforms) and export → import round trips.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>

#include "deterministic_samples.h"
#include "io/flame_export.h"
#include "io/flame_genome.h"
#include "io/flame_import.h"
#include "io/project_io.h"
#include "model/stack_evaluator.h"

using namespace gridifs;

namespace {

constexpr double kPi = 3.14159265358979323846;

FlamePoint vary(const std::string& name, double x, double y, double w, const std::map<std::string, double>& params = {},
                FlameAffine coefs = {}) {
  const FlameVariation* v = findFlameVariation(name);
  EXPECT_NE(v, nullptr) << name;
  if (!v) return {};
  std::vector<double> values;
  for (const auto& [attribute, fallback] : v->params) {
    const auto it = params.find(attribute);
    values.push_back(it == params.end() ? fallback : it->second);
  }
  std::uint64_t random = 1;
  VariationInput in{x, y, 0.0, &coefs, values.data(), &random};
  return v->apply(in, w);
}

void expectNear(FlamePoint got, double x, double y, const std::string& what) {
  EXPECT_NEAR(got.x, x, 1e-9 * (1 + std::fabs(x))) << what;
  EXPECT_NEAR(got.y, y, 1e-9 * (1 + std::fabs(y))) << what;
}

}  // namespace

TEST(FlameVariations, SpotValuesMatchTheClosedForms) {
  const double w = 0.7;
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{{0.3, -0.8}, {-1.2, 0.45}, {0.05, 0.9}}) {
    SCOPED_TRACE(std::to_string(x) + ", " + std::to_string(y));
    const double r2 = x * x + y * y, r = std::sqrt(r2);
    const double theta = std::atan2(x, y);  // the paper's θ = arctan(x / y)
    const double phi = std::atan2(y, x);    // the paper's φ = arctan(y / x)
    expectNear(vary("linear", x, y, w), w * x, w * y, "linear");
    expectNear(vary("sinusoidal", x, y, w), w * std::sin(x), w * std::sin(y), "sinusoidal");
    expectNear(vary("spherical", x, y, w), w * x / r2, w * y / r2, "spherical");
    expectNear(vary("swirl", x, y, w), w * (x * std::sin(r2) - y * std::cos(r2)),
               w * (x * std::cos(r2) + y * std::sin(r2)), "swirl");
    expectNear(vary("horseshoe", x, y, w), w * (x - y) * (x + y) / r, w * 2 * x * y / r, "horseshoe");
    expectNear(vary("polar", x, y, w), w * theta / kPi, w * (r - 1), "polar");
    expectNear(vary("handkerchief", x, y, w), w * r * std::sin(theta + r), w * r * std::cos(theta - r), "handkerchief");
    expectNear(vary("heart", x, y, w), w * r * std::sin(theta * r), -w * r * std::cos(theta * r), "heart");
    expectNear(vary("disc", x, y, w), w * theta / kPi * std::sin(kPi * r), w * theta / kPi * std::cos(kPi * r), "disc");
    expectNear(vary("spiral", x, y, w), w / r * (std::cos(theta) + std::sin(r)),
               w / r * (std::sin(theta) - std::cos(r)), "spiral");
    expectNear(vary("hyperbolic", x, y, w), w * std::sin(theta) / r, w * r * std::cos(theta), "hyperbolic");
    expectNear(vary("diamond", x, y, w), w * std::sin(theta) * std::cos(r), w * std::cos(theta) * std::sin(r),
               "diamond");
    const double p0 = std::sin(theta + r), p1 = std::cos(theta - r);
    expectNear(vary("ex", x, y, w), w * r * (p0 * p0 * p0 + p1 * p1 * p1), w * r * (p0 * p0 * p0 - p1 * p1 * p1), "ex");
    expectNear(vary("bent", x, y, w), w * (x < 0 ? 2 * x : x), w * (y < 0 ? y / 2 : y), "bent");
    const FlameAffine coefs{0.4, 0.3, 0.25, -0.2, 0.6, 0.35};  // a b c d e f
    // flam3 adds 1e-10 to c² and f² against division by zero.
    expectNear(vary("waves", x, y, w, {}, coefs), w * (x + 0.3 * std::sin(y / (0.25 * 0.25 + 1e-10))),
               w * (y + 0.6 * std::sin(x / (0.35 * 0.35 + 1e-10))), "waves");
    expectNear(vary("fisheye", x, y, w), w * 2 / (r + 1) * y, w * 2 / (r + 1) * x, "fisheye");
    expectNear(vary("popcorn", x, y, w, {}, coefs), w * (x + 0.25 * std::sin(std::tan(3 * y))),
               w * (y + 0.35 * std::sin(std::tan(3 * x))), "popcorn");
    expectNear(vary("exponential", x, y, w), w * std::exp(x - 1) * std::cos(kPi * y),
               w * std::exp(x - 1) * std::sin(kPi * y), "exponential");
    expectNear(vary("power", x, y, w), w * std::pow(r, std::sin(theta)) * std::cos(theta),
               w * std::pow(r, std::sin(theta)) * std::sin(theta), "power");
    expectNear(vary("cosine", x, y, w), w * std::cos(kPi * x) * std::cosh(y), -w * std::sin(kPi * x) * std::sinh(y),
               "cosine");
    const double c2 = 0.25 * 0.25;
    const double ringR = std::fmod(r + c2, 2 * c2) - c2 + r * (1 - c2);
    expectNear(vary("rings", x, y, w, {}, coefs), w * ringR * std::cos(theta), w * ringR * std::sin(theta), "rings");
    const double blobR = r * (0.2 + (1.3 - 0.2) / 2 * (std::sin(3 * theta) + 1));
    expectNear(vary("blob", x, y, w, {{"blob_low", 0.2}, {"blob_high", 1.3}, {"blob_waves", 3}}), w * blobR * x / r,
               w * blobR * y / r, "blob");
    expectNear(vary("pdj", x, y, w, {{"pdj_a", 1.1}, {"pdj_b", -0.7}, {"pdj_c", 2.3}, {"pdj_d", 0.4}}),
               w * (std::sin(1.1 * y) - std::cos(-0.7 * x)), w * (std::sin(2.3 * x) - std::cos(0.4 * y)), "pdj");
    expectNear(vary("eyefish", x, y, w), w * 2 / (r + 1) * x, w * 2 / (r + 1) * y, "eyefish");
    expectNear(vary("bubble", x, y, w), w * 4 / (r2 + 4) * x, w * 4 / (r2 + 4) * y, "bubble");
    expectNear(vary("cylinder", x, y, w), w * std::sin(x), w * y, "cylinder");
    {
      const double angle = 0.3 * kPi / 2, dist = 2.5;
      const double k = dist / (dist - y * std::sin(angle));
      expectNear(vary("perspective", x, y, w, {{"perspective_angle", 0.3}, {"perspective_dist", dist}}), w * k * x,
                 w * k * y * std::cos(angle), "perspective");
    }
    {
      const double c1 = 0.3, cc2 = -0.2;
      // curl: z / (1 + c1·z + c2·z²) in complex numbers.
      const std::complex<double> z(x, y), out = z / (1.0 + c1 * z + cc2 * z * z);
      expectNear(vary("curl", x, y, w, {{"curl_c1", c1}, {"curl_c2", cc2}}), w * out.real(), w * out.imag(), "curl");
    }
    {
      const double rx = 0.3, ry = 0.7;
      expectNear(vary("rectangles", x, y, w, {{"rectangles_x", rx}, {"rectangles_y", ry}}),
                 w * ((2 * std::floor(x / rx) + 1) * rx - x), w * ((2 * std::floor(y / ry) + 1) * ry - y),
                 "rectangles");
    }
    expectNear(vary("tangent", x, y, w), w * std::sin(x) / std::cos(y), w * std::tan(y), "tangent");
    {
      const std::complex<double> z(x, y);
      const auto e = std::exp(z), l = std::log(z), s = std::sin(z), c = std::cos(z), t = std::tan(z), sh = std::sinh(z),
                 ch = std::cosh(z), th = std::tanh(z);
      expectNear(vary("exp", x, y, w), w * e.real(), w * e.imag(), "exp");
      expectNear(vary("log", x, y, w), w * l.real(), w * l.imag(), "log");
      expectNear(vary("sin", x, y, w), w * s.real(), w * s.imag(), "sin");
      expectNear(vary("cos", x, y, w), w * c.real(), w * c.imag(), "cos");
      expectNear(vary("tan", x, y, w), w * t.real(), w * t.imag(), "tan");
      expectNear(vary("sinh", x, y, w), w * sh.real(), w * sh.imag(), "sinh");
      expectNear(vary("cosh", x, y, w), w * ch.real(), w * ch.imag(), "cosh");
      expectNear(vary("tanh", x, y, w), w * th.real(), w * th.imag(), "tanh");
      const auto sec = 1.0 / c, sech = 1.0 / ch;
      expectNear(vary("sec", x, y, w), w * sec.real(), w * sec.imag(), "sec");
      expectNear(vary("sech", x, y, w), w * sech.real(), w * sech.imag(), "sech");
      const auto csc = 1.0 / s, cot = c / s, csch = 1.0 / sh;
      expectNear(vary("csc", x, y, w), w * csc.real(), w * csc.imag(), "csc");
      expectNear(vary("cot", x, y, w), w * cot.real(), w * cot.imag(), "cot");
      expectNear(vary("csch", x, y, w), w * csch.real(), w * csch.imag(), "csch");
      // flam3's coth is that of the conjugate point.
      const auto coth = std::cosh(std::conj(z)) / std::sinh(std::conj(z));
      expectNear(vary("coth", x, y, w), w * coth.real(), w * coth.imag(), "coth");
      const std::complex<double> a(0.8, 0.1), b(0.2, -0.3), cc(0.1, 0.4), d(1.0, 0.2);
      const auto m = (a * z + b) / (cc * z + d);
      expectNear(vary("mobius", x, y, w,
                      {{"mobius_re_a", 0.8},
                       {"mobius_im_a", 0.1},
                       {"mobius_re_b", 0.2},
                       {"mobius_im_b", -0.3},
                       {"mobius_re_c", 0.1},
                       {"mobius_im_c", 0.4},
                       {"mobius_re_d", 1.0},
                       {"mobius_im_d", 0.2}}),
                 w * m.real(), w * m.imag(), "mobius");
    }
    expectNear(vary("polar2", x, y, w), w / kPi * theta, w / (2 * kPi) * std::log(r2), "polar2");
    expectNear(vary("cross", x, y, w), w * x / std::fabs(x * x - y * y), w * y / std::fabs(x * x - y * y), "cross");
    (void)phi;
  }
}

TEST(FlameVariations, RandomOnesAreInTheTable) {
  for (const char* name : {"julia",  "blur",  "noise",    "julian",   "juliascope", "gaussian_blur", "radial_blur",
                           "pie",    "arch",  "square",   "rays",     "blade",      "twintrian",     "super_shape",
                           "flower", "conic", "parabola", "boarders", "cpow",       "pre_blur",      "wedge_julia"}) {
    EXPECT_TRUE(isRandomFlameVariation(name)) << name;
    EXPECT_NE(findFlameVariation(name), nullptr) << name;
  }
  // flam3 3.1 numbers 99 variations (0–98); the 3D extensions come after them.
  EXPECT_EQ(flameVariationIndex("mobius"), 98);
  EXPECT_EQ(flameVariationIndex("linear"), 0);
  EXPECT_EQ(flameVariationIndex("pre_blur"), 67);
}

TEST(FlameGenome, ParsesCoefsPostChaosColorsAndPalettes) {
  const auto genomes = parseFlameFile(R"(<flames>
    <flame name="one" size="200 100" center="0.5 -0.25" scale="50" zoom="1" rotate="30" quality="10"
           brightness="3" gamma="2.5" vibrancy="0.5" background="0.1 0.2 0.3" palette="7" supersample="2">
      <xform weight="2" color="0.25" symmetry="0.5" spherical="0.5" linear="0.5" coefs="1 2 3 4 5 6"
             post="0.5 0 0 0.5 0.1 0.2" chaos="0 2"/>
      <xform weight="1" color="0.75" blob="1" blob_low="0.3" julia="1" coefs="0.5 0 0 0.5 0 0"/>
      <finalxform color="1" bubble="1" coefs="1 0 0 1 0 0"/>
    </flame>
    <flame name="two" size="10 10"><xform weight="1" linear="1" coefs="1 0 0 1 0 0"/>
      <color index="0" rgb="255 0 0"/><color index="255" rgb="0 0 255"/></flame>
  </flames>)");
  ASSERT_EQ(genomes.size(), 2u);
  const FlameGenome& g = genomes[0];
  EXPECT_EQ(g.name, "one");
  EXPECT_EQ(g.width, 200);
  EXPECT_DOUBLE_EQ(g.pixelsPerUnit(), 100.0);
  EXPECT_EQ(g.paletteNumber, 7);
  EXPECT_EQ(g.supersample, 2);
  ASSERT_EQ(g.xforms.size(), 2u);
  const FlameXform& x = g.xforms[0];
  // "a d b e c f": x' = a x + b y + c, y' = d x + e y + f.
  EXPECT_EQ(x.coefs, (FlameAffine{1, 3, 5, 2, 4, 6}));
  EXPECT_EQ(x.post, (FlameAffine{0.5, 0, 0.1, 0, 0.5, 0.2}));
  EXPECT_DOUBLE_EQ(x.color_speed, 0.25);  // (1 − symmetry) / 2
  EXPECT_EQ(x.chaos, (std::vector<double>{0, 2}));
  EXPECT_FALSE(x.isAffine());
  EXPECT_DOUBLE_EQ(g.xforms[1].params.at("blob_low"), 0.3);
  ASSERT_TRUE(g.finalXform);
  EXPECT_DOUBLE_EQ(g.finalXform->color_speed, 0.0);
  // Random variations are kept like every other one.
  EXPECT_EQ(g.xforms[1].variations, (std::vector<std::pair<std::string, double>>{{"blob", 1.0}, {"julia", 1.0}}));
  // The whole map: post(Σ w V(pre(p))).
  const FlamePoint p{0.3, -0.2}, t{1 * 0.3 + 3 * -0.2 + 5, 2 * 0.3 + 4 * -0.2 + 6};
  const double r2 = t.x * t.x + t.y * t.y;
  const FlamePoint v{0.5 * t.x / r2 + 0.5 * t.x, 0.5 * t.y / r2 + 0.5 * t.y};
  const FlamePoint q = x.apply(p);
  EXPECT_NEAR(q.x, 0.5 * v.x + 0.1, 1e-12);
  EXPECT_NEAR(q.y, 0.5 * v.y + 0.2, 1e-12);
  ASSERT_TRUE(genomes[1].palette);
  EXPECT_EQ(genomes[1].palette->colors[0], (Rgb{1, 0, 0}));
  EXPECT_EQ(genomes[1].palette->colors[255], (Rgb{0, 0, 1}));
  EXPECT_EQ(&selectGenome(genomes, "two"), &genomes[1]);
  EXPECT_EQ(&selectGenome(genomes, "1"), &genomes[1]);
  EXPECT_THROW(selectGenome(genomes, "three"), FlameError);
  EXPECT_THROW(selectGenome(genomes, "2"), FlameError);
}

TEST(FlameGenome, BadFilesAreRefused) {
  EXPECT_THROW(parseFlameFile(""), FlameError);
  EXPECT_THROW(parseFlameFile("<flame size=\"10 10\">"), FlameError);
  EXPECT_THROW(parseFlameFile("<flame size=\"10 10\"></flame>"), FlameError);
  EXPECT_THROW(parseFlameFile("<flame size=\"10 10\"><xform weight=\"1\" coefs=\"1 0 0 1 0 inf\"/></flame>"),
               FlameError);
  EXPECT_THROW(parseFlameFile("<flame size=\"10 10\"><xform weight=\"1\" coefs=\"1 0 0 1 0\"/></flame>"), FlameError);
  EXPECT_THROW(parseFlameFile("<flame size=\"0 10\"><xform weight=\"1\" coefs=\"1 0 0 1 0 0\"/></flame>"), FlameError);
  EXPECT_THROW(parseFlameFile("<flame size=\"10 10\"><xform weight=\"-1\" coefs=\"1 0 0 1 0 0\"/></flame>"),
               FlameError);
  std::string deep;
  for (int i = 0; i < 100; ++i) deep += "<a>";
  EXPECT_THROW(parseFlameFile(deep + "<flame size=\"10 10\"/>"), FlameError);
}

TEST(FlameImport, AffineXformsAreExactTwoByTwoByTwoGrids) {
  const auto genomes = parseFlameFile(R"(<flame name="affine" size="300 200" center="0.4 -0.3" scale="60" rotate="25">
      <xform weight="1" color="0" linear="1" coefs="0.5 0.2 -0.1 0.6 0.3 -0.2" post="0.9 0.1 0 1 0 0.05"/>
      <xform weight="3" color="1" linear="0.7" coefs="0.4 -0.3 0.3 0.4 -0.5 0.1"/>
    </flame>)");
  FlameImportOptions grids;
  grids.sampleOntoGrids = true;
  const FlameImport imported = importFlameGenome(genomes[0], grids);
  ASSERT_EQ(imported.project.functions.size(), 2u);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < 2; ++i) {
    const Function& fn = imported.project.functions[i];
    EXPECT_EQ(fn.resolution, (Index3{2, 2, 2}));
    ASSERT_TRUE(fn.sampling_error);
    EXPECT_LT(*fn.sampling_error, 1e-12);
    const auto grid = evaluateFunctionAt(fn, "");
    for (int n = 0; n < 200; ++n) {
      const Vec3 p(u(rng), u(rng), u(rng));
      const FlamePoint expected = imported.frame.toX(genomes[0].xforms[i].apply(imported.frame.fromX({p.x, p.y})));
      const Vec3 got = grid->evaluate(p);
      EXPECT_NEAR(got.x, expected.x, 1e-12);
      EXPECT_NEAR(got.y, expected.y, 1e-12);
      EXPECT_NEAR(got.z, 0.0, 1e-15);
    }
  }
  EXPECT_EQ(imported.project.functions[1].weight, 3.0);
  // The frame is a similarity: fromX inverts toX.
  const FlamePoint a{1.7, -2.2}, b = imported.frame.fromX(imported.frame.toX(a));
  EXPECT_NEAR(a.x, b.x, 1e-12);
  EXPECT_NEAR(a.y, b.y, 1e-12);
  // The camera frames the genome's view: half its height in X.
  const Camera& cam = imported.project.camera;
  EXPECT_TRUE(cam.orthographic());
  EXPECT_NEAR(cam.distance * std::tan(cam.fov * kPi / 360.0), 0.5 * 200 / 60 * imported.frame.scale, 1e-12);
}

TEST(FlameImport, NonlinearSamplingErrorShrinksWithResolution) {
  const auto genomes = parseFlameFile(R"(<flame name="swirl" size="100 100" scale="30">
      <xform weight="1" color="0" swirl="1" coefs="0.6 0.2 -0.2 0.6 0.2 0"/>
      <xform weight="1" color="1" linear="1" coefs="0.5 0 0 0.5 -0.4 0"/>
    </flame>)");
  FlameImportOptions coarse, fine;
  coarse.sampleOntoGrids = fine.sampleOntoGrids = true;
  coarse.resolution = 16;
  fine.resolution = 64;
  const FlameImport a = importFlameGenome(genomes[0], coarse), b = importFlameGenome(genomes[0], fine);
  EXPECT_EQ(a.project.functions[0].resolution, (Index3{16, 16, 2}));
  EXPECT_EQ(b.project.functions[0].resolution, (Index3{64, 64, 2}));
  EXPECT_EQ(b.project.functions[1].resolution, (Index3{2, 2, 2}));
  const double ea = *a.project.functions[0].sampling_error, eb = *b.project.functions[0].sampling_error;
  EXPECT_GT(ea, 0.0);
  EXPECT_LT(eb, ea / 8.0);  // bilinear sampling: error ∝ cell size²
  // The recorded error is what flameSamplingError measures.
  EXPECT_DOUBLE_EQ(eb, flameSamplingError(b.project.functions[0], genomes[0].xforms[0], b.frame));
}

TEST(FlameImport, ChaosBecomesTransitionsAndFinalXformTheFinalFunction) {
  const auto genomes = parseFlameFile(R"(<flame name="c" size="100 100" scale="30" palette="3">
      <xform weight="1" color="0" linear="1" chaos="0 1" coefs="0.5 0 0 0.5 -0.4 0"/>
      <xform weight="1" color="1" linear="1" coefs="0.5 0 0 0.5 0.4 0"/>
      <finalxform color="0.5" color_speed="0.2" linear="1" coefs="1 0 0 -1 0 0"/>
    </flame>)");
  const FlameImport imported = importFlameGenome(genomes[0], {});
  EXPECT_EQ(imported.project.transitions, (std::vector<std::vector<double>>{{0, 1}, {1, 1}}));
  ASSERT_TRUE(imported.project.final_function);
  EXPECT_DOUBLE_EQ(imported.project.final_function->color_speed, 0.2);
  EXPECT_EQ(imported.project.render.flame.palette, "flam3:3");
  EXPECT_EQ(imported.project.render.mode, DisplayMode::Flame);
}

TEST(FlameExport, AffineProjectsRoundTripExactly) {
  Project p = test_support::sierpinskiProject();
  for (Function& f : p.functions) f.placement.scale.z = f.placement.translate.z = 0.0;  // a plane IFS
  p.functions[1].placement.rotate = Vec3(0, 0, 20);
  p.functions[2].weight = 2.5;
  p.functions[3].color_speed = 0.3;
  p.functions[3].palette_index = 0.8;
  p.transitions = {{0, 1, 1, 1}, {1, 0, 1, 1}, {1, 1, 0, 2}, {1, 1, 1, 1}};
  p.render.flame.palette = "ember";
  p.camera.projection = CameraProjection::Orthographic;
  p.camera.pitch = 90;
  const FlameExport exported = exportFlame(p, {}, "round trip");
  EXPECT_TRUE(exported.warnings.empty()) << exported.warnings.front();
  const auto genomes = parseFlameFile(exported.xml);
  FlameImportOptions options;
  options.inlinePaletteReference = "file:rt.palette.json";
  const FlameImport back = importFlameGenome(genomes[0], options);
  ASSERT_EQ(back.project.functions.size(), 4u);
  EXPECT_EQ(back.project.transitions, p.transitions);
  for (std::size_t i = 0; i < 4; ++i) {
    const auto a = evaluateFunctionAt(p.functions[i], ""), b = evaluateFunctionAt(back.project.functions[i], "");
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int n = 0; n < 2; ++n) {
          const Vec3 d = a->node(n, j, k) - b->node(n, j, k);
          EXPECT_LT(std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z), 1e-9) << i;
        }
    EXPECT_EQ(back.project.functions[i].weight, p.functions[i].weight);
    EXPECT_EQ(back.project.functions[i].color_speed, p.functions[i].color_speed);
    EXPECT_EQ(back.project.functions[i].palette_index, p.functions[i].palette_index);
  }
  ASSERT_TRUE(back.palette);
  EXPECT_EQ(back.project.render.flame.palette, "file:rt.palette.json");
}

TEST(FlameExport, FitAffineReportsNonAffineGrids) {
  Function f;
  f.resolution = {4, 4, 2};
  double error = 1.0;
  fitAffine(*evaluateFunctionAt(f, ""), error);
  EXPECT_GT(error, 0.5);  // the identity keeps z = ±1, which the plane fit cannot
  f.placement.scale = Vec3(0.5, 0.5, 0.0);
  FlameAffine fit = fitAffine(*evaluateFunctionAt(f, ""), error);
  EXPECT_LT(error, 1e-12);
  EXPECT_NEAR(fit.a, 0.5, 1e-12);
  EXPECT_NEAR(fit.e, 0.5, 1e-12);
  f.ops.push_back(Operation{TwistOp{Axis::Z, Profile::Linear, 1.0, 1.0}, Center{}, Selection{}, false});
  f.placement.scale = Vec3(0.5, 0.5, 1.0);
  fitAffine(*evaluateFunctionAt(f, ""), error);
  EXPECT_GT(error, 0.05);
}
