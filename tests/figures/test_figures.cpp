// The figures tier: every figure of the five papers that docs/figures/figures.json says GridIFS
// makes is made here at a small size, twice, by the real executable. Each must exit 0, cover
// its output where the paper's figure does (pixels off the background, voxels with density,
// grid nodes) and come out the same both times. The manifest itself is checked for complete
// entries, existing projects and the thumbnails docs/FIGURES.md shows.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "cli/run_command.h"
#include "figures/figure_checks.h"

namespace fs = std::filesystem;
using gridifs::figures::Figure;
using gridifs::test_support::quote;

namespace {

const fs::path kRoot = GRIDIFS_SOURCE_DIR;
const fs::path kManifest = kRoot / "docs/figures/figures.json";

std::vector<Figure> madeFigures() {
  std::vector<Figure> made;
  try {
    for (const auto& f : gridifs::figures::loadManifest(kManifest))
      if (f.makeable()) made.push_back(f);
  } catch (const std::exception&) {
    // FiguresManifest.EveryEntryIsComplete reports the broken manifest.
  }
  return made;
}

std::string substitute(std::string arg, const fs::path& project, const fs::path& out) {
  for (const auto& [key, value] :
       {std::pair{std::string("{project}"), project.string()}, std::pair{std::string("{out}"), out.string()},
        std::pair{std::string("{root}"), kRoot.string()}}) {
    for (size_t at; (at = arg.find(key)) != std::string::npos;) arg.replace(at, key.size(), value);
  }
  return arg;
}

/// Runs every step of `f` at its small size into `dir`; returns each step's output files.
std::vector<std::vector<fs::path>> makeSmall(const Figure& f, const fs::path& dir) {
  std::vector<std::vector<fs::path>> outputs;
  for (const auto& step : f.steps) {
    std::string args;
    for (const auto& a : step.args) args += quote(substitute(a, kRoot / step.project, dir / step.out)) + " ";
    for (const auto& a : step.small) args += quote(a) + " ";
    // Progress bars off where the verb has them; verbs that print their result write stdout.
    const auto r = gridifs::test_support::runGridifs(step.quiet ? args + "--quiet" : args);
    EXPECT_EQ(r.exitCode, 0) << "gridifs " << args << "\n" << r.err;
    if (step.stdoutOut) std::ofstream(dir / step.out, std::ios::binary) << r.out;
    outputs.push_back(gridifs::figures::stepOutputs(dir, step.out));
    EXPECT_FALSE(outputs.back().empty()) << "gridifs " << args << " wrote no " << step.out;
  }
  return outputs;
}

void expectCovered(const Figure& f, const fs::path& file) {
  if (f.checkKind == "coverage") {
    const auto coverage = gridifs::figures::imageCoverage(file);
    ASSERT_TRUE(coverage) << file << " is not a readable image";
    EXPECT_GE(*coverage, f.checkMin) << file << ": pixels off the background";
  } else if (f.checkKind == "density") {
    const auto grid = gridifs::figures::readDensity(file);
    ASSERT_TRUE(grid) << file << " has no density grid";
    EXPECT_GE(gridifs::figures::densityCoverage(*grid), f.checkMin) << file << ": voxels with density";
  } else if (f.checkKind == "nodes") {
    const auto nodes = gridifs::figures::readNodes(file);
    std::set<std::array<double, 3>> distinct;
    for (const auto& n : nodes) distinct.insert({n[3], n[4], n[5]});
    EXPECT_GE(double(distinct.size()), f.checkMin) << file << ": distinct node positions";
  } else if (f.checkKind == "mesh") {
    EXPECT_GE(double(gridifs::figures::objFaces(file)), f.checkMin) << file << ": faces";
  } else {
    FAIL() << f.id << ": unknown check kind " << f.checkKind;
  }
}

void expectSame(const Figure& f, const fs::path& a, const fs::path& b) {
  if (gridifs::test_support::slurp(a) == gridifs::test_support::slurp(b)) return;
  if (f.checkKind == "coverage") {
    EXPECT_TRUE(gridifs::figures::samePixels(a, b)) << a << " and " << b << " differ";
  } else if (f.checkKind == "density") {
    EXPECT_TRUE(gridifs::figures::sameDensity(*gridifs::figures::readDensity(a), *gridifs::figures::readDensity(b)))
        << a << " and " << b << " differ";
  } else {
    ADD_FAILURE() << a << " and " << b << " differ";
  }
}

class PaperFigure : public ::testing::TestWithParam<Figure> {};

TEST_P(PaperFigure, MadeSmallCoveredAndDeterministic) {
  const Figure& f = GetParam();
  gridifs::test_support::ScratchDir first("figure-" + f.id + "-1"), second("figure-" + f.id + "-2");
  const auto a = makeSmall(f, first.path);
  const auto b = makeSmall(f, second.path);
  ASSERT_FALSE(HasFailure());
  for (size_t s = 0; s < a.size(); ++s) {
    ASSERT_EQ(a[s].size(), b[s].size()) << f.steps[s].out;
    for (size_t i = 0; i < a[s].size(); ++i) {
      expectCovered(f, a[s][i]);
      expectSame(f, a[s][i], b[s][i]);
    }
  }
}

std::string testName(const ::testing::TestParamInfo<Figure>& info) {
  std::string name = info.param.id;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Papers, PaperFigure, ::testing::ValuesIn(madeFigures()), testName);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(PaperFigure);  // a broken manifest: reported below

// Every entry names its paper, figure and what it shows; a made figure has a project, steps, a
// check and a small committed thumbnail that docs/FIGURES.md shows; any other says why not.
TEST(FiguresManifest, EveryEntryIsComplete) {
  const auto figures = gridifs::figures::loadManifest(kManifest);
  const std::string doc = gridifs::test_support::slurp(kRoot / "docs/FIGURES.md");
  std::set<std::string> ids;
  for (const auto& f : figures) {
    SCOPED_TRACE(f.id);
    EXPECT_TRUE(ids.insert(f.id).second) << "duplicate id";
    EXPECT_FALSE(f.paper.empty() || f.figure.empty() || f.shows.empty());
    EXPECT_NE(doc.find(f.shows), std::string::npos)
        << "docs/FIGURES.md is older than the manifest (run scripts/figures)";
    if (!f.makeable()) {
      EXPECT_TRUE(f.status == "pending" || f.status == "missing") << f.status;
      EXPECT_FALSE(f.reason.empty());
      EXPECT_TRUE(f.steps.empty());
      continue;
    }
    EXPECT_FALSE(f.steps.empty());
    for (const auto& s : f.steps) EXPECT_TRUE(fs::exists(kRoot / s.project)) << s.project;
    EXPECT_FALSE(f.checkKind.empty());
    ASSERT_FALSE(f.thumbnail.empty());
    ASSERT_TRUE(fs::exists(kRoot / f.thumbnail)) << f.thumbnail;
    EXPECT_LT(fs::file_size(kRoot / f.thumbnail), 30u * 1024u) << f.thumbnail;
    EXPECT_NE(doc.find(f.thumbnail.substr(5)), std::string::npos) << f.thumbnail << " not in docs/FIGURES.md";
  }
}

}  // namespace
