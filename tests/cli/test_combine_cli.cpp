// `gridifs combine A B --op OP -o C` on real files: the union's attractor is the union of the two
// attractors, bad input exits 2 with one sentence and leaves the output untouched, and the
// free-form operations build the tensor product and sum.
#include <gtest/gtest.h>

#include <cstring>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "exported_points.h"
#include "freeform/free_form_presets.h"
#include "io/project_io.h"
#include "run_command.h"
#include "tests/cli/example_projects.h"

using namespace gridifs;
using namespace gridifs::test_support;

namespace {

double nearest(const std::vector<Vec3>& cloud, Vec3 p) {
  double best = 1e9;
  for (const Vec3& q : cloud) best = std::min(best, glm::length(q - p));
  return best;
}

/// A small Sierpinski tetrahedron in the (-1, -1, -1) corner of X, away from the big one:
/// f_i(x) = 0.2·x + 0.2·v_i + 0.8·c with corners v_i and centre c = (-0.7, -0.7, -0.7).
std::filesystem::path movedSierpinski(const std::filesystem::path& dir) {
  Project p = loadProject(kSierpinski);
  for (Function& f : p.functions) {
    f.placement.translate = 0.4 * f.placement.translate + Vec3{-0.56};
    f.placement.scale = Vec3{0.2};
  }
  const auto file = dir / "moved.gridifs";
  saveProject(p, file);
  return file;
}

}  // namespace

