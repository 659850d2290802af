// Every flame variation against an independent evaluation: tests/data/flame/variation_reference.py
// computes flam3 3.1's formulas (Draves & Reckase, "The Fractal Flame Algorithm", appendix; flam3's
// variations.c for the later ones) and the documented 3D forms, and writes the JSON read here. The
// deterministic variations are compared value by value; the random ones by the mean, variance and
// branch frequencies of 10^6 draws against moments the script computes by quadrature.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "variations/flame_variations.h"

using namespace gridifs;

namespace {

using nlohmann::json;

const json& reference() {
  static const json data = [] {
    std::ifstream in(std::string(GRIDIFS_TEST_DATA) + "/flame/variation_reference.json");
    return json::parse(in);
  }();
  return data;
}

bool near(double got, double expected) { return std::fabs(got - expected) <= 1e-6 * (1.0 + std::fabs(expected)); }

struct Case {
  FlamePoint p;
  double weight;
  std::vector<double> params;
  FlameAffine coefs;
};

Case readCase(const json& c) {
  Case out;
  out.p = {c["p"][0].get<double>(), c["p"][1].get<double>(), c["p"][2].get<double>()};
  out.weight = c["weight"].get<double>();
  out.params = c["params"].get<std::vector<double>>();
  if (c.contains("coefs")) {
    const auto k = c["coefs"].get<std::vector<double>>();
    out.coefs = {k[0], k[1], k[2], k[3], k[4], k[5]};
  }
  return out;
}

std::string describeCase(const std::string& name, const Case& c) {
  std::string s = name + " at (" + std::to_string(c.p.x) + ", " + std::to_string(c.p.y) + ", " + std::to_string(c.p.z) +
                  "), w = " + std::to_string(c.weight);
  if (!c.params.empty()) {
    s += ", params {";
    for (std::size_t k = 0; k < c.params.size(); ++k) s += (k ? ", " : "") + std::to_string(c.params[k]);
    s += "}";
  }
  return s;
}

// A fixed stream state per variation (FNV-1a of its name), the same on every platform.
std::uint64_t seedFor(const std::string& name) {
  std::uint64_t h = 0xCBF29CE484222325ull;
  for (const char ch : name) h = (h ^ std::uint8_t(ch)) * 0x100000001B3ull;
  return h;
}

std::string triple(double x, double y, double z) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "(%.12g, %.12g, %.12g)", x, y, z);
  return buffer;
}

/// A deterministic variation's reference cases and the table's variation of that name (null when
/// the table has none, which each test asserts against).
struct DeterministicEntry {
  std::string name;
  const FlameVariation* variation;
  const json& cases;
};

std::vector<DeterministicEntry> deterministicEntries() {
  std::vector<DeterministicEntry> out;
  for (const json& entry : reference()["deterministic"]) {
    const std::string name = entry["name"];
    out.push_back({name, findFlameVariation(name), entry["cases"]});
  }
  return out;
}

/// evaluateVariations with `v` as its one term, from the stream state 1.
FlamePoint evaluateOneTerm(const FlameVariation* v, const Case& c) {
  std::uint64_t random = 1;
  const VariationTerm term{v, c.weight, c.params.data()};
  return evaluateVariations(&term, 1, c.p, c.coefs, &random);
}

}  // namespace

TEST(VariationReference, EveryDeterministicVariationHasReferenceCases) {
  std::map<std::string, const json*> byName;
  for (const json& v : reference()["deterministic"]) byName[v["name"].get<std::string>()] = &v;
  std::size_t covered = 0;
  for (const FlameVariation& v : flameVariations()) {
    if (v.random) continue;
    const auto it = byName.find(v.name);
    ASSERT_NE(it, byName.end()) << v.name << " is deterministic but has no reference cases";
    const json& entry = *it->second;
    EXPECT_GE(entry["cases"].size(), 6u) << v.name;
    EXPECT_EQ(entry["writes_z"].get<bool>(), v.writesZ) << v.name << ": the header's 3D forms say otherwise";
    bool onPlane = false, offPlane = false;
    for (const json& c : entry["cases"]) {
      EXPECT_EQ(c["params"].size(), v.params.size()) << v.name;
      EXPECT_EQ(c.contains("coefs"), v.dependent) << v.name;
      (c["p"][2].get<double>() == 0.0 ? onPlane : offPlane) = true;
    }
    EXPECT_TRUE(onPlane && offPlane) << v.name << ": cases on and off the z = 0 plane";
    ++covered;
  }
  for (const auto& [name, entry] : byName) {
    const FlameVariation* v = findFlameVariation(name);
    ASSERT_NE(v, nullptr) << name << " is in the reference but not in the table";
    EXPECT_FALSE(v->random) << name;
  }
  EXPECT_EQ(covered, byName.size());
  EXPECT_GE(covered, 80u);
}

