// Exploring: random worlds by style, mutations and breeding (core/explore/explore.h), and the
// "worth looking at" test they all pass (core/explore/attractor_verdict.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "anim/track_path.h"
#include "explore/explore.h"
#include "io/parameter_paths.h"
#include "io/project_io.h"
#include "schema/project_parameter.h"

namespace gridifs {
namespace {

using json = nlohmann::json;

constexpr ExploreStyle kStyles[] = {ExploreStyle::Grid, ExploreStyle::Flame, ExploreStyle::FreeForm,
                                    ExploreStyle::Volume};

std::string describe(const AttractorVerdict& v) {
  char text[160];
  std::snprintf(text, sizeof text, "%s (covered %.3f spread %.4f thickness %.3f contraction %.3f escaped %.3f)",
                v.why.c_str(), v.covered, v.spread, v.thickness, v.contraction, v.escaped);
  return text;
}

Project asset(const std::string& name) { return loadProject(std::string(GRIDIFS_ASSETS) + "/" + name); }

TEST(Explore, TheSameSeedGivesTheSameBytes) {
  for (ExploreStyle style : kStyles) {
    const RandomWorldOptions options{style, 0, 42};
    const std::string a = serializeProject(randomWorld(options).project);
    const std::string b = serializeProject(randomWorld(options).project);
    EXPECT_EQ(a, b) << exploreStyleName(style);
    const std::string other = serializeProject(randomWorld({style, 0, 43}).project);
    EXPECT_NE(a, other) << exploreStyleName(style) << ": another seed should draw another world";
  }
  const Project parent = asset("twisted_functions.gridifs");
  MutationOptions m;
  m.seed = 7;
  EXPECT_EQ(serializeProject(mutateProject(parent, m, {"p.gridifs"}).project),
            serializeProject(mutateProject(parent, m, {"p.gridifs"}).project));
}

TEST(Explore, EveryResultLoadsAndSavesLikeAHandMadeProjectWithItsLineage) {
  for (ExploreStyle style : kStyles) {
    const ExploreResult r = randomWorld({style, 0, 5});
    const std::string text = serializeProject(r.project);
    // The file is the project: read back, it writes the same bytes.
    const Project again = parseProject(text);
    EXPECT_EQ(serializeProject(again), text) << exploreStyleName(style);
    ASSERT_TRUE(again.lineage);
    EXPECT_TRUE(again.lineage->parents.empty());
    EXPECT_EQ(again.lineage->seed, 5u);
    EXPECT_FALSE(again.lineage->strength);
  }
  MutationOptions m;
  m.seed = 9;
  m.strength = 0.3;
  const Project child = mutateProject(asset("tapered_functions.gridifs"), m, {"tapered_functions.gridifs"}).project;
  const Project again = parseProject(serializeProject(child));
  ASSERT_TRUE(again.lineage);
  EXPECT_EQ(again.lineage->parents, std::vector<std::string>{"tapered_functions.gridifs"});
  EXPECT_EQ(again.lineage->seed, 9u);
  EXPECT_EQ(again.lineage->strength, 0.3);
}

TEST(Explore, TheFunctionCountIsHonoured) {
  for (int n : {2, 3, 6}) EXPECT_EQ(randomWorld({ExploreStyle::Grid, n, 3}).project.functions.size(), std::size_t(n));
}

// Over 100 seeds per style, at least 95 worlds pass the test at their first draw.
TEST(Explore, NinetyFivePercentOfFirstDrawsAreWorthLookingAt) {
  for (ExploreStyle style : kStyles) {
    int worth = 0;
    std::string failures;
    for (std::uint64_t seed = 1; seed <= 100; ++seed) {
      // The first draw, judged as randomWorld judges it (framed).
      Project p = drawRandomWorld({style, 0, seed}, 0);
      const AttractorVerdict v = judgeDraw(p, {}, true);
      if (v.worth)
        ++worth;
      else
        failures += "\n  " + std::to_string(seed) + ": " + describe(v);
    }
    EXPECT_GE(worth, 95) << exploreStyleName(style) << " failed:" << failures;
  }
}

json functionsField(const Project& p, const char* key) {
  json out = json::array();
  for (const json& f : json::parse(serializeProject(p))["functions"]) out.push_back(f.value(key, json()));
  return out;
}

TEST(Explore, KeepHoldsItsFieldsByteEqual) {
  const Project parent = asset("flames/swirl_spherical.gridifs");
  const json before = json::parse(serializeProject(parent));
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    MutationOptions m;
    m.seed = seed;
    m.strength = 1.0;
    std::string unknown;
    ASSERT_TRUE(parseExploreKeep("ops,placement,colors,variations,palette,camera", m.keep, unknown));
    const Project child = mutateProject(parent, m, {"swirl_spherical.gridifs"}).project;
    const json after = json::parse(serializeProject(child));
    EXPECT_EQ(after["camera"], before["camera"]);
    EXPECT_EQ(after["render"]["flame"]["palette"], before["render"]["flame"]["palette"]);
    ASSERT_EQ(after["functions"].size(), before["functions"].size());
    for (const char* key : {"ops", "placement", "color", "palette_index", "color_speed", "variations"})
      EXPECT_EQ(functionsField(child, key), functionsField(parent, key)) << key << ", seed " << seed;
    EXPECT_NE(after, before) << "something must still change (weights, variation parameters)";
  }
}

TEST(Explore, KeepListsAreParsedAndUnknownNamesNamed) {
  ExploreKeep keep;
  std::string unknown;
  EXPECT_TRUE(parseExploreKeep("camera,tracks", keep, unknown));
  EXPECT_TRUE(keep.camera && keep.tracks && !keep.ops);
  EXPECT_FALSE(parseExploreKeep("ops,colours", keep, unknown));
  EXPECT_EQ(unknown, "colours");
}

/// How far `child` is from `parent`: the parameters both have, each moved by its span's share
/// (or relative to its size), plus one for every number only one of them has.
double distance(const Project& parent, const Project& child) {
  double d = 0.0;
  const std::vector<std::string> a = parameterPaths(parent), b = parameterPaths(child);
  for (const std::string& path : a) {
    const auto parsed = TrackPath::parse(path);
    const FoundParameter inChild = findParameter(child, *parsed);
    if (inChild.lookup != ParameterLookup::Number) {
      d += 1.0;
      continue;
    }
    const FoundParameter inParent = findParameter(parent, *parsed);
    const double x = inParent.parameter.get(parent), y = inChild.parameter.get(child);
    const ParameterSpan span = inParent.parameter.span();
    d += span.lo < span.hi ? std::fabs(y - x) / (span.hi - span.lo) : std::fabs(y - x) / (1.0 + std::fabs(x));
  }
  if (b.size() > a.size()) d += double(b.size() - a.size());
  return d;
}

TEST(Explore, AWeakerStrengthStaysCloserToTheParent) {
  const Project parent = asset("twisted_functions.gridifs");
  double weak = 0.0, strong = 0.0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    MutationOptions m;
    m.seed = seed;
    m.strength = 0.1;
    weak += distance(parent, drawMutation(parent, m, 0));
    m.strength = 0.9;
    strong += distance(parent, drawMutation(parent, m, 0));
  }
  EXPECT_LT(weak * 3.0, strong) << "weak " << weak << ", strong " << strong;
}

