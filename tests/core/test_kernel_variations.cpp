// The chaos kernel's variation path (evaluateKernelVariations: inline dispatch, sin, cos and atan2
// from variations/kernel_math.h) against the reference path (evaluateVariations, std:: math) for every
// variation of the table, at a tolerance far below the renderer's float points, and with the same
// random draws.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "variations/flame_variations.h"
#include "variations/kernel_math.h"

using namespace gridifs;

namespace {

/// The kernel keeps points in float (relative step 6e-8); 1e-6 of the magnitude is well inside.
bool close(double got, double expected) {
  if (!std::isfinite(expected)) return true;  // a pole: both paths leave the escape bound
  return std::fabs(got - expected) <= 1e-6 * (1.0 + std::fabs(expected));
}

}  // namespace

TEST(KernelMath, SinCosAtan2AreAccurateFarBelowFloat) {
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), decade(-4.0, 4.9);
  for (int i = 0; i < 200000; ++i) {
    const double x = unit(gen) * std::pow(10.0, decade(gen)), y = unit(gen) * std::pow(10.0, decade(gen));
    EXPECT_NEAR(kernel_math::sin(x), std::sin(x), 1e-10) << x;
    EXPECT_NEAR(kernel_math::cos(x), std::cos(x), 1e-10) << x;
    const double a = std::atan2(y, x);
    EXPECT_LE(std::fabs(kernel_math::atan2(y, x) - a), 1e-9 * std::fabs(a)) << y << ", " << x;
  }
  // The library's values where the reduction does not apply: zeros, infinities, NaN, huge arguments.
  for (const double x : {0.0, -0.0, 1e6, -3e7}) EXPECT_EQ(kernel_math::sin(x), std::sin(x)) << x;
  for (const double y : {0.0, -0.0, 1.0, -1.0})
    for (const double x : {0.0, -0.0, 2.0, -2.0})
      EXPECT_NEAR(kernel_math::atan2(y, x), std::atan2(y, x), 1e-9) << y << ", " << x;
  EXPECT_TRUE(std::isnan(kernel_math::cos(NAN)) && std::isnan(kernel_math::sin(INFINITY)));
  EXPECT_TRUE(std::isnan(kernel_math::atan2(NAN, 1.0)));
}

TEST(KernelVariations, EveryVariationAgreesWithTheReferencePath) {
  std::mt19937_64 gen(11);
  std::uniform_real_distribution<double> coord(-2.0, 2.0), weight(0.2, 1.5), jitter(-0.5, 0.5);
  const auto& table = flameVariations();
  for (const FlameVariation& v : table) {
    for (int i = 0; i < 2000; ++i) {
      const FlamePoint p{coord(gen), coord(gen), coord(gen)};
      std::vector<double> params;
      for (const auto& [name, fallback] : v.params) params.push_back(fallback + jitter(gen));
      const FlameAffine coefs{0.8 + jitter(gen), jitter(gen), jitter(gen), jitter(gen), 0.8 + jitter(gen), jitter(gen)};
      const VariationTerm term{&v, weight(gen), params.data()};
      const KernelVariationTerm kernel = makeKernelVariationTerm(term);
      ASSERT_GE(kernel.body, 0) << v.name;
      const std::uint64_t seed = gen();
      std::uint64_t s1 = seed, s2 = seed;
      const FlamePoint want = evaluateVariations(&term, 1, p, coefs, &s1);
      const FlamePoint got = evaluateKernelVariations(&kernel, 1, v.pre, p, coefs, &s2);
      EXPECT_EQ(s1, s2) << v.name << ": the kernel path draws differently";
      EXPECT_TRUE(close(got.x, want.x) && close(got.y, want.y) && close(got.z, want.z))
          << v.name << " at (" << p.x << ", " << p.y << ", " << p.z << "): kernel (" << got.x << ", " << got.y << ", "
          << got.z << "), reference (" << want.x << ", " << want.y << ", " << want.z << ")";
    }
  }
}

TEST(KernelVariations, ABodyCalledOnItsOwnIsTheSumOfOneTermBitForBit) {
  // What a function of a single term runs (CompiledVariations::singleBody): the same numbers and
  // draws as the sum, -0 included.
  std::mt19937_64 gen(12);
  std::uniform_real_distribution<double> coord(-2.0, 2.0), weight(0.2, 1.5), jitter(-0.5, 0.5);
  int checked = 0;
  for (const FlameVariation& v : flameVariations()) {
    std::vector<double> params;
    for (const auto& [name, fallback] : v.params) params.push_back(fallback + jitter(gen));
    const VariationTerm term{&v, weight(gen), params.data()};
    const KernelVariationTerm kernel = makeKernelVariationTerm(term);
    if (kernel.pre || kernel.flatten) continue;
    const KernelBodyFn body = kernelVariationBody(kernel.body);
    ASSERT_NE(body, nullptr) << v.name;
    ++checked;
    for (int i = 0; i < 200; ++i) {
      const FlamePoint p = i == 0 ? FlamePoint{0.0, -0.0, 0.0} : FlamePoint{coord(gen), coord(gen), coord(gen)};
      const FlameAffine coefs{0.8 + jitter(gen), jitter(gen), jitter(gen), jitter(gen), 0.8 + jitter(gen), jitter(gen)};
      const std::uint64_t seed = gen();
      std::uint64_t s1 = seed, s2 = seed;
      const FlamePoint sum = evaluateKernelVariations(&kernel, 1, false, p, coefs, &s1);
      const FlamePoint q = body(VariationInput{p.x, p.y, p.z, &coefs, kernel.params, &s2}, kernel.weight);
      FlamePoint single;
      single.x += q.x;
      single.y += q.y;
      single.z += kernel.writesZ ? q.z : kernel.weight * p.z;
      EXPECT_EQ(s1, s2) << v.name;
      EXPECT_EQ(std::memcmp(&sum, &single, sizeof sum), 0)
          << v.name << " at (" << p.x << ", " << p.y << ", " << p.z << ")";
    }
  }
  EXPECT_GT(checked, 90);
  EXPECT_EQ(kernelVariationBody(-1), nullptr);
}

TEST(KernelVariations, SumsWithPreVariationsAndFlattenAgree) {
  const auto term = [](const char* name, double w) { return VariationTerm{findFlameVariation(name), w, nullptr}; };
  const std::vector<double> julianParams{5.0, 0.5};
  std::vector<VariationTerm> terms{term("pre_blur", 0.1), term("julia", 0.8), term("spherical", 0.2),
                                   term("heart", 0.5), term("flatten", 1.0)};
  terms.push_back({findFlameVariation("julian"), 0.7, julianParams.data()});
  std::vector<KernelVariationTerm> kernel;
  for (const VariationTerm& t : terms) kernel.push_back(makeKernelVariationTerm(t));
  std::mt19937_64 gen(3);
  std::uniform_real_distribution<double> coord(-2.0, 2.0);
  for (int i = 0; i < 10000; ++i) {
    const FlamePoint p{coord(gen), coord(gen), coord(gen)};
    std::uint64_t s1 = gen(), s2 = s1;
    const FlamePoint want = evaluateVariations(terms.data(), terms.size(), p, {}, &s1);
    const FlamePoint got = evaluateKernelVariations(kernel.data(), kernel.size(), true, p, {}, &s2);
    EXPECT_EQ(s1, s2);
    EXPECT_TRUE(close(got.x, want.x) && close(got.y, want.y) && got.z == 0.0 && want.z == 0.0) << i;
  }
}
