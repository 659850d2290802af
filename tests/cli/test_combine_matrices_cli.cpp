// IFS matrices with states on the command line (Thollot, Zair, Tosan & Vandorpe 1997, §3.2, §4):
// `combine` with every operation on grid, free-form and state projects, the attractor of the
// results (export-points, export-mesh), `info` on the state graph, and bad input.
#include <gtest/gtest.h>

#include <cstring>
#include <glm/geometric.hpp>

#include "exported_points.h"
#include "freeform/free_form_presets.h"
#include "freeform/state_expansion.h"
#include "io/project_io.h"
#include "run_command.h"
#include "tests/cli/example_projects.h"

using namespace gridifs;
using namespace gridifs::test_support;

namespace {

CommandResult combine(const std::filesystem::path& a, const std::filesystem::path& b, const std::string& op,
                      const std::filesystem::path& out) {
  return runGridifs("combine " + quote(a.string()) + " " + quote(b.string()) + " --op " + op + " -o " +
                    quote(out.string()));
}

/// The Sierpinski tetrahedron with its first map from state 0 only: the attractor is f1's corner copy.
Project cornerProject() {
  Project p = loadProject(kSierpinski);
  p.states = IfsStates{{{{}, {0}}, {{}, {0, 1, 2, 3}}}, {0}, {1}};
  return p;
}

}  // namespace

TEST(CombineMatricesCli, EveryOperationOnGridProjects) {
  const ScratchDir dir("combine-matrices");
  const auto corner = dir.path / "corner.gridifs";
  saveProject(cornerProject(), corner);
  const std::filesystem::path sierpinski = kSierpinski;
  for (const char* op : {"union", "concat", "product", "shuffle", "intersection", "composition", "matrix-union"}) {
    // State projects with each other and with a plain one.
    for (const auto& [a, b] : {std::pair{corner, corner}, std::pair{sierpinski, corner}}) {
      if (std::string(op) == "intersection" || std::string(op) == "matrix-union" || std::string(op) == "composition")
        if (a != b) continue;  // different numbers of states (checked below)
      const auto out = dir.path / (std::string(op) + ".gridifs");
      const CommandResult r = combine(a, b, op, out);
      ASSERT_EQ(r.exitCode, 0) << op << ": " << r.err;
      const Project c = loadProject(out);
      ASSERT_TRUE(c.states) << op;
      EXPECT_TRUE(c.transitions.empty());
      // --samples counts chaos-game steps: with states the skip phase and hidden steps plot nothing.
      const auto points = exportPoints(out, dir.path / "c.ply", 3000);
      EXPECT_GT(points.size(), 150u) << op;
    }
  }
  // The corner with itself entrywise is the corner: every point in f1's corner copy.
  const auto same = dir.path / "same.gridifs";
  ASSERT_EQ(combine(corner, corner, "intersection", same).exitCode, 0);
  const Project c = loadProject(same);
  EXPECT_EQ(c.functions.size(), 4u);  // the same names: the same functions
  const Vec3 f1corner = loadProject(kSierpinski).functions[0].placement.translate;
  for (const Vec3& p : exportPoints(same, dir.path / "same.ply", 4000))
    EXPECT_LT(glm::length(p - f1corner), 0.5 * std::sqrt(3.0) + 1e-3);
  // Grid product and shuffle of two plain projects now combine too (the paper's tensor operations).
  for (const char* op : {"product", "shuffle"}) {
    const CommandResult r = combine(sierpinski, sierpinski, op, dir.path / "plain.gridifs");
    EXPECT_EQ(r.exitCode, 0) << r.err;
  }
}

TEST(CombineMatricesCli, FreeFormProjectsWithTheSameControlPoints) {
  const ScratchDir dir("combine-matrices-free");
  Project a = defaultNewProject();
  applyFreeFormPreset(a, FreeFormPreset::Sierpinski);
  saveProject(a, dir.path / "a.gridifs");
  for (const char* op : {"concat", "intersection", "composition", "matrix-union", "union"}) {
    const auto out = dir.path / (std::string(op) + ".gridifs");
    const CommandResult r = combine(dir.path / "a.gridifs", dir.path / "a.gridifs", op, out);
    ASSERT_EQ(r.exitCode, 0) << op << ": " << r.err;
    EXPECT_GT(exportPoints(out, dir.path / "c.ply", 2000).size(), 400u) << op;
  }
}

TEST(CombineMatricesCli, ResultsWithoutAttractorAndMismatchedStatesExitTwo) {
  const ScratchDir dir("combine-matrices-bad");
  const auto corner = dir.path / "corner.gridifs", out = dir.path / "out.gridifs";
  saveProject(cornerProject(), corner);
  std::ofstream(out) << "keep me";
  const struct {
    std::string a, b, op, message;
  } cases[] = {
      {kSierpinski, corner.string(), "intersection", "needs two matrices with the same states"},
      {kSierpinski, corner.string(), "matrix-union", "needs two matrices with the same states"},
  };
  for (const auto& c : cases) {
    const CommandResult r = combine(c.a, c.b, c.op, out);
    EXPECT_EQ(r.exitCode, 2) << c.op;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(slurp(out), "keep me");
  }
  // A bad state matrix in a file: exit 2 naming the JSON path, nothing written.
  std::string text = serializeProject(loadProject(kSierpinski));
  text.insert(text.rfind('}'),
              ",\"states\": {\"matrix\": [[[0], [1]], [[2, 1, 9], [3]]], \"initial\": [0], \"final\": [1]}\n");
  std::ofstream(dir.path / "bad.gridifs") << text;
  const CommandResult r = runGridifs("render " + quote((dir.path / "bad.gridifs").string()) + " -o " +
                                     quote((dir.path / "bad.png").string()) + " --samples 1000");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("states.matrix[1][0][2]"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path / "bad.png"));
}

TEST(CombineMatricesCli, InfoAndExportMeshFollowTheStates) {
  const ScratchDir dir("combine-matrices-info");
  const auto corner = dir.path / "corner.gridifs";
  saveProject(cornerProject(), corner);
  const CommandResult info = runGridifs("info " + quote(corner.string()));
  ASSERT_EQ(info.exitCode, 0) << info.err;
  EXPECT_NE(info.out.find("states: 2, initial {0}, final {1}"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("strongly connected component {0}: passed through once"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("strongly connected component {1}: a cycle"), std::string::npos) << info.out;
  const CommandResult json = runGridifs("info " + quote(corner.string()) + " --json");
  EXPECT_NE(json.out.find("\"components\""), std::string::npos);
  const auto mesh = dir.path / "corner.ply";
  const CommandResult r =
      runGridifs("export-mesh " + quote(corner.string()) + " -o " + quote(mesh.string()) + " --depth 3");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_GT(std::filesystem::file_size(mesh), 1000u);
}
