// gridifs volume through the real executable: an OpenVDB file with the density grid, the
// lattice transform and (coloured IFS) the colour grid; bad input → exit 2, one sentence naming
// the file, nothing written.
#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Count.h>

#include <fstream>

#include "run_command.h"

using namespace gridifs::test_support;
namespace fs = std::filesystem;

namespace {

const char* kMedians = R"({"format": "gridifs", "version": 1, "functions": [
  {"name": "A", "kind": "median", "weight": 2, "set": {"primitive": "sphere", "center": [-0.45, 0, 0], "radius": 0.3}},
  {"name": "B", "kind": "median", "weight": 1, "color": [0.2, 0.4, 1],
   "set": {"mesh": "cube.obj", "fill": "solid", "placement": {"translate": [0.45, 0, 0], "scale": [0.3, 0.3, 0.3]}}}],
  "volume": {"resolution": 64, "iterations": 100, "skip": 10, "seed": 1, "samples": 100000}})";

void writeCube(const fs::path& file) {
  std::ofstream out(file);
  for (int v = 0; v < 8; ++v)
    out << "v " << ((v & 1) ? 1 : -1) << " " << ((v & 2) ? 1 : -1) << " " << ((v & 4) ? 1 : -1) << "\n";
  out << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
}

}  // namespace

TEST(VolumeCli, WritesAFogVolumeWithTheLatticeTransform) {
  ScratchDir dir("volume-cli");
  writeCube(dir.path / "cube.obj");
  writeText(dir.path / "two.gridifs", kMedians);
  const fs::path out = dir.path / "two.vdb";
  const CommandResult r = runGridifs("volume " + quote((dir.path / "two.gridifs").string()) + " -o " +
                                     quote(out.string()) + " --resolution 48 --iterations 60 --seed 2 --threads 2");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  openvdb::initialize();
  openvdb::io::File vdb(out.string());
  vdb.open();
  auto density = openvdb::gridPtrCast<openvdb::FloatGrid>(vdb.readGrid("density"));
  ASSERT_TRUE(density);
  EXPECT_EQ(density->getGridClass(), openvdb::GRID_FOG_VOLUME);
  EXPECT_NEAR(density->voxelSize().x(), 2.0 / 48, 1e-12);
  EXPECT_NEAR(density->transform().indexToWorld(openvdb::Vec3d(0, 0, 0)).y(), -1.0 + 1.0 / 48, 1e-12);
  EXPECT_TRUE(vdb.hasGrid("color"));
  vdb.close();
  EXPECT_FLOAT_EQ(openvdb::tools::minMax(density->tree()).max(), 1.0f);
  // The mesh set (a cube scaled to ±0.3 around x = 0.45) carries density at its centre.
  const int i = int((0.45 + 1.0) * 24.0);
  EXPECT_GT(density->getConstAccessor().getValue(openvdb::Coord(i, 24, 24)), 0.0f);
}

TEST(VolumeCli, PointIfsIsBinned) {
  ScratchDir dir("volume-cli-points");
  const fs::path out = dir.path / "s.vdb";
  const CommandResult r =
      runGridifs("volume " + quote(std::string(GRIDIFS_ASSETS) + "/sierpinski_tetrahedron.gridifs") + " -o " +
                 quote(out.string()) + " --resolution 32 --samples 2e5");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::exists(out));
}

TEST(VolumeCli, BadInputExitsTwoAndWritesNothing) {
  ScratchDir dir("volume-cli-bad");
  writeText(dir.path / "two.gridifs", kMedians);  // cube.obj is missing
  const std::string project = quote((dir.path / "two.gridifs").string());
  const fs::path out = dir.path / "two.vdb";
  CommandResult r = runGridifs("volume " + project + " -o " + quote(out.string()));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("cube.obj"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  writeCube(dir.path / "cube.obj");
  r = runGridifs("volume " + project + " -o " + quote(out.string()) + " --resolution 1024");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--resolution"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  r = runGridifs("volume " + project + " -o " + quote((dir.path / "two.png").string()));
  EXPECT_EQ(r.exitCode, 2);
  // An open mesh cannot be filled.
  std::ofstream(dir.path / "cube.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  r = runGridifs("volume " + project + " -o " + quote(out.string()));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("not closed"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  // A VDB set whose grid does not exist.
  writeText(dir.path / "v.gridifs", R"({"format": "gridifs", "version": 1, "functions": [
    {"kind": "median", "set": {"vdb": "none.vdb", "grid": "density", "threshold": 0.5}}]})");
  r = runGridifs("volume " + quote((dir.path / "v.gridifs").string()) + " -o " + quote(out.string()));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("none.vdb"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  // The chaos game's condensation sampler names the set once, under its function.
  writeText(dir.path / "c.gridifs", R"({"format": "gridifs", "version": 1, "functions": [
    {"kind": "condensation", "set": {"mesh": "gone.obj", "fill": "solid"}}]})");
  const fs::path png = dir.path / "c.png";
  r = runGridifs("render " + quote((dir.path / "c.gridifs").string()) + " -o " + quote(png.string()) +
                 " --device cpu -q");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("functions[0].set.mesh"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("functions[0].functions"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(png));
}