TEST(Explore, BreedingDrawsFunctionsFromBothParents) {
  const Project a = asset("twisted_functions.gridifs"), b = asset("tapered_functions.gridifs");
  bool fromA = false, fromB = false;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    MutationOptions m;
    m.seed = seed;
    m.strength = 0.05;
    m.mate = &b;
    const ExploreResult child = mutateProject(a, m, {"a.gridifs", "b.gridifs"});
    EXPECT_EQ(child.project.lineage->parents.size(), 2u);
    for (const Function& f : child.project.functions) {
      // The stack's operation types say where a function came from (twists in one, tapers in the other).
      for (const Operation& op : f.ops) {
        fromA = fromA || std::string(opTypeName(op.params)) == "twist";
        fromB = fromB || std::string(opTypeName(op.params)) == "taper";
      }
    }
  }
  EXPECT_TRUE(fromA && fromB);
  // Two kinds of IFS cannot breed.
  const Project freeForm = randomWorld({ExploreStyle::FreeForm, 0, 1}).project;
  MutationOptions m;
  m.mate = &freeForm;
  try {
    mutateProject(a, m, {});
    FAIL() << "a grid IFS bred with a free-form one";
  } catch (const ModelError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot breed a free-form IFS with a grid IFS; breed two of one kind");
  }
}

TEST(AttractorVerdict, NamesASpeckALineAFloodAndARunaway) {
  Project p = asset("sierpinski_tetrahedron.gridifs");
  EXPECT_TRUE(judgeAttractor(p).worth) << describe(judgeAttractor(p));

  Project speck = p;
  for (Function& f : speck.functions) f.placement.scale = Vec3{0.01, 0.01, 0.01};
  EXPECT_EQ(judgeAttractor(speck).why, "a speck") << describe(judgeAttractor(speck));

  // Every map onto the x axis: the attractor is a segment of it.
  Project line = p;
  for (Function& f : line.functions) {
    f.placement.scale[1] = f.placement.scale[2] = 0.0;
    f.placement.translate[1] = f.placement.translate[2] = 0.0;
    f.placement.rotate = Vec3{0.0};
  }
  EXPECT_EQ(judgeAttractor(line).why, "a line") << describe(judgeAttractor(line));

  // Eight maps onto the octants of X: the attractor is the solid cube, and a narrow view fills with it.
  Project flood = p;
  flood.functions.resize(1);
  flood.functions[0].placement = Placement{};
  flood.functions[0].placement.scale = Vec3{0.5};
  for (int octant = 0; octant < 8; ++octant) {
    Function f = flood.functions[0];
    f.name = "o" + std::to_string(octant);
    f.placement.translate = Vec3{octant & 1 ? 0.5 : -0.5, octant & 2 ? 0.5 : -0.5, octant & 4 ? 0.5 : -0.5};
    flood.functions.push_back(f);
  }
  flood.functions.erase(flood.functions.begin());
  flood.camera.fov = 20.0;
  EXPECT_EQ(judgeAttractor(flood).why, "a flood") << describe(judgeAttractor(flood));

  // Maps that stretch everything beyond X (a variation stage extrapolates the grid map, so
  // nothing clamps it): the chaos game never settles.
  Project runaway = p;
  for (Function& f : runaway.functions) {
    f.placement.scale = Vec3{1.6};
    f.variations = {{"linear", 1.0}};
  }
  EXPECT_EQ(judgeAttractor(runaway).why, "runs off") << describe(judgeAttractor(runaway));
}

TEST(AttractorVerdict, IsTheSameEveryTime) {
  const Project p = asset("twisted_functions.gridifs");
  const AttractorVerdict a = judgeAttractor(p), b = judgeAttractor(p);
  EXPECT_EQ(a.covered, b.covered);
  EXPECT_EQ(a.spread, b.spread);
  EXPECT_EQ(a.contraction, b.contraction);
}

}  // namespace
}  // namespace gridifs
