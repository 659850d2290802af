// The image writer and OpenVDB are plugins (image_io/, vdb_io/): gridifs itself links neither
// OpenImageIO nor OpenVDB, so verbs that write no image or volume start without loading their
// libraries; a missing plugin is one sentence.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "tests/cli/example_projects.h"
#include "tests/cli/run_command.h"

namespace gridifs {
namespace {

using namespace test_support;
namespace fs = std::filesystem;

/// gridifs's dynamic section (objdump -p), for its NEEDED libraries.
std::string dynamicSection(const std::string& scratchName) {
  ScratchDir dir(scratchName);
  const fs::path listing = dir.path / "dynamic.txt";
  EXPECT_EQ(std::system(("objdump -p " + quote(GRIDIFS_EXE) + " > " + quote(listing.string())).c_str()), 0);
  const std::string text = test_support::slurp(listing.string());
  EXPECT_NE(text.find("NEEDED"), std::string::npos) << "objdump listed no dynamic section";
  return text;
}

/// Runs `verb INPUT -o OUT options` with `variable` naming a plugin that does not exist: one
/// sentence, exit 1, nothing written (not even a temporary file).
void expectMissingPluginFails(const std::string& verb, const std::string& input, const std::string& output,
                              const std::string& options, const std::string& variable) {
  ScratchDir dir("plugin-missing-" + verb);
  const fs::path out = dir.path / output;
  const auto r = runGridifs(verb + " " + quote(input) + " -o " + quote(out.string()) + " " + options, "",
                            variable + "=" + quote((dir.path / "libmissing.so").string()));
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("could not be loaded"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(fs::is_empty(dir.path)) << "no temporary file is left behind";
}

TEST(ImagePlugin, GridifsDoesNotLinkOpenImageIO) {
  EXPECT_EQ(dynamicSection("image-plugin-needed").find("libOpenImageIO"), std::string::npos)
      << "gridifs links OpenImageIO again: every start pays for loading it";
}

TEST(ImagePlugin, ImagesAreWrittenThroughThePlugin) {
  ScratchDir dir("image-plugin-write");
  for (const char* ext : {"png", "exr", "tif"}) {
    const fs::path out = dir.path / (std::string("out.") + ext);
    const auto r = runGridifs("render " + quote(asset("sierpinski_tetrahedron.gridifs")) + " -o " +
                              quote(out.string()) + " --width 64 --height 48 --samples 20000 --device cpu -q");
    EXPECT_EQ(r.exitCode, 0) << ext << ": " << r.err;
    EXPECT_GT(fs::exists(out) ? fs::file_size(out) : 0u, 100u) << ext;
  }
}

TEST(ImagePlugin, AMissingPluginIsOneSentenceAndWritesNothing) {
  expectMissingPluginFails("render", asset("sierpinski_tetrahedron.gridifs"), "out.png",
                           "--width 64 --height 48 --samples 20000 --device cpu -q", "GRIDIFS_IMAGE_IO");
}

TEST(VdbPlugin, GridifsDoesNotLinkOpenVdb) {
  EXPECT_EQ(dynamicSection("vdb-plugin-needed").find("libopenvdb"), std::string::npos)
      << "gridifs links OpenVDB again: every start pays for loading it";
}

TEST(VdbPlugin, AMissingPluginIsOneSentenceAndWritesNothing) {
  expectMissingPluginFails("volume", asset("volumes/two_sets.gridifs"), "out.vdb", "--resolution 16 --device cpu -q",
                           "GRIDIFS_VDB_IO");
}

}  // namespace
}  // namespace gridifs
