// The transition matrix on the command line: info's strong-connectivity warning, bad matrices
// refused with their JSON path, and export-mesh building only the allowed words.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/project_io.h"
#include "run_command.h"
#include "tests/cli/example_projects.h"

using namespace gridifs;
using namespace gridifs::test_support;

namespace {

std::filesystem::path withTransitions(const ScratchDir& dir, const std::string& name, const std::string& matrix) {
  nlohmann::json j = nlohmann::json::parse(slurp(kSierpinski));
  j["transitions"] = nlohmann::json::parse(matrix);
  const auto file = dir.path / name;
  std::ofstream(file) << j.dump(1);
  return file;
}

}  // namespace

TEST(TransitionsCli, InfoWarnsWhenTheGraphIsNotStronglyConnected) {
  const ScratchDir dir("transitions-info");
  const auto connected = withTransitions(dir, "a.gridifs", "[[0,1,1,1],[1,0,1,1],[1,1,0,1],[1,1,1,0]]");
  const CommandResult a = runGridifs("info " + quote(connected.string()) + " --json");
  ASSERT_EQ(a.exitCode, 0) << a.err;
  EXPECT_TRUE(nlohmann::json::parse(a.out)["strongly_connected"].get<bool>());
  EXPECT_EQ(a.err.find("strongly connected"), std::string::npos);
  // 0 ↔ 1 and 2 ↔ 3, with 1 → 2 but no way back.
  const auto split = withTransitions(dir, "b.gridifs", "[[0,1,0,0],[1,0,1,0],[0,0,0,1],[0,0,1,0]]");
  const CommandResult b = runGridifs("info " + quote(split.string()));
  ASSERT_EQ(b.exitCode, 0) << b.err;
  EXPECT_NE(b.err.find("not strongly connected (components {0 1}, {2 3})"), std::string::npos) << b.err;
}

TEST(TransitionsCli, BadMatricesExitTwoWithTheJsonPath) {
  const ScratchDir dir("transitions-bad");
  const struct {
    const char* matrix;
    const char* path;
  } cases[] = {{"[[1,1,1,1],[1,1,1,1],[1,1,1,1]]", "transitions:"},
               {"[[1,1,1,1],[1,1,1,1],[1,1,1],[1,1,1,1]]", "transitions[2]:"},
               {"[[1,1,1,1],[1,1,1,1],[1,1,1,1],[1,-2,1,1]]", "transitions[3][1]:"},
               {"[[0,0,0,0],[1,1,1,1],[1,1,1,1],[1,1,1,1]]", "transitions[0]:"}};
  for (const auto& c : cases) {
    const auto file = withTransitions(dir, "bad.gridifs", c.matrix);
    const std::string before = slurp(file);
    const CommandResult r = runGridifs("info " + quote(file.string()));
    EXPECT_EQ(r.exitCode, 2) << c.matrix;
    EXPECT_NE(r.err.find(c.path), std::string::npos) << r.err;
    EXPECT_EQ(slurp(file), before);
  }
}

TEST(TransitionsCli, ExportMeshBuildsOnlyTheAllowedWords) {
  const ScratchDir dir("transitions-mesh");
  const auto file = withTransitions(dir, "n.gridifs", "[[0,1,1,1],[1,0,1,1],[1,1,0,1],[1,1,1,0]]");
  const auto restricted = dir.path / "r.off", full = dir.path / "f.off";
  ASSERT_EQ(
      runGridifs("export-mesh " + quote(file.string()) + " -o " + quote(restricted.string()) + " --depth 3").exitCode,
      0);
  ASSERT_EQ(runGridifs("export-mesh " + quote(kSierpinski) + " -o " + quote(full.string()) + " --depth 3").exitCode, 0);
  auto faces = [](const std::filesystem::path& off) {
    std::ifstream in(off);
    std::string magic;
    long v = 0, f = 0, e = 0;
    in >> magic >> v >> f >> e;
    return f;
  };
  // 4·3·3 = 36 allowed words of length 3 instead of 4³ = 64.
  EXPECT_EQ(faces(restricted) * 64, faces(full) * 36);
  EXPECT_GT(faces(restricted), 0);
}
