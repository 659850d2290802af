// Native flame variations against the reference renderer: for each group of flam3's variations
// (the paper's appendix, the dependent ones, the parametric ones, the random ones, the plugin
// pack's and the complex functions), a genome that uses every variation of the group
// (tests/data/flame/variations/make_genomes.py) is imported with `gridifs import-flame` and
// rendered by `gridifs render --mode flame` and by `flam3-render`. The judge is flam3's own
// seed-to-seed agreement: the correlation of the alpha channels of two flam3 renders from
// different random streams. GridIFS's render, from its own stream, must agree with flam3 as well
// as flam3 agrees with itself, up to 0.01 (at these sample counts the estimate of a correlation
// itself varies by a few thousandths from stream to stream).
#include <gtest/gtest.h>

#include <cstdio>

#include "flam3_compare.h"
#include "run_command.h"

using namespace gridifs::test_support;

namespace {

void crossCheckGroup(const std::string& group) {
  if (!haveFlam3()) GTEST_SKIP() << "flam3-render (flam3-utils) is not installed";
  const ScratchDir dir("flam3-variations-" + group);
  const auto genome = std::filesystem::path(GRIDIFS_TEST_DATA) / "flame" / "variations" / (group + ".flame");
  const auto project = dir.path / (group + ".gridifs");
  const CommandResult imported =
      runGridifs("import-flame " + quote(genome.string()) + " -o " + quote(project.string()));
  ASSERT_EQ(imported.exitCode, 0) << imported.err;
  // Every variation is known: the import warns about nothing.
  EXPECT_EQ(imported.err.find("warning"), std::string::npos) << imported.err;
  const Flam3Agreement agreement = agreementWithFlam3(genome, project, dir.path);
  ASSERT_TRUE(agreement.error.empty()) << agreement.error;
  const AlphaComparison &self = agreement.self, &cross = agreement.cross;
  ASSERT_GT(self.coveredF, 500) << "the genome should cover the view";
  std::printf("[variations %s] flam3 vs flam3: %s\n[variations %s] flam3 vs gridifs: %s\n", group.c_str(),
              self.summary().c_str(), group.c_str(), cross.summary().c_str());
  EXPECT_GE(cross.corrAlpha, self.corrAlpha - 0.01);
  EXPECT_GE(cross.corrLuma, self.corrLuma - 0.01);
}

}  // namespace

TEST(Flam3Variations, TheAppendixVariations) { crossCheckGroup("appendix"); }
TEST(Flam3Variations, TheDependentVariations) { crossCheckGroup("dependent"); }
TEST(Flam3Variations, TheParametricVariations) { crossCheckGroup("parametric"); }
TEST(Flam3Variations, TheRandomVariations) { crossCheckGroup("random"); }
TEST(Flam3Variations, ThePluginAndComplexVariations) { crossCheckGroup("plugin"); }
