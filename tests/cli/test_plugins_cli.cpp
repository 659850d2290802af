// The image writer and OpenVDB are plugins (image_io/, vdb_io/): gridifs itself links neither
// OpenImageIO nor OpenVDB, so verbs that write no image or volume start without loading their
// libraries; a missing plugin is one sentence. Nor does the command line link the window's or the
// live inputs' libraries: the modeller is gridifs-modeller beside it, which gridifs execs.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
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

TEST(CommandLine, GridifsLinksNoWindowOrLiveInputLibrary) {
  const std::string dynamic = dynamicSection("command-line-needed");
  for (const char* library : {"libglfw", "libSDL2", "librtmidi", "liblo.so", "libX11"})
    EXPECT_EQ(dynamic.find(library), std::string::npos)
        << "gridifs links " << library << " again: every image the plugin loads pays for a longer symbol scope";
}

TEST(CommandLine, OpeningAWindowWithoutTheModellerBesideItIsOneSentence) {
  ScratchDir dir("command-line-alone");
  const fs::path alone = dir.path / "gridifs";
  fs::copy_file(GRIDIFS_EXE, alone);
  const std::string err = (dir.path / "err.txt").string();
  const std::string command =
      quote(alone.string()) + " " + quote(asset("default.gridifs")) + " < /dev/null > /dev/null 2> " + quote(err);
  const int status = std::system(command.c_str());
  const std::string text = test_support::slurp(err);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) != 0) << text;
  EXPECT_NE(text.find("modeller window"), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
}

TEST(CommandLine, TheModellersFarmJobsRunTheCommandLine) {
  const fs::path commandLine = fs::canonical(GRIDIFS_EXE);
  const fs::path modeller = commandLine.parent_path() / "gridifs-modeller";
  if (!fs::exists(modeller)) GTEST_SKIP() << "a build without the modeller";
  ScratchDir dir("command-line-farm");
  const fs::path job = dir.path / "job";
  const std::string command = quote(modeller.string()) + " farm " + quote(asset("sierpinski_tetrahedron.gridifs")) +
                              " --parts 2 --dir " + quote(job.string()) + " -o " +
                              quote((dir.path / "out.png").string()) + " > /dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  std::ifstream in(job / "farm.json");
  const nlohmann::json written = nlohmann::json::parse(in, nullptr, false);
  ASSERT_TRUE(written.is_object() && written.contains("executable"));
  EXPECT_EQ(fs::path(written["executable"].get<std::string>()), commandLine)
      << "the batch scripts would load the window's libraries for every part";
}

}  // namespace
}  // namespace gridifs
