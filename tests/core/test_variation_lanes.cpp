// The variation stage of four chains at once (variations/variation_lanes.h, variations/lane_math.h): the
// four-lane sin, cos, atan2 and pow against the library's; every four-lane variation against its
// reference body (Draves & Reckase, appendix) with the same random draws; a whole IFS's batched
// stage against each function's own; which IFSs batch; and renders that stay a function of the seed.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "flame_seed_checks.h"
#include "io/flame_genome.h"
#include "io/flame_import.h"
#include "render/accumulation.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "tone/palette.h"
#include "variations/flame_variations.h"
#include "variations/lane_math.h"
#include "variations/variation_lanes.h"

using namespace gridifs;
using lane_math::v4f;

namespace {

/// Float lanes: a few float ulps of the magnitude, plus what float rounding of the angle-like
/// arguments (sin of r², of r·θ, …) does.
bool laneClose(double got, double expected, double tolerance = 2e-5) {
  if (!std::isfinite(expected)) return true;  // a pole: the chain leaves the escape bound either way
  return std::fabs(got - expected) <= tolerance * (1.0 + std::fabs(expected));
}

v4f lanes(const double (&v)[4]) { return v4f{float(v[0]), float(v[1]), float(v[2]), float(v[3])}; }

}  // namespace

TEST(LaneMath, SinCosAtan2AndPowStayWithinAFewFloatUlps) {
  std::mt19937_64 gen(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), decade(-3.0, 3.9), positive(-6.0, 6.0), exponent(-2.0, 2.0);
  for (int i = 0; i < 50000; ++i) {
    double x[4], y[4], b[4], e[4];
    for (int l = 0; l < 4; ++l) {
      x[l] = float(unit(gen) * std::pow(10.0, decade(gen)));
      y[l] = float(unit(gen) * std::pow(10.0, decade(gen)));
      b[l] = float(std::pow(10.0, positive(gen)));
      e[l] = float(exponent(gen));
    }
    const auto sc = lane_math::sincos(lanes(x));
    const v4f a = lane_math::atan2(lanes(y), lanes(x)), p = lane_math::pow(lanes(b), lanes(e));
    for (int l = 0; l < 4; ++l) {
      // Below the reduction limit the error is the float rounding of r and of the series; the
      // library's own beyond it.
      EXPECT_NEAR(sc.sin[l], std::sin(x[l]), 3e-7) << x[l];
      EXPECT_NEAR(sc.cos[l], std::cos(x[l]), 3e-7) << x[l];
      EXPECT_NEAR(a[l], std::atan2(y[l], x[l]), 3e-7 * (1.0 + std::fabs(std::atan2(y[l], x[l]))))
          << y[l] << ", " << x[l];
      const double want = std::pow(b[l], e[l]);
      EXPECT_NEAR(p[l], want, 3e-6 * want) << b[l] << "^" << e[l];
    }
  }
  // Signs of zeros as the library's, NaN and infinities through the library's path.
  const v4f zeros = lane_math::atan2(v4f{0.0f, -0.0f, 0.0f, -0.0f}, v4f{1.0f, 1.0f, -1.0f, -1.0f});
  EXPECT_EQ(zeros[0], 0.0f);
  EXPECT_TRUE(std::signbit(zeros[1]));
  EXPECT_FLOAT_EQ(zeros[2], float(std::atan2(0.0, -1.0)));
  EXPECT_FLOAT_EQ(zeros[3], float(std::atan2(-0.0, -1.0)));
  const auto odd = lane_math::sincos(v4f{NAN, INFINITY, 1e6f, -3e7f});
  EXPECT_TRUE(std::isnan(odd.sin[0]) && std::isnan(odd.cos[1]));
  EXPECT_FLOAT_EQ(odd.sin[2], float(std::sin(1e6)));
  EXPECT_FLOAT_EQ(odd.cos[3], float(std::cos(-3e7)));
  const v4f edge = lane_math::pow(v4f{0.0f, 4.0f, 1e-35f, 2.0f}, v4f{0.5f, 0.5f, 0.5f, 200.0f});
  EXPECT_EQ(edge[0], 0.0f);
  EXPECT_FLOAT_EQ(edge[1], 2.0f);
  EXPECT_FLOAT_EQ(edge[2], float(std::pow(1e-35, 0.5)));
  EXPECT_TRUE(std::isinf(edge[3]));
}

