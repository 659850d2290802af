// Projects with a construction tree on the command line: the figure 4.2 example renders, and a
// bad tree (unknown operation, missing leaf file, a cycle, the wrong number of operands) exits 2
// with one sentence naming the JSON path, writing nothing.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <fstream>

#include "io/project_io.h"
#include "run_command.h"

using namespace gridifs;
using namespace gridifs::test_support;
namespace fs = std::filesystem;

namespace {

const fs::path kExample = fs::path(GRIDIFS_ASSETS) / "matrices" / "construction_tree.gridifs";

}  // namespace

TEST(ConstructionCli, FigureExampleRendersItsTree) {
  ScratchDir dir("construction-render");
  const fs::path out = dir.path / "tree.png";
  const CommandResult r = runGridifs("render " + quote(kExample.string()) + " -o " + quote(out.string()) +
                                     " --samples 400000 --width 200 --height 200 --device cpu");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  OIIO::ImageBuf image(out.string());
  const auto stats = OIIO::ImageBufAlgo::computePixelStats(image);
  ASSERT_GE(stats.max.size(), 3u);
  EXPECT_GT(stats.max[0] + stats.max[1] + stats.max[2], 0.5f);  // the attractor was drawn
}

TEST(ConstructionCli, BadTreesExitTwoNamingTheJsonPath) {
  ScratchDir dir("construction-bad");
  saveProject(loadProject(fs::path(GRIDIFS_ASSETS) / "sierpinski_tetrahedron.gridifs"), dir.path / "leaf.gridifs");
  const std::string head = R"({"format": "gridifs", "version": 1, "functions": [{"name": "f"}], "construction": )";
  const struct {
    const char* name;
    std::string construction, path;
  } cases[] = {
      {"op", R"({"root": {"op": "blend", "children": [{"file": "leaf.gridifs"}, {"file": "leaf.gridifs"}]}})",
       "construction.root.op: unknown operation \"blend\""},
      {"missing", R"({"root": {"op": "union", "children": [{"file": "leaf.gridifs"}, {"file": "none.gridifs"}]}})",
       "construction.root.children[1].file: the leaf file"},
      {"cycle", R"({"root": {"op": "union", "children": [{"file": "leaf.gridifs"}, {"file": "cycle.gridifs"}]}})",
       "construction.root.children[1].file: the leaf cycle.gridifs leads back"},
      {"arity", R"({"root": {"op": "concat", "children": [{"file": "leaf.gridifs"}]}})",
       "construction.root.children: concat takes 2 operands, not 1"},
  };
  for (const auto& c : cases) {
    const fs::path project = dir.path / (std::string(c.name) + ".gridifs");
    writeText(project, head + c.construction + "}");
    const fs::path out = dir.path / (std::string(c.name) + ".png");
    const CommandResult r = runGridifs("render " + quote(project.string()) + " -o " + quote(out.string()) +
                                       " --samples 1000 --width 16 --height 16 --device cpu");
    EXPECT_EQ(r.exitCode, 2) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.path), std::string::npos) << c.name << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.name << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.name;
  }
}