TEST(VariationReference, ApplyMatchesTheReference) {
  for (const auto& [name, v, cases] : deterministicEntries()) {
    ASSERT_NE(v, nullptr) << name;
    for (const json& jc : cases) {
      const Case c = readCase(jc);
      std::uint64_t random = 1;
      const VariationInput in{c.p.x, c.p.y, c.p.z, &c.coefs, c.params.data(), &random};
      const FlamePoint got = v->apply(in, c.weight);
      const double ex = jc["expected"][0], ey = jc["expected"][1], ez = jc["expected"][2];
      const bool ok = near(got.x, ex) && near(got.y, ey) && (!v->writesZ || near(got.z, ez));
      EXPECT_TRUE(ok) << describeCase(name, c) << ": apply gives " << triple(got.x, got.y, got.z) << ", reference "
                      << triple(ex, ey, ez) << (v->writesZ ? "" : " (z not written)");
    }
  }
}

TEST(VariationReference, EvaluateVariationsMatchesForOneTerm) {
  for (const auto& [name, v, cases] : deterministicEntries()) {
    ASSERT_NE(v, nullptr) << name;
    for (const json& jc : cases) {
      const Case c = readCase(jc);
      const FlamePoint got = evaluateOneTerm(v, c);
      const double ex = jc["expected"][0], ey = jc["expected"][1], ez = jc["expected"][2];
      EXPECT_TRUE(near(got.x, ex) && near(got.y, ey) && near(got.z, ez))
          << describeCase(name, c) << ": evaluateVariations gives " << triple(got.x, got.y, got.z) << ", reference "
          << triple(ex, ey, ez);
    }
  }
}

TEST(VariationReference, OnTheZ0PlaneEveryVariationIsFlam3s) {
  std::size_t checked = 0;
  for (const auto& [name, v, cases] : deterministicEntries()) {
    ASSERT_NE(v, nullptr) << name;
    std::size_t onPlane = 0;
    for (const json& jc : cases) {
      if (!jc.contains("flam3_xy")) continue;
      const Case c = readCase(jc);
      ASSERT_EQ(c.p.z, 0.0);
      const FlamePoint got = evaluateOneTerm(v, c);
      const double fx = jc["flam3_xy"][0], fy = jc["flam3_xy"][1];
      EXPECT_TRUE(near(got.x, fx) && near(got.y, fy)) << describeCase(name, c) << ": (" << got.x << ", " << got.y
                                                      << ") but flam3's 2D formula gives (" << fx << ", " << fy << ")";
      ++onPlane;
    }
    EXPECT_GE(onPlane, 3u) << name;
    checked += onPlane;
  }
  EXPECT_GT(checked, 0u);
}

namespace {

struct Moments {
  double n = 0, sum[2] = {0, 0}, sumSq[2] = {0, 0};
  void add(double x, double y) {
    ++n;
    sum[0] += x, sum[1] += y;
    sumSq[0] += x * x, sumSq[1] += y * y;
  }
  double mean(int a) const { return sum[a] / n; }
  double variance(int a) const { return sumSq[a] / n - mean(a) * mean(a); }
};

constexpr int kDraws = 1000000;
constexpr double kSigmas = 5.0;

}  // namespace

