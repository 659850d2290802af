// The model verbs through the real executable: info, nodes, eval, and the
// bad-input corpus: every hostile file → exit 2, one sentence, nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "run_command.h"
#include "tests/cli/example_projects.h"

using namespace gridifs::test_support;
namespace fs = std::filesystem;

namespace {

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

// Every file of the bad-input corpus gets its own sentence, the same from every verb: the JSON
// path and what is wrong there, so a message that loses its path or its words fails here.
TEST(CliModel, BadInputCorpusSaysWhatIsWrong) {
  const std::map<std::string, std::string> expected = {
      {"bend_same_axis.gridifs", "functions[0].ops[0].toward: the bend must go toward an axis other than its own."},
      {"calculator_nan.gridifs", "functions[0].ops[0].x: the expression gives a non-finite value at node (0, 0, 0)."},
      {"calculator_syntax.gridifs", "functions[0].ops[0].x: unexpected end of expression at position 6."},
      {"calculator_unknown_variable.gridifs", "functions[0].ops[0].y: unexpected token \"w\" found at position 2."},
      {"color_out_of_range.gridifs", "functions[0].color[0]: expected a number between 0 and 1, found 2."},
      {"empty.gridifs", "the file is empty."},
      {"functions_not_array.gridifs", "functions: expected an array, found an object."},
      {"inf_number.gridifs", "the file contains a number too large to represent."},
      {"morph_singular.gridifs",
       "functions[0].ops[0].pairs: two morph start points coincide (pair 1), so the morph system is singular."},
      {"nan_literal.gridifs", "the file is not valid JSON at line 1, column 86."},
      {"negative_weight.gridifs", "functions[0].weight: expected a number between 0 and 1e+09, found -1."},
      {"no_functions.gridifs", "functions: the IFS needs at least one function."},
      {"not_json.gridifs", "the file is not valid JSON at line 1, column 2."},
      {"overflow_ops.gridifs",
       "functions[0].ops[0].factors[0]: expected a number between -1e+06 and 1e+06, found 1e+300."},
      {"render_zero_width.gridifs", "render.width: expected an integer between 1 and 16384."},
      {"resolution_1.gridifs", "functions[0].resolution[0]: expected an integer between 2 and 128."},
      {"resolution_huge.gridifs", "functions[0].resolution[0]: expected an integer between 2 and 128."},
      {"root_array.gridifs", "(root): expected an object, found an array."},
      {"selection_bad_index.gridifs", "functions[0].ops[0].selection[0].i[1]: expected an integer, found a string."},
      {"set_unknown_primitive.gridifs",
       "functions[0].set.primitive: expected \"sphere\", \"box\" or \"torus\", found \"cone\"."},
      {"truncated.gridifs", "the JSON ends too early (truncated?) at line 1, column 76."},
      {"unknown_op.gridifs",
       "functions[0].ops[0].type: unknown operation \"explode\" (expected translate, rotate, scale, taper, twist, "
       "bend, magnet, morph, calculator, nodes or field)."},
      {"unknown_version.gridifs", "version: unsupported version 99 (this GridIFS reads version 1)."},
      {"volume_field_negative_period.gridifs",
       "volume.field.period[3]: expected a number between 0 and 1e+06, found -4."},
      {"volume_resolution_huge.gridifs", "volume.resolution: expected an integer between 16 and 512."},
      {"weight_string.gridifs", "functions[0].weight: expected a number, found a string."},
      {"zero_weights.gridifs", "functions: every active function has weight 0 (weights must not all be zero)."},
  };
  int files = 0;
  for (const auto& entry : fs::directory_iterator(std::string(GRIDIFS_TEST_DATA) + "/bad")) {
    ++files;
    const std::string name = entry.path().filename().string();
    const auto it = expected.find(name);
    if (it == expected.end()) {
      ADD_FAILURE() << "tests/data/bad/" << name << " has no expected sentence in this test";
      continue;
    }
    const std::string want = "gridifs: " + entry.path().string() + ": " + it->second + "\n";
    for (const std::string verb : {"info", "nodes", "eval"}) {
      const std::string extra = verb == "info" ? "" : " --function 0";
      const auto r = runGridifs(verb + " " + quote(entry.path().string()) + extra, "0 0 0\n");
      EXPECT_EQ(r.exitCode, 2) << verb << " " << name;
      EXPECT_EQ(r.err, want) << verb << " " << name;
    }
  }
  EXPECT_EQ(files, int(expected.size())) << "a corpus file with an expected sentence is missing";
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
