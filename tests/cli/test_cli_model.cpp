// The model verbs through the real executable: info, nodes, eval, and the
// bad-input corpus: every hostile file → exit 2, one sentence, nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "run_command.h"

using namespace gridifs::test_support;
namespace fs = std::filesystem;

namespace {

std::string asset(const std::string& name) { return std::string(GRIDIFS_ASSETS) + "/" + name; }

void writeText(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

std::vector<std::vector<double>> parseRows(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream l(line);
    std::vector<double> row;
    double v;
    while (l >> v) row.push_back(v);
    rows.push_back(row);
  }
  return rows;
}

// Hostile files too big to commit, generated into `dir`.
void writeGeneratedCorpus(const fs::path& dir) {
  writeText(dir / "deep_nesting.gridifs", R"({"format":"gridifs","version":1,"functions":[{"name":)" +
                                              std::string(200000, '[') + std::string(200000, ']') + "}]}");
  writeText(dir / "megabyte_string.gridifs",
            R"({"format":"gridifs","version":1,"functions":[{"name":")" + std::string(3 << 20, 'x') + "\"}]}");
  writeText(dir / "megabyte_expression.gridifs",
            R"({"format":"gridifs","version":1,"functions":[{"ops":[{"type":"calculator","x":")" +
                std::string(2 << 20, 'x') + "\"}]}]}");
  std::string many = R"({"format":"gridifs","version":1,"functions":[)";
  for (int i = 0; i < 100000; ++i) many += std::string(i ? "," : "") + R"({"name":"f","resolution":[128,128,128]})";
  writeText(dir / "hundred_thousand_functions.gridifs", many + "]}");
  writeText(dir / "binary_garbage.gridifs", std::string("\x00\xff\xfe{\x01", 5));
}

}  // namespace

TEST(CliModel, InfoListsFunctionsAndContractivity) {
  const auto j = runGridifs("info " + quote(asset("sierpinski_tetrahedron.gridifs")) + " --json");
  ASSERT_EQ(j.exitCode, 0) << j.err;
  const auto doc = nlohmann::json::parse(j.out);
  ASSERT_EQ(doc["functions"].size(), 4u);
  for (const auto& f : doc["functions"]) {
    EXPECT_NEAR(f["contractivity"].get<double>(), 0.5, 1e-9);
    EXPECT_NEAR(f["probability"].get<double>(), 0.25, 1e-12);
    EXPECT_TRUE(f["contractive"].get<bool>());
  }
  const auto text = runGridifs("info " + quote(asset("sierpinski_tetrahedron.gridifs")));
  EXPECT_EQ(text.exitCode, 0);
  EXPECT_NE(text.out.find("4 functions"), std::string::npos);
  EXPECT_TRUE(text.err.empty()) << text.err;
}

TEST(CliModel, InfoWarnsWhenAFunctionIsNotContractive) {
  ScratchDir dir("info-warn");
  writeText(
      dir.path / "expanding.gridifs",
      R"({"format":"gridifs","version":1,"functions":[{"name":"grow","placement":{"scale":[1.2,1,1]}},{"name":"ok","placement":{"scale":[0.5,0.5,0.5]}}]})");
  const auto r = runGridifs("info " + quote((dir.path / "expanding.gridifs").string()));
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.err.find("warning: function 0 \"grow\" may not be contractive"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("\"ok\""), std::string::npos);
}

TEST(CliModel, EveryExampleIsContractive) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(GRIDIFS_ASSETS)) {
    if (entry.path().extension() != ".gridifs") continue;
    ++count;
    const auto r = runGridifs("info " + quote(entry.path().string()) + " --json");
    ASSERT_EQ(r.exitCode, 0) << entry.path() << r.err;
    EXPECT_TRUE(nlohmann::json::parse(r.out)["contractive"].get<bool>()) << entry.path() << r.out;
    EXPECT_TRUE(r.err.empty()) << entry.path() << r.err;
  }
  EXPECT_GE(count, 9);
}

TEST(CliModel, NodesAgreeWithTheTwistFormula) {
  // Gröller & Wegenkittl 1994, §2.3 twist about the grid center, then placement scale 0.5: node = 0.5·twist(u).
  ScratchDir dir("nodes");
  const double k = 1.3;
  writeText(
      dir.path / "t.gridifs",
      R"({"format":"gridifs","version":1,"functions":[{"name":"t","resolution":[4,5,6],"placement":{"scale":[0.5,0.5,0.5]},
                "ops":[{"type":"twist","axis":"z","profile":"linear","k":1.3}]}]})");
  const auto r = runGridifs("nodes " + quote((dir.path / "t.gridifs").string()) + " --function 0");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto rows = parseRows(r.out);
  ASSERT_EQ(rows.size(), 120u);
  for (const auto& row : rows) {
    ASSERT_EQ(row.size(), 6u);
    const double x = -1 + 2 * row[0] / 3, y = -1 + 2 * row[1] / 4, z = -1 + 2 * row[2] / 5;
    const double phi = k * z;
    EXPECT_NEAR(row[3], 0.5 * (x * std::cos(phi) - y * std::sin(phi)), 1e-6);
    EXPECT_NEAR(row[4], 0.5 * (x * std::sin(phi) + y * std::cos(phi)), 1e-6);
    EXPECT_NEAR(row[5], 0.5 * z, 1e-6);
  }
}