TEST(VariationReference, RandomVariationsMatchTheirDistributions) {
  std::set<std::string> seen;
  for (const json& entry : reference()["random"]) {
    const std::string name = entry["name"];
    const FlameVariation* v = findFlameVariation(name);
    ASSERT_NE(v, nullptr) << name;
    EXPECT_TRUE(v->random) << name;
    seen.insert(name);
    const Case c = readCase(entry);
    ASSERT_EQ(c.params.size(), v->params.size()) << name;

    std::vector<std::pair<double, double>> branches;
    std::vector<double> frequency;
    if (entry.contains("branches"))
      for (std::size_t b = 0; b < entry["branches"].size(); ++b) {
        branches.emplace_back(entry["branches"][b][0].get<double>(), entry["branches"][b][1].get<double>());
        frequency.push_back(entry["branch_freq"][b].get<double>());
      }
    std::vector<double> hits(branches.size(), 0.0);
    double offBranch = 0;

    std::uint64_t random = seedFor(name);
    const VariationInput in{c.p.x, c.p.y, c.p.z, &c.coefs, c.params.data(), &random};
    Moments m;
    for (int i = 0; i < kDraws; ++i) {
      const FlamePoint q = v->apply(in, c.weight);
      m.add(q.x, q.y);
      if (branches.empty()) continue;
      bool found = false;
      for (std::size_t b = 0; b < branches.size() && !found; ++b)
        if (std::fabs(q.x - branches[b].first) <= 1e-9 * (1 + std::fabs(branches[b].first)) &&
            std::fabs(q.y - branches[b].second) <= 1e-9 * (1 + std::fabs(branches[b].second))) {
          hits[b] += 1;
          found = true;
        }
      if (!found) ++offBranch;
    }

    const std::string where = describeCase(name, c) + ", " + std::to_string(kDraws) + " draws";
    for (int a = 0; a < 2; ++a) {
      const char* axis = a == 0 ? "x" : "y";
      const double mean = entry["mean"][a], var = entry["var"][a], m4 = entry["m4"][a];
      // Standard errors of the sample mean and variance (the reference is exact up to quadrature).
      const double meanTol = kSigmas * std::sqrt(var / kDraws) + 1e-12;
      // The second term covers the second-order error that dominates where the first-order one
      // vanishes (two equally likely values: julia).
      const double varTol =
          kSigmas * std::sqrt(std::max(m4 - var * var, 0.0) / kDraws) + kSigmas * kSigmas * var / kDraws + 1e-12;
      EXPECT_NEAR(m.mean(a), mean, meanTol) << where << ": mean of " << axis;
      EXPECT_NEAR(m.variance(a), var, varTol) << where << ": variance of " << axis;
    }
    if (!branches.empty()) {
      EXPECT_EQ(offBranch, 0.0) << where << ": " << offBranch << " draws on none of the " << branches.size()
                                << " branches";
      for (std::size_t b = 0; b < branches.size(); ++b) {
        const double p = frequency[b], tol = kSigmas * std::sqrt(p * (1 - p) / kDraws);
        EXPECT_NEAR(hits[b] / kDraws, p, tol)
            << where << ": branch " << b << " (" << branches[b].first << ", " << branches[b].second << ")";
      }
    }
  }
  for (const FlameVariation& v : flameVariations())
    if (v.random) {
      EXPECT_TRUE(seen.count(v.name)) << v.name << " is random but has no reference distribution";
    }
}

