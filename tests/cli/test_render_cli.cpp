// gridifs render / export-points on real files: outputs, determinism, bad input.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstring>
#include <set>

#include "base/system_memory.h"
#include "io/project_io.h"
#include "render/chaos_renderer.h"
#include "tests/cli/image_file_read.h"
#include "tests/cli/run_command.h"
#include "tests/core/renderer_scenes.h"

namespace gridifs {
namespace {

using namespace test_support;
namespace fs = std::filesystem;

/// Parses a binary little-endian PLY with x y z float + red green blue uchar.
std::vector<Vec3> readPly(const fs::path& file, std::vector<std::array<unsigned char, 3>>* colors = nullptr) {
  const std::string data = test_support::slurp(file);
  const std::size_t end = data.find("end_header\n");
  EXPECT_NE(end, std::string::npos);
  const std::string header = data.substr(0, end);
  EXPECT_NE(header.find("format binary_little_endian 1.0"), std::string::npos);
  const std::size_t at = header.find("element vertex ");
  const std::size_t count = std::stoull(header.substr(at + 15));
  const std::size_t body = end + 11;
  EXPECT_EQ(data.size() - body, count * 15);
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < count && body + 15 * (i + 1) <= data.size(); ++i) {
    float xyz[3];
    std::memcpy(xyz, data.data() + body + 15 * i, 12);
    points.emplace_back(xyz[0], xyz[1], xyz[2]);
    if (colors) {
      std::array<unsigned char, 3> c;
      std::memcpy(c.data(), data.data() + body + 15 * i + 12, 3);
      colors->push_back(c);
    }
  }
  return points;
}

fs::path writeProject(const ScratchDir& dir, const std::string& name, const Project& project) {
  const fs::path file = dir.path / name;
  saveProject(project, file);
  return file;
}

std::size_t filesIn(const fs::path& dir) {
  return std::size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

TEST(RenderCli, WritesPngTiffAndExrWithDepth) {
  ScratchDir dir("render-formats");
  const fs::path project = writeProject(dir, "sierpinski.gridifs", test::sierpinskiTetrahedron());
  for (const char* ext : {"png", "tif", "exr"}) {
    SCOPED_TRACE(ext);
    const fs::path out = dir.path / (std::string("out.") + ext);
    const auto r = runGridifs("render " + quote(project.string()) + " -o " + quote(out.string()) +
                              " --width 96 --height 72 --samples 100000 --threads 2 --device cpu");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "") << "no progress bar when stderr is not a terminal";
    const ImageFile image = readImageFile(out);
    ASSERT_EQ(image.width, 96);
    ASSERT_EQ(image.height, 72);
    int lit = 0;
    for (std::size_t i = 0; i < image.pixels.size(); i += image.channels) lit += image.pixels[i] > 0.05f;
    EXPECT_GT(lit, 300);
    if (std::string(ext) == "exr") {
      ASSERT_EQ(image.channels, 8);  // R G B A Z and the world position P
      EXPECT_EQ(image.names[4], "Z");
      float minZ = 1e30f, maxZ = 0;
      for (std::size_t i = 0; i < image.pixels.size(); i += 8)
        if (image.pixels[i + 3] > 0) {
          minZ = std::min(minZ, image.pixels[i + 4]);
          maxZ = std::max(maxZ, image.pixels[i + 4]);
        }
      // The tetrahedron lies within √3 of the target, 4.5 from the eye.
      EXPECT_GT(minZ, 4.5f - 1.74f);
      EXPECT_LT(maxZ, 4.5f + 1.74f);
      EXPECT_LT(minZ, maxZ);
    } else {
      EXPECT_EQ(image.channels, 3);
    }
  }
  EXPECT_EQ(filesIn(dir.path), 4u) << "no temporary files left behind";
}

TEST(RenderCli, SameSeedSamePixelsOtherSeedDiffers) {
  ScratchDir dir("render-determinism");
  const fs::path project = writeProject(dir, "s.gridifs", test::sierpinskiTetrahedron());
  auto render = [&](const std::string& name, int seed) {
    const fs::path out = dir.path / name;
    const auto r = runGridifs("render " + quote(project.string()) + " -o " + quote(out.string()) +
                              " --width 80 --height 60 --samples 50000 --threads 2 --seed " + std::to_string(seed));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return readImageFile(out).pixels;
  };
  const auto a = render("a.png", 3), b = render("b.png", 3), c = render("c.png", 4);
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
}

TEST(ExportPointsCli, SierpinskiPointsLieOnTheAttractor) {
  ScratchDir dir("export-points");
  const fs::path project = writeProject(dir, "s.gridifs", test::sierpinskiTetrahedron());
  const fs::path out = dir.path / "points.ply";
  const auto r = runGridifs("export-points " + quote(project.string()) + " -o " + quote(out.string()) +
                            " --samples 200000 --threads 3");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::vector<std::array<unsigned char, 3>> colors;
  const auto points = readPly(out, &colors);
  ASSERT_GT(points.size(), 190'000u);
  std::set<int> addresses;
  std::size_t off = 0;
  for (const Vec3& p : points) {
    off += !test::inSierpinski(p, 7, 1e-3);
    addresses.insert(test::sierpinskiAddress(p, 5, 1e-3));
  }
  EXPECT_EQ(off, 0u);
  addresses.erase(-1);
  EXPECT_EQ(addresses.size(), 1024u);
  std::set<std::array<unsigned char, 3>> distinct(colors.begin(), colors.end());
  EXPECT_GT(distinct.size(), 50u) << "structural colours blend the function colours";
  // Same options → identical bytes.
  const fs::path again = dir.path / "again.ply";
  ASSERT_EQ(runGridifs("export-points " + quote(project.string()) + " -o " + quote(again.string()) +
                       " --samples 200000 --threads 3")
                .exitCode,
            0);
  EXPECT_EQ(test_support::slurp(out), test_support::slurp(again));
}

TEST(RenderCli, BadInputIsRefusedWithOneSentenceAndNoFile) {
  ScratchDir dir("render-bad");
  const fs::path project = writeProject(dir, "s.gridifs", test::sierpinskiTetrahedron());
  const std::string p = quote(project.string());
  const std::string out = quote((dir.path / "out.png").string());
  struct Case {
    std::string args;
    int code;
    std::string mentions;
  };
  const std::vector<Case> cases = {
      {"render " + p + " -o " + out + " --samples 0", 2, "--samples"},
      {"render " + p + " -o " + out + " --samples 1e12", 2, "limit"},
      {"render " + p + " -o " + out + " --samples lots", 2, "--samples"},
      {"render " + p + " -o " + out + " --width 0", 2, "s.gridifs"},
      {"render " + p + " -o " + out + " --width 16384 --height 16384", 2, "megapixels"},
      {"render " + p + " -o " + out + " --threads 0", 2, "--threads"},
      {"render " + p + " -o " + quote((dir.path / "out.jpg").string()), 2, "out.jpg"},
      {"render " + p + " -o " + quote((dir.path / "missing" / "out.png").string()), 2, "does not exist"},
      {"render " + p + " -o /proc/gridifs-test.png", 1, "/proc/gridifs-test.png"},
      {"render " + quote((dir.path / "nope.gridifs").string()) + " -o " + out, 2, "nope.gridifs"},
      {"export-points " + p + " -o " + quote((dir.path / "p.ply").string()) + " --samples 0", 2, "--samples"},
      {"export-points " + p + " -o " + quote((dir.path / "p.obj").string()), 2, "p.obj"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args);
    const auto r = runGridifs(c.args);
    EXPECT_EQ(r.exitCode, c.code) << r.err;
    EXPECT_NE(r.err.find(c.mentions), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_EQ(filesIn(dir.path), 1u) << "only the project file: nothing half-written";
}

TEST(RenderCli, NonFiniteCalculatorIsBadInputAndExpandingIfsStillRenders) {
  ScratchDir dir("render-odd");
  Project nan = test::sierpinskiTetrahedron();
  CalculatorOp calc;
  calc.x = calc.y = calc.z = "sqrt(-1)";
  Operation op;
  op.params = calc;
  nan.functions[1].ops.push_back(op);
  const fs::path nanFile = writeProject(dir, "nan.gridifs", nan);
  auto r = runGridifs("render " + quote(nanFile.string()) + " -o " + quote((dir.path / "nan.png").string()));
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("nan.gridifs"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path / "nan.png"));

  Project expanding = test::sierpinskiTetrahedron();
  expanding.functions[0].placement.scale = Vec3{1.5};
  const fs::path expFile = writeProject(dir, "expanding.gridifs", expanding);
  r = runGridifs("render " + quote(expFile.string()) + " -o " + quote((dir.path / "exp.png").string()) +
                 " --samples 20000 --width 64 --height 48");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("may not be contractive"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir.path / "exp.png"));
}

// A render whose buffers would not fit the free memory is refused before it allocates, with a
// sentence that says how much it needs.
TEST(RenderCli, ARenderThatDoesNotFitInMemoryIsRefusedUpFront) {
  RenderJob job;
  job.width = job.height = 8192;
  job.threads = 64;
  const auto available = availableMemoryBytes();
  if (!available || *available >= renderBufferBytes(job))
    GTEST_SKIP() << "this machine has room for a 64-thread 8192² render";
  ScratchDir dir("render-memory");
  const fs::path project = writeProject(dir, "s.gridifs", test::sierpinskiTetrahedron());
  const fs::path out = dir.path / "out.png";
  const auto r = runGridifs("render " + quote(project.string()) + " -o " + quote(out.string()) +
                            " --width 8192 --height 8192 --threads 64 --device cpu");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("needs about"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("GiB"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace gridifs
