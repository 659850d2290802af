// gridifs export-mesh through the real executable: every format loads back
// through OpenMesh with the right counts and colors; bad input → exit 2, one sentence naming the
// file, nothing written.
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

struct Loaded {
  bool ok = false;
  IfsMesh mesh;
  bool colors = false;
};

Loaded load(const fs::path& file) {
  Loaded l;
  l.mesh.request_vertex_colors();
  OpenMesh::IO::Options options = OpenMesh::IO::Options::VertexColor;
  l.ok = OpenMesh::IO::read_mesh(l.mesh, file.string(), options);
  l.colors = options.vertex_has_color();
  return l;
}

std::vector<std::string> entries(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(folder)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::size_t lineCount(const std::string& text) { return std::size_t(std::count(text.begin(), text.end(), '\n')); }

}  // namespace

TEST(CliExportMesh, SierpinskiInEveryFormat) {
  ScratchDir dir("export-mesh-formats");
  struct Case {
    const char* name;
    std::size_t faces, vertices;
    bool colors;
  };
  // 4^3 copies of the cube: 6 quads and 8 vertices each; STL triangulates (12 per cube).
  for (const Case c : {Case{"s.ply", 384, 512, true}, Case{"s.off", 384, 512, true}, Case{"s.obj", 384, 512, false},
                       Case{"s.stl", 768, 0, false}}) {
    SCOPED_TRACE(c.name);
    const fs::path out = dir.path / c.name;
    const auto r = runGridifs("export-mesh " + quote(kSierpinski) + " -o " + quote(out.string()) + " --depth 3");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("= " + std::to_string(c.faces) + " faces"), std::string::npos) << r.out;
    EXPECT_EQ(r.err.find('\r'), std::string::npos);  // no progress bar when stderr is not a terminal
    const Loaded l = load(out);
    ASSERT_TRUE(l.ok);
    EXPECT_EQ(l.mesh.n_faces(), c.faces);
    if (c.vertices) {
      EXPECT_EQ(l.mesh.n_vertices(), c.vertices);
    }
    if (c.vertices) {  // OpenMesh's STL reader leaves the color flag as requested
      EXPECT_EQ(l.colors, c.colors);
    }
    if (!c.colors) {
      EXPECT_NE(r.err.find("no vertex colors"), std::string::npos) << r.err;
    }
    // All inside the tetrahedron's bounding cube.
    for (auto vh : l.mesh.vertices())
      for (int d = 0; d < 3; ++d) ASSERT_LE(std::fabs(l.mesh.point(vh)[d]), 1.0f + 1e-6f);
  }
  EXPECT_EQ(entries(dir.path), (std::vector<std::string>{"s.obj", "s.off", "s.ply", "s.stl"}));
}

TEST(CliExportMesh, ColorsAreTheFunctionColorsAtDepthOne) {
  ScratchDir dir("export-mesh-colors");
  const fs::path out = dir.path / "one.ply";
  const auto r = runGridifs("export-mesh " + quote(kSierpinski) + " -o " + quote(out.string()) + " --depth 1");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Loaded l = load(out);
  ASSERT_TRUE(l.ok && l.colors);
  // The asset's first function is orange (1, 0.55, 0.15): the first copy's 8 vertices.
  const auto c = l.mesh.color(IfsMesh::VertexHandle(0));
  EXPECT_NEAR(c[0], 1.0f, 1.0f / 255.0f);
  EXPECT_NEAR(c[1], 0.55f, 1.0f / 255.0f);
  EXPECT_NEAR(c[2], 0.15f, 1.0f / 255.0f);
}

