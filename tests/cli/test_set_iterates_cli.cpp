// The deterministic algorithm over sets and the book of drawings from the command line (gridifs
// volume --depth D [--pages]), drawings as sets, and render / export-points / export-mesh of
// projects with median functions: real files through the real executable.
#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Count.h>

#include <cmath>
#include <cstring>
#include <fstream>

#include "run_command.h"

using namespace gridifs::test_support;
namespace fs = std::filesystem;

namespace {

/// A small 2D project: medians onto a comma and a letter drawn in PNGs (copied from the assets),
/// looking down z, with the render settings of a thumbnail.
std::string drawingProject(const std::string& extraFunction = "", const std::string& start = "") {
  return std::string(R"({"format": "gridifs", "version": 1,
    "camera": {"yaw": -90, "pitch": 89.9, "distance": 3.4, "target": [0, 0, 0], "fov": 35, "ortho": true},
    "render": {"width": 64, "height": 64, "samples": 40000, "background": [1, 1, 1], "depth_cue": 0},
    "functions": [
      {"name": "A", "kind": "median", "color": [0, 0, 0], "set": {"image": "comma.png", "thickness": 0.2}},
      {"name": "B", "kind": "median", "color": [0, 0, 0], "set": {"image": "letter_l.png", "thickness": 0.2}})") +
         extraFunction + R"(],
    "volume": {"resolution": 32, "iterations": 60, "skip": 20)" +
         (start.empty() ? "" : R"(, "start": )" + start) + "}}";
}

struct DrawingDir : ScratchDir {
  explicit DrawingDir(const std::string& name, const std::string& project = drawingProject()) : ScratchDir(name) {
    for (const char* png : {"comma.png", "letter_l.png", "bananas.png"})
      fs::copy_file(std::string(GRIDIFS_ASSETS) + "/volumes/" + png, path / png);
    writeText(path / "p.gridifs", project);
  }
  std::string project() const { return quote((path / "p.gridifs").string()); }
  std::string out(const std::string& name) const { return quote((path / name).string()); }
};

struct VdbStats {
  std::uint64_t active = 0;
  float min = 0.0f, max = 0.0f;
};

VdbStats readDensity(const fs::path& file) {
  openvdb::initialize();
  openvdb::io::File vdb(file.string());
  vdb.open();
  auto density = openvdb::gridPtrCast<openvdb::FloatGrid>(vdb.readGrid("density"));
  vdb.close();
  VdbStats s;
  if (!density) return s;
  s.active = density->activeVoxelCount();
  const auto range = openvdb::tools::minMax(density->tree());
  s.min = range.min();
  s.max = range.max();
  return s;
}

std::size_t countFiles(const fs::path& dir, const std::string& ext) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.path().extension() == ext;
  return n;
}

}  // namespace

TEST(SetIteratesCli, DepthWritesTheSetIterateAsAVolumeOfOnes) {
  DrawingDir dir("setiter-depth");
  CommandResult r = runGridifs("volume " + dir.project() + " --depth 0 -o " + dir.out("a0.vdb") + " -q");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(readDensity(dir.path / "a0.vdb").active, 32u * 32u * 32u);  // A_0 = X without volume.start
  r = runGridifs("volume " + dir.project() + " --depth 3 -o " + dir.out("a3.vdb") + " -q --threads 2");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const VdbStats a3 = readDensity(dir.path / "a3.vdb");
  EXPECT_GT(a3.active, 100u);
  EXPECT_LT(a3.active, 32u * 32u * 32u / 4);
  EXPECT_EQ(a3.min, 1.0f);
  EXPECT_EQ(a3.max, 1.0f);
  // The same iterate as a mesh (iso-surface) and as an image.
  r = runGridifs("volume " + dir.project() + " --depth 3 -o " + dir.out("a3.obj") + " -q");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(slurp(dir.path / "a3.obj").find("\nf "), std::string::npos);
  r = runGridifs("volume " + dir.project() + " --depth 3 -o " + dir.out("a3.png") + " -q");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_GT(fs::file_size(dir.path / "a3.png"), 100u);
  // export-mesh of a project with median functions: the iso-surface of the same A_D.
  r = runGridifs("export-mesh " + dir.project() + " --depth 3 -o " + dir.out("e3.obj"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(slurp(dir.path / "e3.obj"), slurp(dir.path / "a3.obj"));
}

TEST(SetIteratesCli, PagesAreNumberedByAddressInBaseN) {
  // A third, constant map (σ = 2) onto a box: every page whose address starts with 2 is the box.
  DrawingDir dir("setiter-pages", drawingProject(R"(, {"name": "C", "kind": "condensation",
                                      "set": {"primitive": "box", "center": [0, -0.6, 0], "size": [0.4, 0.2, 0.2]}})",
                                                 R"({"image": "bananas.png", "thickness": 0.2})"));
  const CommandResult r =
      runGridifs("volume " + dir.project() + " --depth 2 --pages -o " + dir.out("p_%02d.vdb") + " -q");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(countFiles(dir.path, ".vdb"), 9u);
  for (int n = 0; n < 9; ++n) EXPECT_TRUE(fs::exists(dir.path / ("p_0" + std::to_string(n) + ".vdb"))) << n;
  const std::uint64_t box = readDensity(dir.path / "p_06.vdb").active;
  EXPECT_EQ(readDensity(dir.path / "p_07.vdb").active, box);
  EXPECT_EQ(readDensity(dir.path / "p_08.vdb").active, box);
  EXPECT_NE(readDensity(dir.path / "p_00.vdb").active, box);
  // Pages as images: one PNG per page.
  const CommandResult images =
      runGridifs("volume " + dir.project() + " --depth 1 --pages -o " + dir.out("page_%d.png") + " -q");
  ASSERT_EQ(images.exitCode, 0) << images.err;
  EXPECT_EQ(countFiles(dir.path, ".png"), 3u + 3u);  // three drawings copied, three pages
  EXPECT_NE(slurp(dir.path / "page_0.png"), slurp(dir.path / "page_1.png"));
}

