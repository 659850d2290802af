// gridifs export-mesh with condensation functions (A_n = C ∪ F(A_{n−1}), Sokolov & Gentil, §3.1):
// the pine-tree series of one contraction and a tree mesh, face counts |C| + N·|A_{n−1}| in the
// summary and the limit, and bad sets (missing or unreadable mesh, a median function): exit 2,
// one sentence, nothing written.
#include <gtest/gtest.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <algorithm>

#include "mesh/ifs_mesh.h"
#include "run_command.h"
#include "tests/cli/example_projects.h"

using namespace gridifs;
using namespace gridifs::test_support;
namespace fs = std::filesystem;

namespace {

std::string project(const std::string& secondFunction) {
  return R"({"format": "gridifs", "version": 1, "functions": [
    {"name": "half", "resolution": [2, 2, 2], "placement": {"scale": [0.5, 0.5, 0.5]}},
    )" + secondFunction +
         "]}";
}

}  // namespace

TEST(CliExportMeshCondensation, PineTreeSeriesHalvesEachCopy) {
  ScratchDir dir("export-mesh-pine");
  const fs::path out = dir.path / "pines.ply";
  const auto r =
      runGridifs("export-mesh " + quote(kPineTrees) + " -o " + quote(out.string()) + " --depth 5 --base sphere");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // The level-0 sphere has 128 faces and 114 vertices; the tree mesh 264 faces.
  const std::size_t treeFaces = 264, faces = 128 + 5 * treeFaces;
  EXPECT_NE(r.out.find("= " + std::to_string(faces) + " faces"), std::string::npos) << r.out;
  IfsMesh mesh;
  mesh.request_vertex_colors();
  OpenMesh::IO::Options options = OpenMesh::IO::Options::VertexColor;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(mesh, out.string(), options));
  ASSERT_EQ(mesh.n_faces(), faces);
  ASSERT_EQ((mesh.n_vertices() - 114) % 5, 0u);
  const std::size_t treeVertices = (mesh.n_vertices() - 114) / 5;
  // Copy k of the tree is f^k(C) with f a uniform scale by one half: its extent halves per level.
  auto extent = [&](int k) {
    float lo = 1e9f, hi = -1e9f;
    for (std::size_t v = 114 + std::size_t(k) * treeVertices; v < 114 + std::size_t(k + 1) * treeVertices; ++v) {
      const float z = mesh.point(IfsMesh::VertexHandle(int(v)))[2];
      lo = std::min(lo, z);
      hi = std::max(hi, z);
    }
    return hi - lo;
  };
  EXPECT_GT(extent(0), 0.5f);
  for (int k = 1; k < 5; ++k) EXPECT_NEAR(extent(k), 0.5f * extent(k - 1), 1e-4f * extent(0)) << k;
  // The same request with a face limit below the total is refused before any work.
  const fs::path refused = dir.path / "refused.ply";
  const auto r2 = runGridifs("export-mesh " + quote(kPineTrees) + " -o " + quote(refused.string()) +
                             " --depth 5 --base sphere --max-faces 1400");
  EXPECT_EQ(r2.exitCode, 2);
  EXPECT_NE(r2.err.find("1,448 faces"), std::string::npos) << r2.err;
  EXPECT_FALSE(fs::exists(refused));
}

TEST(CliExportMeshCondensation, BadSetsExitTwoAndWriteNothing) {
  ScratchDir dir("export-mesh-condensation-bad");
  writeText(dir.path / "garbage.obj", "this is not a mesh\n");
  writeText(dir.path / "missing.gridifs",
            project(R"({"name": "t", "kind": "condensation", "set": {"mesh": "no_tree.obj", "fill": "solid"}})"));
  writeText(dir.path / "garbage.gridifs",
            project(R"({"name": "t", "kind": "condensation", "set": {"mesh": "garbage.obj", "fill": "solid"}})"));
  writeText(dir.path / "old.ply", "previous content");
  struct Case {
    std::string file, names;
  };
  for (const Case& c : {Case{"missing.gridifs", "no_tree.obj"}, Case{"garbage.gridifs", "garbage.obj"}}) {
    SCOPED_TRACE(c.file);
    const auto r = runGridifs("export-mesh " + quote((dir.path / c.file).string()) + " -o " +
                              quote((dir.path / "old.ply").string()) + " --depth 3");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(c.names), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(slurp(dir.path / "old.ply"), "previous content");
  }
  // A sphere set is built: the export succeeds.
  writeText(dir.path / "ball.gridifs",
            project(R"({"name": "b", "kind": "condensation", "set": {"primitive": "sphere", "radius": 0.3}})"));
  const auto r = runGridifs("export-mesh " + quote((dir.path / "ball.gridifs").string()) + " -o " +
                            quote((dir.path / "ball.ply").string()) + " --depth 3");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  // N = 1: A_3 is one cube and three spheres of 512 faces.
  EXPECT_NE(r.out.find("= " + std::to_string(6 + 3 * 512) + " faces"), std::string::npos) << r.out;
}
