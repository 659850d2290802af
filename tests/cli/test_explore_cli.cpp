// gridifs random and gridifs mutate, run as a user runs them: the files they write load, render
// and save like hand-made projects; the same seed writes the same bytes; --keep holds its fields;
// bad options are refused with one sentence and nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/project_io.h"
#include "tests/cli/example_projects.h"
#include "tests/cli/run_command.h"

namespace gridifs {
namespace {

using test_support::asset;
using test_support::quote;
using test_support::runGridifs;
using test_support::slurp;
namespace fs = std::filesystem;
using json = nlohmann::json;

struct ExploreFolder {
  fs::path dir;
  ExploreFolder() : dir(fs::temp_directory_path() / ("gridifs-explore-cli-" + std::to_string(::getpid()))) {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~ExploreFolder() { fs::remove_all(dir); }
  std::string operator/(const std::string& name) const { return (dir / name).string(); }
};

TEST(ExploreCli, RandomWritesWorldsThatLoadRenderAndSave) {
  ExploreFolder tmp;
  for (const char* style : {"grid", "flame", "free-form", "volume"}) {
    const std::string out = tmp / (std::string(style) + ".gridifs");
    const auto r = runGridifs("random -o " + quote(out) + " --seed 11 --style " + style);
    ASSERT_EQ(r.exitCode, 0) << style << ": " << r.err;
    EXPECT_NE(r.out.find(out + ": " + style + " world, seed 11"), std::string::npos) << r.out;
    const json project = json::parse(slurp(out));
    EXPECT_EQ(project["lineage"]["seed"], 11);
    EXPECT_TRUE(project["lineage"]["parents"].empty());
    EXPECT_EQ(runGridifs("info " + quote(out)).exitCode, 0) << style;
    const auto render = runGridifs("render " + quote(out) + " -o " + quote(tmp / "r.png") +
                                   " --width 64 --height 48 --samples 20000 --quiet");
    EXPECT_EQ(render.exitCode, 0) << style << ": " << render.err;
  }
}

TEST(ExploreCli, TheSameSeedWritesTheSameBytesAndCountNumbersTheFiles) {
  ExploreFolder tmp;
  ASSERT_EQ(runGridifs("random -o " + quote(tmp / "a_%02d.gridifs") + " --seed 5 --count 3").exitCode, 0);
  ASSERT_EQ(runGridifs("random -o " + quote(tmp / "b_%02d.gridifs") + " --seed 5 --count 3").exitCode, 0);
  for (const char* i : {"00", "01", "02"})
    EXPECT_EQ(slurp(tmp / ("a_" + std::string(i) + ".gridifs")), slurp(tmp / ("b_" + std::string(i) + ".gridifs")));
  // File i of --count has seed S+i, so it can be drawn again alone.
  ASSERT_EQ(runGridifs("random -o " + quote(tmp / "c.gridifs") + " --seed 6").exitCode, 0);
  EXPECT_EQ(slurp(tmp / "c.gridifs"), slurp(tmp / "a_01.gridifs"));
  EXPECT_NE(slurp(tmp / "a_00.gridifs"), slurp(tmp / "a_01.gridifs"));
}

TEST(ExploreCli, MutateKeepsWhatKeepNamesByteEqual) {
  ExploreFolder tmp;
  const std::string parent = asset("twisted_functions.gridifs");
  const auto r = runGridifs("mutate " + quote(parent) + " -o " + quote(tmp / "m_%02d.gridifs") +
                            " --count 4 --seed 3 --strength 1 --keep ops,colors,camera");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // The parent as GridIFS writes it (the example is hand-written: 1 where GridIFS writes 1.0).
  const json before = json::parse(serializeProject(loadProject(parent)));
  for (const char* i : {"00", "01", "02", "03"}) {
    const json child = json::parse(slurp(tmp / ("m_" + std::string(i) + ".gridifs")));
    EXPECT_EQ(child["camera"], before["camera"]);
    ASSERT_EQ(child["functions"].size(), before["functions"].size());
    for (std::size_t f = 0; f < before["functions"].size(); ++f) {
      EXPECT_EQ(child["functions"][f]["ops"].dump(), before["functions"][f]["ops"].dump());
      EXPECT_EQ(child["functions"][f]["color"].dump(), before["functions"][f]["color"].dump());
    }
    EXPECT_NE(child, before);
    EXPECT_EQ(child["lineage"]["parents"][0], parent);
    EXPECT_EQ(child["lineage"]["strength"], 1.0);
  }
}

TEST(ExploreCli, MateBreedsTwoProjects) {
  ExploreFolder tmp;
  const auto r = runGridifs("mutate " + quote(asset("twisted_functions.gridifs")) + " --mate " +
                            quote(asset("tapered_functions.gridifs")) + " -o " + quote(tmp / "child.gridifs") +
                            " --seed 2 --strength 0.2");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const json child = json::parse(slurp(tmp / "child.gridifs"));
  EXPECT_EQ(child["lineage"]["parents"].size(), 2u);
  EXPECT_EQ(runGridifs("info " + quote(tmp / "child.gridifs")).exitCode, 0);
}

TEST(ExploreCli, BadOptionsAreRefusedWithOneSentenceAndNothingWritten) {
  ExploreFolder tmp;
  const std::string out = quote(tmp / "x.gridifs");
  const std::string parent = quote(asset("twisted_functions.gridifs"));
  const struct {
    std::string args, sentence;
  } cases[] = {
      {"random -o " + out + " --style fuzzy",
       "gridifs: --style must be grid, flame, free-form or volume, not \"fuzzy\".\n"},
      {"random -o " + out + " --functions 40", "gridifs: --functions must be between 2 and 12, not 40.\n"},
      {"random -o " + out + " --count 0", "gridifs: --count must be between 1 and 1000, not 0.\n"},
      {"random -o " + quote(tmp / "x.png"), ""},
      {"random -o " + quote(tmp / "x.gridifs") + " --count 3", ""},
      {"mutate " + parent + " -o " + out + " --strength 0",
       "gridifs: --strength must be above 0 and at most 1, not 0.\n"},
      {"mutate " + parent + " -o " + out + " --keep ops,colours",
       "gridifs: --keep takes ops, placement, colors, variations, palette, camera or tracks, not \"colours\".\n"},
      {"mutate " + quote(tmp / "missing.gridifs") + " -o " + out, ""},
      {"mutate " + parent + " --mate " + quote(asset("freeform/fig5_1_bezier_curve.gridifs")) + " -o " + out, ""},
  };
  for (const auto& c : cases) {
    const auto r = runGridifs(c.args);
    EXPECT_EQ(r.exitCode, 2) << c.args << ": " << r.err;
    if (!c.sentence.empty()) {
      EXPECT_EQ(r.err, c.sentence) << c.args;
    }
    EXPECT_FALSE(r.err.empty());
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(fs::is_empty(tmp.dir)) << c.args << " wrote something";
  }
}

}  // namespace
}  // namespace gridifs