TEST(CombineCli, UnionIsTheUnionOfTheAttractors) {
  const ScratchDir dir("combine-union");
  const auto b = movedSierpinski(dir.path);
  const auto c = dir.path / "c.gridifs";
  const CommandResult r =
      runGridifs("combine " + quote(kSierpinski) + " " + quote(b.string()) + " --op union -o " + quote(c.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Project combined = loadProject(c);
  ASSERT_EQ(combined.functions.size(), 8u);
  EXPECT_EQ(combined.transitions[0][4], 0.0);  // block diagonal
  EXPECT_EQ(combined.transitions[5][1], 0.0);
  EXPECT_EQ(combined.transitions[5][6], 1.0);
  const auto pa = exportPoints(kSierpinski, dir.path / "a.ply", 20000);
  const auto pb = exportPoints(b, dir.path / "b.ply", 20000);
  // Enough samples that every chain restarts a few times (a chain stays in the half it started in
  // until it restarts), and a stride prime to the 4 interleaved chains of each worker.
  const auto pc = exportPoints(c, dir.path / "c.ply", 40000);
  ASSERT_GT(pc.size(), 38000u);  // less the skipped first iterations of each chain
  int nearA = 0, nearB = 0;
  for (std::size_t i = 0; i < pc.size(); i += 13) {
    const double da = nearest(pa, pc[i]), db = nearest(pb, pc[i]);
    EXPECT_LT(std::min(da, db), 0.05) << "a point of the union is on neither attractor";
    nearA += da < db;
    nearB += db <= da;
  }
  EXPECT_GT(nearA, 600);  // both parts are drawn, about equally (equal total weights)
  EXPECT_GT(nearB, 600);
}

TEST(CombineCli, ConcatLetsTheFirstContinueIntoTheSecond) {
  const ScratchDir dir("combine-concat");
  const auto b = movedSierpinski(dir.path);
  const auto c = dir.path / "c.gridifs";
  ASSERT_EQ(
      runGridifs("combine " + quote(kSierpinski) + " " + quote(b.string()) + " --op concat -o " + quote(c.string()))
          .exitCode,
      0);
  const Project combined = loadProject(c);
  EXPECT_EQ(combined.transitions[0][4], 1.0);  // A → B allowed
  EXPECT_EQ(combined.transitions[4][0], 0.0);  // B → A not
  const CommandResult info = runGridifs("info " + quote(c.string()));
  EXPECT_NE(info.err.find("not strongly connected"), std::string::npos) << info.err;
}

TEST(CombineCli, FreeFormProductIsTheSumOfTheAttractors) {
  const ScratchDir dir("combine-product");
  // A: a planar curve (z = 0); B: a cubic along z only. A ⊗ B plots A(s) + B(t).
  Project a = defaultNewProject(), b = defaultNewProject();
  applyFreeFormPreset(a, FreeFormPreset::BezierCurve);
  for (Vec3& p : a.space->control_points) p.z = 0.0;
  applyFreeFormPreset(b, FreeFormPreset::BezierCurve);
  b.space->control_points = {{0, 0, -0.5}, {0, 0, 0.4}, {0, 0, -0.2}, {0, 0, 0.5}};
  saveProject(a, dir.path / "a.gridifs");
  saveProject(b, dir.path / "b.gridifs");
  for (const char* op : {"product", "shuffle"}) {
    const auto c = dir.path / (std::string(op) + ".gridifs");
    const CommandResult r =
        runGridifs("combine " + quote((dir.path / "a.gridifs").string()) + " " +
                   quote((dir.path / "b.gridifs").string()) + " --op " + op + " -o " + quote(c.string()));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Project combined = loadProject(c);
    EXPECT_EQ(combined.space->control_points.size(), 16u);
    EXPECT_EQ(combined.functions.size(), std::string(op) == "product" ? 4u : 4u);
    const auto pa = exportPoints(dir.path / "a.gridifs", dir.path / "a.ply", 20000);
    const auto pc = exportPoints(c, dir.path / "c.ply", 3000);
    double zmin = 1, zmax = -1;
    for (std::size_t i = 0; i < pc.size(); i += 3) {
      EXPECT_LT(nearest(pa, Vec3{pc[i].x, pc[i].y, 0.0}), 0.03) << op;
      zmin = std::min(zmin, pc[i].z);
      zmax = std::max(zmax, pc[i].z);
    }
    EXPECT_LT(zmin, -0.2) << op;  // B's range in z is covered
    EXPECT_GT(zmax, 0.2) << op;
  }
}

TEST(CombineCli, BadInputExitsTwoAndWritesNothing) {
  const ScratchDir dir("combine-bad");
  const auto out = dir.path / "out.gridifs";
  std::ofstream(out) << "keep me";
  Project freeForm = defaultNewProject();
  applyFreeFormPreset(freeForm, FreeFormPreset::Sierpinski);
  saveProject(freeForm, dir.path / "free.gridifs");
  std::ofstream(dir.path / "broken.gridifs") << "{\"format\": \"gridifs\"";
  Project other = freeForm;
  other.space->control_points[0].x += 0.25;
  saveProject(other, dir.path / "other.gridifs");
  // The same maps under other names: an intersection with nothing in common.
  Project renamed = loadProject(kSierpinski);
  for (Function& fn : renamed.functions) fn.name += "'";
  const auto moved = dir.path / "renamed.gridifs";
  saveProject(renamed, moved);
  const std::string s = quote(kSierpinski), f = quote((dir.path / "free.gridifs").string());
  const struct {
    std::string args, message;
  } cases[] = {
      {s + " " + s + " --op intersect", "--op must be union, concat, product, shuffle, intersection"},
      {s + " " + quote(moved.string()) + " --op intersection", "has no attractor"},
      {s + " " + f + " --op union", "combine needs two of the same kind"},
      {f + " " + quote((dir.path / "other.gridifs").string()) + " --op concat", "needs the same control points"},
      {s + " " + quote((dir.path / "broken.gridifs").string()) + " --op union", "broken.gridifs"},
      {s + " " + quote((dir.path / "missing.gridifs").string()) + " --op union", "missing.gridifs"},
  };
  for (const auto& c : cases) {
    const CommandResult r = runGridifs("combine " + c.args + " -o " + quote(out.string()));
    EXPECT_EQ(r.exitCode, 2) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(slurp(out), "keep me");
  }
}