TEST(VariationReference, RandomVariationsAreDeterministicInTheirStream) {
  for (const json& entry : reference()["random"]) {
    const std::string name = entry["name"];
    const FlameVariation* v = findFlameVariation(name);
    ASSERT_NE(v, nullptr) << name;
    const Case c = readCase(entry);
    const std::uint64_t seed = 0x243F6A8885A308D3ull;
    std::uint64_t first = seed, second = seed, other = seed + 1;
    const VariationInput a{c.p.x, c.p.y, c.p.z, &c.coefs, c.params.data(), &first};
    const VariationInput b{c.p.x, c.p.y, c.p.z, &c.coefs, c.params.data(), &second};
    const VariationInput d{c.p.x, c.p.y, c.p.z, &c.coefs, c.params.data(), &other};
    bool differs = false;
    for (int i = 0; i < 64; ++i) {
      const FlamePoint p = v->apply(a, c.weight), q = v->apply(b, c.weight), r = v->apply(d, c.weight);
      ASSERT_EQ(p.x, q.x) << name << " draw " << i;
      ASSERT_EQ(p.y, q.y) << name << " draw " << i;
      ASSERT_EQ(p.z, q.z) << name << " draw " << i;
      ASSERT_EQ(first, second) << name << " draw " << i;
      differs |= p.x != r.x || p.y != r.y;
    }
    EXPECT_NE(first, seed) << name << " draws nothing from its stream";
    EXPECT_TRUE(differs) << name << ": another stream state gives the same 64 draws";

    // Through evaluateVariations: the same draws, and a planar one carries w·z.
    std::uint64_t s1 = seed, s2 = seed;
    const VariationInput e{c.p.x, c.p.y, c.p.z, &c.coefs, c.params.data(), &s1};
    const VariationTerm term{v, c.weight, c.params.data()};
    const FlamePoint direct = v->apply(e, c.weight);
    const FlamePoint summed = evaluateVariations(&term, 1, c.p, c.coefs, &s2);
    EXPECT_EQ(s1, s2) << name;
    if (v->pre) continue;  // contributes nothing itself: checked below
    EXPECT_EQ(summed.x, direct.x) << name;
    EXPECT_EQ(summed.y, direct.y) << name;
    if (!v->writesZ) {
      EXPECT_DOUBLE_EQ(summed.z, c.weight * c.p.z) << name;
    }
  }
}

TEST(VariationReference, PreBlurMovesThePointTheOtherVariationsSee) {
  const FlameVariation* pre = findFlameVariation("pre_blur");
  const FlameVariation* linear = findFlameVariation("linear");
  const FlameVariation* spherical = findFlameVariation("spherical");
  ASSERT_TRUE(pre && linear && spherical);
  const FlamePoint p{0.43, -0.61, 0.25};
  const FlameAffine identity;
  for (std::uint64_t seed = 1; seed < 200; ++seed) {
    std::uint64_t s1 = seed, s2 = seed;
    const VariationInput in{p.x, p.y, p.z, &identity, nullptr, &s1};
    const FlamePoint d = pre->apply(in, 0.5);
    // pre_blur first in flam3 whatever its place in the list; z is not blurred (flam3 is 2D).
    const VariationTerm terms[] = {{spherical, 0.3, nullptr}, {pre, 0.5, nullptr}, {linear, 1.0, nullptr}};
    const FlamePoint got = evaluateVariations(terms, 3, p, identity, &s2);
    const double x = p.x + d.x, y = p.y + d.y, z = p.z;
    const double k = 0.3 / (x * x + y * y + z * z + 1e-10);
    EXPECT_NEAR(got.x, x + k * x, 1e-12) << seed;
    EXPECT_NEAR(got.y, y + k * y, 1e-12) << seed;
    EXPECT_NEAR(got.z, z + k * z, 1e-12) << seed;
  }
}

TEST(VariationReference, FlattenClearsTheSumsZ) {
  const FlameVariation* flatten = findFlameVariation("flatten");
  const FlameVariation* linear = findFlameVariation("linear");
  const FlameVariation* swirl = findFlameVariation("swirl");
  ASSERT_TRUE(flatten && linear && swirl);
  const FlamePoint p{0.43, -0.61, 0.25};
  const FlameAffine identity;
  std::uint64_t random = 1;
  const VariationTerm terms[] = {{linear, 0.6, nullptr}, {swirl, 0.4, nullptr}, {flatten, 1.0, nullptr}};
  const FlamePoint got = evaluateVariations(terms, 3, p, identity, &random);
  const double r2 = p.x * p.x + p.y * p.y;
  // Apophysis 7X's flatten: the other variations' x and y untouched, z set to 0.
  EXPECT_NEAR(got.x, 0.6 * p.x + 0.4 * (std::sin(r2) * p.x - std::cos(r2) * p.y), 1e-12);
  EXPECT_NEAR(got.y, 0.6 * p.y + 0.4 * (std::cos(r2) * p.x + std::sin(r2) * p.y), 1e-12);
  EXPECT_EQ(got.z, 0.0);
  const FlamePoint without = evaluateVariations(terms, 2, p, identity, &random);
  EXPECT_NEAR(without.z, 0.6 * p.z + 0.4 * p.z, 1e-12);  // linear's w·z plus swirl's carried w·z
}
