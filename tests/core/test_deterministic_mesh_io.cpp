// Writing F^n(A) through OpenMesh and reading it back (PLY, OFF, OBJ, STL), atomic replacement,
// and the output-path checks the CLI runs before any work.
#include <gtest/gtest.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <algorithm>

#include "deterministic_samples.h"
#include "io/project_io.h"
#include "mesh/deterministic_ifs.h"
#include "mesh/mesh_io.h"

using namespace gridifs;
using namespace gridifs::test_support;
namespace fs = std::filesystem;

namespace {

DeterministicMesh sierpinskiMesh(int depth, bool triangulate = false) {
  BaseMeshSpec spec;
  spec.subdivision = 1;
  spec.triangulate = triangulate;
  DeterministicOptions options;
  options.depth = depth;
  return runDeterministic(snapshotDeterministicIfs(sierpinskiProject()), spec, options);
}

IfsMesh readBack(const fs::path& file, OpenMesh::IO::Options& options) {
  IfsMesh mesh;
  mesh.request_vertex_colors();
  options = OpenMesh::IO::Options::VertexColor;
  EXPECT_TRUE(OpenMesh::IO::read_mesh(mesh, file.string(), options)) << file;
  return mesh;
}

std::vector<fs::path> folderEntries(const fs::path& folder) {
  std::vector<fs::path> entries;
  for (const auto& e : fs::directory_iterator(folder)) entries.push_back(e.path().filename());
  std::sort(entries.begin(), entries.end());
  return entries;
}

std::string slurpFile(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

TEST(MeshIo, FormatsFromExtensions) {
  EXPECT_EQ(meshFormatFromPath("a/b.PLY"), MeshFormat::Ply);
  EXPECT_EQ(meshFormatFromPath("b.obj"), MeshFormat::Obj);
  EXPECT_EQ(meshFormatFromPath("b.Stl"), MeshFormat::Stl);
  EXPECT_EQ(meshFormatFromPath("b.off"), MeshFormat::Off);
  EXPECT_FALSE(meshFormatFromPath("b.xyz"));
  EXPECT_FALSE(meshFormatFromPath("ply"));
  EXPECT_TRUE(formatHasVertexColors(MeshFormat::Ply));
  EXPECT_TRUE(formatHasVertexColors(MeshFormat::Off));
  EXPECT_FALSE(formatHasVertexColors(MeshFormat::Obj));
  EXPECT_TRUE(formatNeedsTriangles(MeshFormat::Stl));
}

TEST(MeshIo, EveryFormatLoadsBackWithItsColors) {
  TempFolder folder("mesh-io-formats");
  const DeterministicMesh quads = sierpinskiMesh(2);
  const DeterministicMesh triangles = sierpinskiMesh(2, true);
  struct Case {
    const char* name;
    bool binary, colors, exactPositions;
  };
  for (const Case c : {Case{"out.ply", true, true, true}, Case{"ascii.ply", false, true, false},
                       Case{"out.off", false, true, false}, Case{"out.obj", false, false, false},
                       Case{"out.stl", true, false, true}, Case{"ascii.stl", false, false, false}}) {
    SCOPED_TRACE(c.name);
    const bool stl = meshFormatFromPath(c.name) == MeshFormat::Stl;
    const IfsMesh& written = stl ? triangles.mesh : quads.mesh;
    writeMeshFile(written, folder / c.name, MeshWriteOptions{c.binary, true});
    OpenMesh::IO::Options got;
    const IfsMesh mesh = readBack(folder / c.name, got);
    ASSERT_EQ(mesh.n_faces(), written.n_faces());
    // STL stores separate triangles: readers weld equal positions, which joins copies that touch
    // (Sierpinski pieces share corners), so only the faces are comparable.
    if (stl) continue;
    EXPECT_EQ(got.vertex_has_color(), c.colors);
    ASSERT_EQ(mesh.n_vertices(), written.n_vertices());
    float worst = 0.0f;
    int colorErrors = 0;
    for (auto vh : mesh.vertices()) {
      worst = std::max(worst, (mesh.point(vh) - written.point(vh)).norm());
      if (c.colors)
        for (int d = 0; d < 3; ++d)  // 8-bit in the file
          colorErrors += std::fabs(mesh.color(vh)[d] - written.color(vh)[d]) > 0.5f / 255.0f + 1e-6f;
    }
    if (c.exactPositions) {
      EXPECT_EQ(worst, 0.0f);
    }
    EXPECT_LT(worst, 1e-6f);
    EXPECT_EQ(colorErrors, 0);
    for (auto fh : mesh.faces()) ASSERT_EQ(mesh.valence(fh), written.valence(fh));
  }
  // Only the finished files are left: the temporaries were renamed.
  EXPECT_EQ(folderEntries(folder.path),
            (std::vector<fs::path>{"ascii.ply", "ascii.stl", "out.obj", "out.off", "out.ply", "out.stl"}));
}

TEST(MeshIo, PlyCarriesTheFaceAddress) {
  TempFolder folder("mesh-io-address");
  const DeterministicMesh out = sierpinskiMesh(2);
  writeMeshFile(out.mesh, folder / "binary.ply");
  const std::string header = slurpFile(folder / "binary.ply").substr(0, 400);
  EXPECT_NE(header.find("format binary_little_endian"), std::string::npos) << header;
  EXPECT_NE(header.find("property uchar red"), std::string::npos) << header;
  EXPECT_NE(header.find("element face 384"), std::string::npos) << header;
  EXPECT_NE(header.find("property int address"), std::string::npos) << header;
  // OpenMesh reads custom properties from ASCII PLY: the addresses survive the round trip.
  writeMeshFile(out.mesh, folder / "ascii.ply", MeshWriteOptions{false, true});
  IfsMesh mesh;
  OpenMesh::IO::Options options = OpenMesh::IO::Options::Custom;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(mesh, (folder / "ascii.ply").string(), options));
  OpenMesh::FPropHandleT<int> address;
  ASSERT_TRUE(mesh.get_property_handle(address, "address"));
  const auto written = addressProperty(out.mesh);
  for (auto fh : mesh.faces()) ASSERT_EQ(mesh.property(address, fh), out.mesh.property(written, fh));
}

TEST(MeshIo, ReplacesAtomicallyAndFailsCleanly) {
  TempFolder folder("mesh-io-atomic");
  const DeterministicMesh small = sierpinskiMesh(1);
  const DeterministicMesh large = sierpinskiMesh(3);
  writeMeshFile(small.mesh, folder / "a.ply");
  writeMeshFile(large.mesh, folder / "a.ply");  // replaces
  OpenMesh::IO::Options got;
  EXPECT_EQ(readBack(folder / "a.ply", got).n_faces(), large.mesh.n_faces());

  // The target is a folder: IoError naming it, the folder untouched, no temporary left.
  fs::create_directories(folder / "dir.ply");
  try {
    writeMeshFile(small.mesh, folder / "dir.ply");
    ADD_FAILURE() << "writing over a folder succeeded";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find((folder / "dir.ply").string()), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_directory(folder / "dir.ply"));
  EXPECT_THROW(writeMeshFile(small.mesh, folder / "missing" / "a.ply"), IoError);
  EXPECT_THROW(writeMeshFile(small.mesh, folder / "a.xyz"), ModelError);
  EXPECT_EQ(folderEntries(folder.path), (std::vector<fs::path>{"a.ply", "dir.ply"}));
}

TEST(MeshIo, OutputPathsAreCheckedBeforeWork) {
  TempFolder folder("mesh-io-check");
  const auto messageOf = [](const fs::path& p) -> std::string {
    try {
      checkMeshOutputPath(p);
    } catch (const ModelError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(messageOf(folder / "fine.ply"), "");
  EXPECT_EQ(messageOf(folder / "fine.STL"), "");
  fs::create_directories(folder / "dir.obj");
  for (const fs::path& bad : {folder / "x.xyz", folder / "noext", folder / "missing" / "x.ply", folder / "dir.obj"}) {
    const std::string m = messageOf(bad);
    EXPECT_NE(m.find(bad.string()), std::string::npos) << m;
    EXPECT_NE(m.find("cannot write"), std::string::npos) << m;
  }
  EXPECT_NE(messageOf(folder / "x.xyz").find("unknown mesh format"), std::string::npos);
  EXPECT_EQ(folderEntries(folder.path), (std::vector<fs::path>{"dir.obj"}));  // no probe left behind
}