TEST(CliExportMesh, BasesAndSubdivision) {
  ScratchDir dir("export-mesh-bases");
  writeText(dir.path / "tetra.off",
            "OFF\n4 4 0\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n");
  struct Case {
    std::string args;
    std::size_t faces;
  };
  for (const Case& c :
       {Case{"--base sphere", 16 * 128}, Case{"--base sphere --subdivide 1", 16 * 512}, Case{"--subdivide 2", 16 * 96},
        Case{"--subdivide 1 --smooth", 16 * 24}, Case{"--base " + quote((dir.path / "tetra.off").string()), 16 * 4},
        Case{"--base " + quote((dir.path / "tetra.off").string()) + " --subdivide 2 --fit", 16 * 64}}) {
    SCOPED_TRACE(c.args);
    const fs::path out = dir.path / "out.ply";
    const auto r =
        runGridifs("export-mesh " + quote(kSierpinski) + " -o " + quote(out.string()) + " --depth 2 " + c.args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Loaded l = load(out);
    ASSERT_TRUE(l.ok);
    EXPECT_EQ(l.mesh.n_faces(), c.faces);
  }
}

TEST(CliExportMesh, BadInputExitsTwoNamingTheFileAndWritesNothing) {
  ScratchDir dir("export-mesh-bad");
  writeText(dir.path / "empty.ply", "");
  writeText(dir.path / "points.ply",
            "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
            "end_header\n0 0 0\n1 1 1\n");
  writeText(dir.path / "fin.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n");
  writeText(dir.path / "bad.gridifs",
            "{\"format\": \"gridifs\", \"version\": 1, \"functions\": [{\"weight\": \"x\"}]}");
  writeText(dir.path / "old.ply", "previous content");
  fs::create_directories(dir.path / "folder.ply");
  const std::string d = dir.path.string();
  const std::string good = " -o " + quote(d + "/old.ply") + " --depth 2";
  struct Case {
    std::string args, names;  // `names`: the file the sentence must name
  };
  const std::vector<Case> cases = {
      {quote(kSierpinski) + good + " --base " + quote(d + "/missing.obj"), d + "/missing.obj"},
      {quote(kSierpinski) + good + " --base " + quote(d + "/empty.ply"), d + "/empty.ply"},
      {quote(kSierpinski) + good + " --base " + quote(d + "/points.ply"), d + "/points.ply"},
      {quote(kSierpinski) + good + " --base " + quote(d + "/fin.obj"), d + "/fin.obj"},
      {quote(kSierpinski) + " -o " + quote(d + "/old.ply") + " --depth 40", kSierpinski},
      {quote(kSierpinski) + " -o " + quote(d + "/old.ply") + " --depth 9 --base sphere --subdivide 3", kSierpinski},
      {quote(kSierpinski) + " -o " + quote(d + "/nowhere/x.ply") + " --depth 2", d + "/nowhere/x.ply"},
      {quote(kSierpinski) + " -o " + quote(d + "/x.xyz") + " --depth 2", d + "/x.xyz"},
      {quote(kSierpinski) + " -o " + quote(d + "/folder.ply") + " --depth 2", d + "/folder.ply"},
      {quote(d + "/missing.gridifs") + good, d + "/missing.gridifs"},
      {quote(d + "/bad.gridifs") + good, d + "/bad.gridifs"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args);
    const auto r = runGridifs("export-mesh " + c.args);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(lineCount(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find(c.names), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(slurp(dir.path / "old.ply"), "previous content");
  }
  // Usage errors are bad input too.
  for (const std::string& args :
       std::vector<std::string>{quote(kSierpinski) + " -o " + quote(d + "/x.ply") + " --depth -1",
                                quote(kSierpinski) + " -o " + quote(d + "/x.ply"),
                                quote(kSierpinski) + " -o " + quote(d + "/x.ply") + " --depth 2 --subdivide 99"}) {
    const auto r = runGridifs("export-mesh " + args);
    EXPECT_EQ(r.exitCode, 2) << args << ": " << r.err;
  }
  EXPECT_EQ(entries(dir.path),
            (std::vector<std::string>{"bad.gridifs", "empty.ply", "fin.obj", "folder.ply", "old.ply", "points.ply"}));
}

TEST(CliExportMesh, FaceLimitRefusesBeforeWork) {
  ScratchDir dir("export-mesh-budget");
  // Depth 8 of the subdivided cube is ~1.6 M faces: under the hard limit, so it is written; a
  // lowered limit refuses the same request.
  const fs::path out = dir.path / "big.ply";
  auto r = runGridifs("export-mesh " + quote(kSierpinski) + " -o " + quote(out.string()) +
                      " --depth 8 --subdivide 1 --max-faces 1000000");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("1,572,864 faces"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  r = runGridifs("export-mesh " + quote(kSierpinski) + " -o " + quote(out.string()) + " --depth 6 --subdivide 1");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(load(out).ok);
}