TEST(VariationLanes, EveryFourLaneBodyIsItsReferenceBodyWithTheSameDraws) {
  std::mt19937_64 gen(21);
  std::uniform_real_distribution<double> coord(-2.0, 2.0), weight(0.2, 1.5), jitter(-0.5, 0.5);
  int checked = 0;
  for (const FlameVariation& v : flameVariations()) {
    const LaneBodyFn body = laneVariationBody(v.name);
    if (!body) continue;
    ++checked;
    EXPECT_FALSE(v.pre || v.dependent) << v.name
                                       << ": the four-lane forms read neither the affine fit nor move the point";
    std::vector<double> params[4];
    for (int i = 0; i < 2000; ++i) {
      // Every lane combination: the inactive lanes draw nothing.
      const int active = i < 16 ? i : 0xF;
      VariationLanes in;
      double x[4], y[4], z[4], w[4];
      for (int l = 0; l < 4; ++l) {
        x[l] = float(coord(gen)), y[l] = float(coord(gen)), z[l] = float(coord(gen)), w[l] = float(weight(gen));
        params[l].clear();
        for (const auto& [name, fallback] : v.params) params[l].push_back(fallback + jitter(gen));
        in.params[l] = params[l].data();
      }
      in.x = lanes(x), in.y = lanes(y), in.z = lanes(z), in.weight = lanes(w);
      in.active = active;
      const std::uint64_t seed = gen();
      std::uint64_t laneStream = seed, referenceStream = seed;
      in.random = &laneStream;
      v4f gx{}, gy{}, gz{};
      body(in, gx, gy, gz);
      for (int l = 0; l < 4; ++l) {
        if (!(active >> l & 1)) continue;
        const FlamePoint want =
            v.apply(VariationInput{x[l], y[l], z[l], nullptr, params[l].data(), &referenceStream}, w[l]);
        EXPECT_TRUE(laneClose(gx[l], want.x) && laneClose(gy[l], want.y) && (!v.writesZ || laneClose(gz[l], want.z)))
            << v.name << " lane " << l << " at (" << x[l] << ", " << y[l] << ", " << z[l] << "): lanes (" << gx[l]
            << ", " << gy[l] << ", " << gz[l] << "), reference (" << want.x << ", " << want.y << ", " << want.z << ")";
      }
      EXPECT_EQ(laneStream, referenceStream) << v.name << ": the lanes draw differently";
    }
  }
  EXPECT_GE(checked, 20);
  EXPECT_EQ(laneVariationBody("no such variation"), nullptr);
  EXPECT_EQ(laneVariationBodyIndex("waves"), -1);  // dependent: lane by lane through its kernel body
}

namespace {

/// Deterministic, dependent (popcorn, waves: no four-lane form), parametric and 3D variations, the
/// same variation in several functions with different weights, a post map and flatten.
const char* kBatchGenome = R"(<flame name="batch" size="160 120" scale="40" palette="5">
  <xform weight="1" color="0" swirl="0.6" spherical="0.4" coefs="0.6 0.25 -0.25 0.6 0.3 0.1"/>
  <xform weight="0.8" color="0.5" popcorn="0.5" linear="0.5" handkerchief="0.2" coefs="0.5 -0.1 0.2 0.55 -0.4 0.2" post="0.9 0.1 -0.1 0.9 0.05 0"/>
  <xform weight="0.6" color="1" rings2="0.7" rings2_val="0.4" heart="0.3" swirl="0.1" coefs="0.7 0 0 0.7 0 -0.3"/>
  <xform weight="0.4" color="0.2" waves="0.3" coefs="0.6 0 0.1 0.6 0.2 -0.3"/>
</flame>)";

/// kGenome imported natively, with the 3D bubble and flatten added to its last function (a 3D
/// genome would import sampled onto grids), and a grid function without variations (as a flame's
/// symmetry xforms import).
Project batchProject() {
  Project project = importFlameGenome(parseFlameFile(kBatchGenome)[0], {}).project;
  project.functions[3].variations["bubble"] = 0.5;
  project.functions[3].variations["flatten"] = 1.0;
  Function plain = project.functions[0];
  plain.variations.clear();
  plain.variation_params.clear();
  plain.post.reset();
  project.functions.push_back(plain);
  return project;
}

}  // namespace

