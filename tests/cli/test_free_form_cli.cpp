// `gridifs free-form` on real files: presets of a degree, F̂ of a grid project onto a flat or
// paraboloid control net, and bad input (a degree out of range, a project that already has
// control points, matrices that are not stochastic or not of the space's size) exits 2 with one
// sentence naming the option or JSON path, writing nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "io/project_io.h"
#include "run_command.h"

using namespace gridifs;
using namespace gridifs::test_support;
namespace fs = std::filesystem;

namespace {

fs::path tempDir() {
  const fs::path dir = fs::temp_directory_path() / ("gridifs-free-form-cli-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

const std::string kGasket = std::string(GRIDIFS_ASSETS) + "/freeform/sierpinski_gasket_grid.gridifs";

void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

}  // namespace

TEST(FreeFormCli, PresetsOfADegree) {
  const fs::path dir = tempDir();
  for (const std::string name : {"bezier-curve", "bspline-curve", "bezier-patch", "bspline-patch"}) {
    const fs::path out = dir / (name + ".gridifs");
    const CommandResult r = runGridifs("free-form -o " + quote(out.string()) + " --preset " + name + " --degree 5");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Project p = loadProject(out);
    const bool patch = name.find("patch") != std::string::npos;
    EXPECT_EQ(p.space->control_points.size(), patch ? 36u : 6u) << name;
  }
}

TEST(FreeFormCli, MapsAGridProjectOntoAParaboloid) {
  const fs::path dir = tempDir();
  const fs::path out = dir / "lifted.gridifs";
  const CommandResult r = runGridifs("free-form -o " + quote(out.string()) + " --from " + quote(kGasket) +
                                     " --net hyperbolic-paraboloid --height 0.4");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Project p = loadProject(out);
  ASSERT_TRUE(p.space.has_value());
  EXPECT_EQ(p.space->control_points.size(), 6u);  // a quadratic triangle
  EXPECT_EQ(p.functions.size(), 3u);
  const CommandResult info = runGridifs("info " + quote(out.string()));
  EXPECT_EQ(info.exitCode, 0) << info.err;
}

TEST(FreeFormCli, BadInputExitsTwoAndWritesNothing) {
  const fs::path dir = tempDir();
  const fs::path out = dir / "never.gridifs";
  fs::remove(out);
  auto expectBad = [&](const std::string& args, const std::string& needle) {
    const CommandResult r = runGridifs(args);
    EXPECT_EQ(r.exitCode, 2) << args;
    EXPECT_NE(r.err.find(needle), std::string::npos) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(out)) << args;
  };
  const std::string o = "free-form -o " + quote(out.string());
  expectBad(o + " --preset bezier-curve --degree 8", "--degree");
  expectBad(o + " --preset bezier-curve --degree 0", "--degree");
  expectBad(o + " --preset bezier-curve --split 1.5", "--split");
  expectBad(o + " --preset teapot", "--preset");
  expectBad(o + " --preset bspline-curve --roughness 0.3", "--roughness");
  expectBad(o + " --from " + quote(kGasket) + " --degree 9", "--degree");
  expectBad(o + " --from " + quote(kGasket) + " --net cone", "--net");
  expectBad(o, "exactly one of");
  // A project that already has control points.
  const fs::path curve = dir / "curve.gridifs";
  ASSERT_EQ(runGridifs("free-form -o " + quote(curve.string()) + " --preset bezier-curve").exitCode, 0);
  expectBad(o + " --from " + quote(curve.string()), "space");

  // Matrices: a row that does not sum to 1, a matrix of the wrong size.
  const std::string head =
      R"({"format": "gridifs", "version": 1, "space": {"control_points": [[0,0,0],[1,0,0],[1,1,0]]}, "functions": [)";
  const fs::path rows = dir / "rows.gridifs", size = dir / "size.gridifs";
  write(rows, head + R"({"name": "a", "kind": "matrix", "matrix": [[1,0,0],[0.5,0.6,0],[0,0,1]]}]})");
  write(size, head + R"({"name": "a", "kind": "matrix", "matrix": [[1,0],[0,1]]}]})");
  for (const auto& [file, path] : {std::pair{rows, "functions[0].matrix[1]"}, std::pair{size, "functions[0].matrix"}}) {
    const CommandResult r = runGridifs("info " + quote(file.string()));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
    const CommandResult m = runGridifs(o + " --from " + quote(file.string()));
    EXPECT_EQ(m.exitCode, 2);
    EXPECT_NE(m.err.find(path), std::string::npos) << m.err;
    EXPECT_FALSE(fs::exists(out));
  }
}