TEST(SetIteratesCli, RenderExportPointsAndMeshAcceptMedianFunctions) {
  DrawingDir dir("setiter-render");
  CommandResult r = runGridifs("render " + dir.project() + " -o " + dir.out("r.png") + " -q --device cpu");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_GT(fs::file_size(dir.path / "r.png"), 100u);
  r = runGridifs("export-points " + dir.project() + " -o " + dir.out("p.ply") + " --samples 1000 -q --device cpu");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // The points lie in the voxels of the drawings' density volume: the slab |z| ≤ 0.1 of X.
  const std::string ply = slurp(dir.path / "p.ply");
  const std::size_t header = ply.find("end_header\n");
  ASSERT_NE(header, std::string::npos);
  const std::size_t stride = 3 * sizeof(float) + 3;  // x y z float, red green blue uchar
  const std::size_t count = (ply.size() - header - 11) / stride;
  ASSERT_GT(count, 500u);
  for (std::size_t i = 0; i < count; ++i) {
    float xyz[3];
    std::memcpy(xyz, ply.data() + header + 11 + i * stride, sizeof xyz);
    EXPECT_LE(std::abs(xyz[2]), 0.1f + 2.0f / 32) << i;
    EXPECT_LE(std::abs(xyz[0]), 1.0f);
  }
}

TEST(SetIteratesCli, BadInputExitsTwoWithOneSentenceAndWritesNothing) {
  DrawingDir dir("setiter-bad");
  writeText(dir.path / "missing.gridifs",
            R"({"format": "gridifs", "version": 1, "functions": [
                {"kind": "median", "set": {"image": "nowhere.png"}}]})");
  writeText(dir.path / "blank.gridifs",
            R"({"format": "gridifs", "version": 1, "functions": [
                {"kind": "median", "set": {"image": "comma.png", "threshold": 0}}]})");
  writeText(dir.path / "garbage.png", "not an image");
  writeText(dir.path / "garbage.gridifs",
            R"({"format": "gridifs", "version": 1, "functions": [
                {"kind": "median", "set": {"image": "garbage.png"}}]})");
  struct Case {
    std::string args, mentions;
  };
  const std::string out = dir.out("o.vdb"), pages = dir.out("o_%03d.vdb");
  for (const Case& c : {
           Case{"volume " + dir.project() + " --depth 13 --pages -o " + pages, "4096 pages"},
           Case{"volume " + dir.project() + " --depth 65 -o " + out, "--depth"},
           Case{"volume " + dir.project() + " --depth -1 -o " + out, "--depth"},
           Case{"volume " + dir.project() + " --depth 2 --pages -o " + out, "%"},
           Case{"volume " + dir.project() + " --pages -o " + pages, "--depth"},
           Case{"volume " + dir.project() + " --depth 2 --resolution 4 -o " + out, "--resolution"},
           Case{"volume " + dir.project() + " --depth 2 -o " + dir.out("o.txt"), "o.txt"},
           Case{"volume " + quote((dir.path / "missing.gridifs").string()) + " --depth 1 -o " + out, "nowhere.png"},
           Case{"volume " + quote((dir.path / "blank.gridifs").string()) + " --depth 1 -o " + out, "threshold"},
           Case{"volume " + quote((dir.path / "garbage.gridifs").string()) + " --depth 1 -o " + out, "garbage.png"},
           Case{"render " + quote((dir.path / "missing.gridifs").string()) + " -o " + dir.out("o.png"), "nowhere.png"},
       }) {
    SCOPED_TRACE(c.args);
    const CommandResult r = runGridifs(c.args + " -q");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(c.mentions), std::string::npos) << r.err;
    EXPECT_EQ(countFiles(dir.path, ".vdb"), 0u);
    EXPECT_FALSE(fs::exists(dir.path / "o.png"));
  }
}