TEST(BatchedVariations, AWholeIfsBatchedIsEachFunctionsOwnStage) {
  const auto ifs = compileIfs(batchProject());
  ASSERT_NE(ifs->batchedVariations, nullptr);
  const BatchedVariations& batch = *ifs->batchedVariations;
  // swirl once for the two functions that have it, every other term in a slot of its own; none
  // for the plain function.
  EXPECT_EQ(batch.slots.size(), 10u);
  EXPECT_EQ(batch.keepsGridImage, (std::vector<std::uint8_t>{0, 0, 0, 0, 1}));
  std::mt19937_64 gen(8);
  std::uniform_real_distribution<double> coord(-3.0, 3.0);
  std::uniform_int_distribution<std::uint32_t> pick(0, std::uint32_t(ifs->functions.size() - 1));
  std::uint64_t unused = 0;
  for (int i = 0; i < 20000; ++i) {
    std::uint32_t fn[4];
    v4f q[4];
    std::array<double, 3> grid[4];
    for (int l = 0; l < 4; ++l) {
      fn[l] = pick(gen);
      const CompiledFunction& f = ifs->functions[fn[l]];
      const std::array<float, 3> p{float(coord(gen)), float(coord(gen)), float(coord(gen))};
      // As the kernel gives them: the extrapolated grid map before a variation stage, else the grid's own.
      const auto g = f.variations ? f.evaluateExtrapolated(p) : f.evaluate(p);
      q[l] = v4f{g[0], g[1], g[2], 0.0f};
      grid[l] = {g[0], g[1], g[2]};
    }
    batch.apply(fn, q, unused);
    for (int l = 0; l < 4; ++l) {
      const CompiledFunction& f = ifs->functions[fn[l]];
      const auto want = f.variations ? f.variations->apply(grid[l], unused) : grid[l];
      for (int d = 0; d < 3; ++d)
        EXPECT_TRUE(laneClose(q[l][d], want[std::size_t(d)], 5e-5))
            << "function " << fn[l] << " axis " << d << ": batched " << q[l][d] << ", own " << want[std::size_t(d)];
      EXPECT_EQ(q[l][3], 0.0f);
    }
  }
}

TEST(BatchedVariations, IfssWithAPreVariationTooManyTermsOrNoVariationsDoNotBatch) {
  const Project project = batchProject();
  EXPECT_NE(compileIfs(project)->batchedVariations, nullptr);
  Project pre = project;
  pre.functions[1].variations["pre_blur"] = 0.1;  // moves the point every other term sees
  EXPECT_EQ(compileIfs(pre)->batchedVariations, nullptr);
  Project crowded = project;  // more distinct terms than a slot mask holds
  int added = 0;
  for (const FlameVariation& v : flameVariations())
    if (!v.pre && added < 33 && crowded.functions[0].variations.emplace(v.name, 0.01).second) ++added;
  ASSERT_EQ(added, 33);
  EXPECT_EQ(compileIfs(crowded)->batchedVariations, nullptr);
  Project plain = project;
  for (Function& f : plain.functions) {  // a grid IFS runs its own loop
    f.variations.clear();
    f.post.reset();
  }
  EXPECT_EQ(compileIfs(plain)->batchedVariations, nullptr);
}

TEST(BatchedVariations, RandomVariationsRenderAsAFunctionOfTheSeedForAnyThreadCount) {
  const FlameGenome genome = parseFlameFile(R"(<flame name="r" size="100 80" scale="30" palette="1">
    <xform weight="1" color="0" julia="0.7" blur="0.3" coefs="0.6 0.2 -0.2 0.6 0.2 0"/>
    <xform weight="1" color="1" julian="1" julian_power="4" heart="0.2" coefs="0.5 0 0 0.5 -0.3 0.1"/>
    <xform weight="0.5" color="0.5" noise="0.4" spherical="0.6" coefs="0.5 0 0 0.5 0.3 0.3"/>
  </flame>)")[0];
  const Project p = importFlameGenome(genome, {}).project;
  ASSERT_NE(compileIfs(p)->batchedVariations, nullptr);
  test::expectAFunctionOfTheSeedForAnyThreadCount(p, 300'002);  // a last partial round of two chains, lane by lane
}