TEST(CliModel, EvalAgreesWithTheMagnetFormulaOnNodesAndIsTrilinearBetween) {
  ScratchDir dir("eval");
  writeText(dir.path / "m.gridifs",
            R"({"format":"gridifs","version":1,"functions":[{"name":"a"},{"name":"m","resolution":[3,3,3],
                "ops":[{"type":"magnet","point":[0.5,0.5,0.5],"dmax":1.5,"strength":0.6,"falloff":2}]}]})");
  // Node (2,2,1) sits at (1,1,0): d = sqrt(0.75), f = 0.6·((1.5 − d)/1.5)².
  const double d = std::sqrt(0.75), f = 0.6 * std::pow((1.5 - d) / 1.5, 2);
  const auto r = runGridifs("eval " + quote((dir.path / "m.gridifs").string()) + " --function m", "1 1 0\n\n5 5 0\n");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto rows = parseRows(r.out);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_NEAR(rows[0][0], 1 + f * (0.5 - 1), 1e-6);
  EXPECT_NEAR(rows[0][1], 1 + f * (0.5 - 1), 1e-6);
  EXPECT_NEAR(rows[0][2], 0 + f * 0.5, 1e-6);
  EXPECT_EQ(rows[1], rows[0]);  // (5,5,0) is clamped to (1,1,0)
}

TEST(CliModel, EvalRejectsMalformedInputLines) {
  const auto r = runGridifs("eval " + quote(asset("default.gridifs")) + " --function 0", "0 0 0\n1 2\n");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("line 2"), std::string::npos) << r.err;
  const auto nan = runGridifs("eval " + quote(asset("default.gridifs")) + " --function 0", "nan 0 0\n");
  EXPECT_EQ(nan.exitCode, 2);
}

TEST(CliModel, BadUsageExitsTwoWithOneSentence) {
  for (const std::string& args : std::vector<std::string>{
           "nodes", "nodes " + quote(asset("default.gridifs")),
           "nodes " + quote(asset("default.gridifs")) + " --function 9",
           "nodes " + quote(asset("default.gridifs")) + " --function nope", "info /definitely/not/here.gridifs",
           "info " + quote(asset("default.gridifs")) + " --bogus", "--bogus-option"}) {
    const auto r = runGridifs(args);
    EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << args;
  }
}

TEST(CliModel, BadInputCorpusFailsCleanlyFromEveryVerb) {
  ScratchDir dir("corpus");
  for (const auto& entry : fs::directory_iterator(std::string(GRIDIFS_TEST_DATA) + "/bad"))
    fs::copy_file(entry.path(), dir.path / entry.path().filename());
  writeGeneratedCorpus(dir.path);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir.path)) {
    ++files;
    const std::string file = entry.path().string();
    const std::string before = slurp(entry.path());
    const auto stamp = fs::last_write_time(entry.path());
    for (const std::string verb : {"info", "info --json", "nodes --function 0", "eval --function 0"}) {
      const auto r = runGridifs(verb.substr(0, verb.find(' ')) + " " + quote(file) +
                                    (verb.find(' ') == std::string::npos ? "" : verb.substr(verb.find(' '))),
                                "0 0 0\n");
      EXPECT_EQ(r.exitCode, 2) << verb << " " << file << "\n" << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << verb << " " << file << "\n" << r.err.substr(0, 300);
      EXPECT_NE(r.err.find(entry.path().filename().string()), std::string::npos) << r.err.substr(0, 300);
      EXPECT_LT(r.err.size(), 400u) << "the message should be one short sentence: " << r.err.substr(0, 300);
      EXPECT_TRUE(r.out.empty()) << verb << " " << file;
    }
    EXPECT_EQ(fs::last_write_time(entry.path()), stamp) << file;
    EXPECT_EQ(slurp(entry.path()), before) << file;
  }
  EXPECT_GE(files, 25);
  // Nothing new was written next to the inputs.
  int after = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir.path)) ++after;
  EXPECT_EQ(after, files);
}
