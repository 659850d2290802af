// Split renders on the command line (docs/FARM.md): an image or volume depends on the project and
// its options, never on --threads or on how the work is split. `render --part K/N` and
// `volume --part K/N` write a part's accumulation, `merge` sums all N parts in any order into the
// very file the whole render writes, byte for byte, and refuses a missing, duplicated, truncated,
// damaged or foreign part with exit 2 and one sentence, writing nothing. A killed part writer
// leaves no file under the target's name.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "io/render_part_file.h"
#include "tests/cli/example_projects.h"
#include "tests/cli/run_command.h"

namespace gridifs {
namespace {

using namespace test_support;
namespace fs = std::filesystem;

const std::string kShaded = asset("shaded_tetrahedron.gridifs");  // render.mode "shaded", shadows

/// What is rendered: a project, the output's extension and the options beyond the common ones
/// (small size, 10^6 samples: 16 chunks, --device cpu).
struct Mode {
  std::string name, project, ext;
  std::string options;  // render options that shape the accumulation (parts get them too)
  std::string finish;   // finishing options: given to the whole render and to merge, not to parts
  bool volume = false;  // `gridifs volume` instead of `gridifs render`
  bool frames = false;  // --frames 0:1: -o is a pattern, one file (or part) per frame
  std::string samples = "1e6";
};

/// An image mode of `gridifs render`.
Mode imageMode(const std::string& name, const std::string& project, const std::string& ext, const std::string& options,
               const std::string& finish = "") {
  Mode m;
  m.name = name;
  m.project = project;
  m.ext = ext;
  m.options = options;
  m.finish = finish;
  return m;
}

const Mode kZBufferPng = imageMode("zbuffer-png", kTwisted, "png", "--mode zbuffer");
const Mode kZBufferExr = imageMode("zbuffer-exr", kTwisted, "exr", "--mode zbuffer");
const Mode kFlamePng = imageMode("flame-png", kTwisted, "png", "--mode flame");
const Mode kFlame16 = imageMode("flame-png16", kTwisted, "png", "--mode flame", "--bit-depth 16");
const Mode kFlameTif = imageMode("flame-tif", kTwisted, "tif", "--mode flame");
const Mode kFlameExr = imageMode("flame-exr", kTwisted, "exr", "--mode flame");
const Mode kFlameTransparent = imageMode("flame-transparent", kTwisted, "png", "--mode flame", "--transparent");
const Mode kFlamePalette = imageMode("flame-palette", kTwisted, "png", "--mode flame --palette aurora");
const Mode kShadedPng = imageMode("shaded-png", kShaded, "png", "--mode shaded");
const Mode kShadedExr = imageMode("shaded-exr", kShaded, "exr", "--mode shaded");
const Mode kMotionBlur = imageMode("blur", kAnimated, "png", "--motion-blur 3 --time 0.5");
const Mode kFlameMotionBlur = imageMode("flame-blur", kAnimated, "png", "--motion-blur 3 --time 0.5 --mode flame");
const Mode kFrames = [] {
  Mode m = imageMode("frames", kAnimated, "png", "");
  m.frames = true;
  return m;
}();
const Mode kVolume = [] {
  Mode m;
  m.name = "volume";
  m.project = kPineTrees;
  m.ext = "vdb";
  m.options = "--resolution 32";
  m.volume = true;
  return m;
}();

/// The command line of `mode` writing `out`, with `extra` (--threads, --part) appended.
std::string commandOf(const Mode& mode, const fs::path& out, const std::string& extra) {
  const std::string common = mode.volume ? " --samples " + mode.samples + " --device cpu -q "
                                         : " --width 160 --height 120 --samples " + mode.samples + " --device cpu -q ";
  return std::string(mode.volume ? "volume " : "render ") + quote(mode.project) + " -o " + quote(out.string()) +
         common + mode.options + (mode.frames ? " --frames 0:1 " : " ") + extra;
}

/// The output files of a run writing `out` (a pattern with --frames).
std::vector<fs::path> outputsOf(const Mode& mode, const fs::path& out) {
  if (!mode.frames) return {out};
  std::vector<fs::path> files;
  for (int f = 0; f <= 1; ++f) {
    char name[256];
    std::snprintf(name, sizeof name, out.filename().string().c_str(), f);
    files.push_back(out.parent_path() / name);
  }
  return files;
}

/// Runs gridifs and reports a failure (with its stderr) when it does not exit 0.
bool succeeds(const std::string& args) {
  const CommandResult r = runGridifs(args);
  if (r.exitCode == 0) return true;
  ADD_FAILURE() << "gridifs " << args << "\nexited " << r.exitCode << ": " << r.err;
  return false;
}

/// The two files hold the same bytes (on failure: the sizes and the first differing offset).
void expectSameBytes(const fs::path& expected, const fs::path& actual) {
  const std::string a = slurp(expected), b = slurp(actual);
  ASSERT_FALSE(a.empty()) << expected << " is missing or empty";
  if (a == b) return;
  std::size_t at = 0;
  while (at < a.size() && at < b.size() && a[at] == b[at]) ++at;
  ADD_FAILURE() << actual << " differs from " << expected << ": " << b.size() << " and " << a.size()
                << " bytes, first difference at byte " << at;
}

std::set<std::string> entriesOf(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(folder)) names.insert(e.path().filename().string());
  return names;
}

// ---------------------------------------------------------------------------------------------
// The same bytes for any thread count.

void expectThreadIndependent(const Mode& mode) {
  ScratchDir dir("parts-threads-" + mode.name);
  std::vector<std::vector<fs::path>> outputs;
  for (int threads : {1, 2, 3}) {
    const fs::path out = dir.path / ("t" + std::to_string(threads) + (mode.frames ? "_%02d." : ".") + mode.ext);
    ASSERT_TRUE(succeeds(commandOf(mode, out, mode.finish + " --threads " + std::to_string(threads))));
    outputs.push_back(outputsOf(mode, out));
  }
  for (std::size_t t = 1; t < outputs.size(); ++t)
    for (std::size_t f = 0; f < outputs[0].size(); ++f) {
      SCOPED_TRACE(outputs[t][f].filename().string());
      expectSameBytes(outputs[0][f], outputs[t][f]);
    }
  if (mode.frames) {
    EXPECT_NE(slurp(outputs[0][0]), slurp(outputs[0][1])) << "the two frames of an animation differ";
  }
}

TEST(RenderThreads, ZBufferPngIsTheSameForOneTwoAndThreeThreads) { expectThreadIndependent(kZBufferPng); }
TEST(RenderThreads, ZBufferExrIsTheSameForOneTwoAndThreeThreads) { expectThreadIndependent(kZBufferExr); }
TEST(RenderThreads, FlameIsTheSameForOneTwoAndThreeThreads) { expectThreadIndependent(kFlamePng); }
TEST(RenderThreads, FlameTiffIsTheSameForOneTwoAndThreeThreads) { expectThreadIndependent(kFlameTif); }
TEST(RenderThreads, ShadedIsTheSameForOneTwoAndThreeThreads) { expectThreadIndependent(kShadedPng); }
TEST(RenderThreads, ShadedExrIsTheSameForOneTwoAndThreeThreads) { expectThreadIndependent(kShadedExr); }
TEST(RenderThreads, MotionBlurIsTheSameForOneTwoAndThreeThreads) { expectThreadIndependent(kMotionBlur); }
TEST(RenderThreads, FramesAreTheSameForOneTwoAndThreeThreads) { expectThreadIndependent(kFrames); }
TEST(RenderThreads, VolumeIsTheSameForOneTwoAndThreeThreads) { expectThreadIndependent(kVolume); }

// The file does not depend on when it was written either: EXR and TIFF carry no date of writing
// (OpenImageIO stamps one unless told otherwise), a VDB no random UUID (OpenVDB writes one). A
// merge runs long after its parts were rendered, and its file must still be the render's.
TEST(RenderThreads, TheSameRenderASecondLaterIsTheSameFile) {
  ScratchDir dir("parts-later");
  for (const Mode& mode : {kZBufferExr, kFlameTif, kVolume}) {
    SCOPED_TRACE(mode.name);
    const fs::path first = dir.path / ("first." + mode.ext), second = dir.path / ("second." + mode.ext);
    ASSERT_TRUE(succeeds(commandOf(mode, first, "--threads 2")));
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));  // another second on the clock
    ASSERT_TRUE(succeeds(commandOf(mode, second, "--threads 2")));
    expectSameBytes(first, second);
  }
}

// ---------------------------------------------------------------------------------------------
// Parts merge into the whole render.

/// Renders `mode` whole (2 threads) and in N = 1, 3 and 7 parts (threads 1–3 by part), merges
/// each split with the parts in a shuffled order, and compares the bytes with the whole render.
void expectPartsMergeIntoTheWhole(const Mode& mode, std::vector<int> splits = {1, 3, 7}) {
  ScratchDir dir("parts-merge-" + mode.name);
  const fs::path whole = dir.path / (std::string(mode.frames ? "whole_%02d." : "whole.") + mode.ext);
  ASSERT_TRUE(succeeds(commandOf(mode, whole, mode.finish + " --threads 2")));
  const std::vector<fs::path> wholeFiles = outputsOf(mode, whole);
  std::mt19937 rng(std::uint32_t(splits.size() * 7919 + mode.name.size()));
  for (int n : splits) {
    SCOPED_TRACE("N = " + std::to_string(n));
    // parts[f][k]: frame f's part k.
    std::vector<std::vector<fs::path>> parts(wholeFiles.size());
    for (int k = 0; k < n; ++k) {
      const std::string stem = "n" + std::to_string(n) + (mode.frames ? "_%02d_" : "_") + std::to_string(k) + ".gpart";
      const fs::path out = dir.path / stem;
      ASSERT_TRUE(succeeds(commandOf(
          mode, out,
          "--part " + std::to_string(k) + "/" + std::to_string(n) + " --threads " + std::to_string(1 + k % 3))));
      const std::vector<fs::path> files = outputsOf(mode, out);
      for (std::size_t f = 0; f < files.size(); ++f) {
        ASSERT_TRUE(fs::exists(files[f])) << files[f];
        parts[f].push_back(files[f]);
      }
    }
    for (std::size_t f = 0; f < wholeFiles.size(); ++f) {
      std::shuffle(parts[f].begin(), parts[f].end(), rng);
      std::string args = "merge";
      for (const fs::path& p : parts[f]) args += " " + quote(p.string());
      const fs::path merged = dir.path / ("merged_n" + std::to_string(n) + "_f" + std::to_string(f) + "." + mode.ext);
      ASSERT_TRUE(succeeds(args + " -o " + quote(merged.string()) + " " + mode.finish));
      SCOPED_TRACE(merged.filename().string());
      expectSameBytes(wholeFiles[f], merged);
    }
  }
}

TEST(RenderPartsMerge, ZBufferPng) { expectPartsMergeIntoTheWhole(kZBufferPng); }
TEST(RenderPartsMerge, ZBufferExr) { expectPartsMergeIntoTheWhole(kZBufferExr); }
TEST(RenderPartsMerge, FlamePng) { expectPartsMergeIntoTheWhole(kFlamePng); }
TEST(RenderPartsMerge, FlamePng16Bit) { expectPartsMergeIntoTheWhole(kFlame16); }
TEST(RenderPartsMerge, FlameTiff) { expectPartsMergeIntoTheWhole(kFlameTif, {3}); }
TEST(RenderPartsMerge, FlameExr) { expectPartsMergeIntoTheWhole(kFlameExr, {3}); }
TEST(RenderPartsMerge, FlameTransparent) { expectPartsMergeIntoTheWhole(kFlameTransparent, {3}); }
TEST(RenderPartsMerge, FlameWithAnotherPalette) { expectPartsMergeIntoTheWhole(kFlamePalette, {3}); }
TEST(RenderPartsMerge, ShadedPng) { expectPartsMergeIntoTheWhole(kShadedPng); }
TEST(RenderPartsMerge, ShadedExr) { expectPartsMergeIntoTheWhole(kShadedExr, {3}); }
TEST(RenderPartsMerge, MotionBlur) { expectPartsMergeIntoTheWhole(kMotionBlur); }
TEST(RenderPartsMerge, FlameMotionBlur) { expectPartsMergeIntoTheWhole(kFlameMotionBlur, {3}); }
TEST(RenderPartsMerge, FramesOnePartFilePerFrame) { expectPartsMergeIntoTheWhole(kFrames); }
TEST(RenderPartsMerge, Volume) { expectPartsMergeIntoTheWhole(kVolume); }

// 10^5 samples are 2 chunks: of 3 or 7 parts, most get no chunk at all. Such a part is still a
// valid part (it adds nothing), and the merge is still the whole render.
TEST(RenderPartsMerge, MorePartsThanChunks) {
  Mode zbuffer = kZBufferPng;
  zbuffer.name = "zbuffer-few-chunks";
  zbuffer.samples = "1e5";
  expectPartsMergeIntoTheWhole(zbuffer, {3, 7});
  Mode volume = kVolume;
  volume.name = "volume-few-chunks";
  volume.samples = "1e5";
  expectPartsMergeIntoTheWhole(volume, {3});
}

// ---------------------------------------------------------------------------------------------
// Refusals: exit 2, one line naming the offending file(s), nothing written.

class MergeRefusals : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<ScratchDir>("parts-refusals");
    auto render = [](const std::string& project, const std::string& part, const std::string& name,
                     const std::string& extra = "--width 160") {
      const fs::path out = dir_->path / name;
      succeeds("render " + quote(project) + " -o " + quote(out.string()) +
               " --height 120 --samples 1e6 --device cpu -q --threads 2 --part " + part + " " + extra);
      return out;
    };
    for (int k = 0; k < 3; ++k)
      parts_.push_back(render(kTwisted, std::to_string(k) + "/3", "p" + std::to_string(k) + ".gpart"));
    otherSeed_ = render(kTwisted, "1/3", "other_seed.gpart", "--width 160 --seed 7");
    otherProject_ = render(kSierpinski, "1/3", "other_project.gpart");
    otherCount_ = render(kTwisted, "1/4", "other_count.gpart");
    otherSize_ = render(kTwisted, "1/3", "other_size.gpart", "--width 161");
    const fs::path volumePart = dir_->path / "volume.gpart";
    succeeds("volume " + quote(kPineTrees) + " -o " + quote(volumePart.string()) +
             " --resolution 32 --samples 1e6 --device cpu -q --part 1/3");
    volumePart_ = volumePart;
  }
  static void TearDownTestSuite() {
    parts_.clear();
    dir_.reset();
  }

  /// A copy of `part` named `name`, with `edit` applied to its bytes.
  static fs::path editedCopy(const fs::path& part, const std::string& name,
                             const std::function<void(std::string&)>& edit) {
    std::string bytes = slurp(part);
    edit(bytes);
    const fs::path out = dir_->path / name;
    std::ofstream(out, std::ios::binary | std::ios::trunc) << bytes;
    return out;
  }

  /// Where a part file's compressed payload starts and ends (render_part_file.h: "GRIDPART",
  /// version, header length, header, its CRC; ...; stream length, CRC, "PARTEND\n").
  static std::pair<std::size_t, std::size_t> payloadOf(const std::string& bytes) {
    std::uint32_t headerLength = 0;
    std::memcpy(&headerLength, bytes.data() + 12, 4);
    return {16 + std::size_t(headerLength) + 4, bytes.size() - 20};
  }

  /// `merge PARTS -o OUT` is refused: exit 2, one line naming each of `named`, no output and no
  /// other new file in the folder; and an existing output is left as it was.
  static void expectRefused(const std::vector<fs::path>& given, const std::vector<std::string>& named,
                            const std::string& ext = "png") {
    std::string args = "merge";
    for (const fs::path& p : given) args += " " + quote(p.string());
    const fs::path out = dir_->path / ("merged." + ext);
    const std::set<std::string> before = entriesOf(dir_->path);
    const CommandResult r = runGridifs(args + " -o " + quote(out.string()));
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
    EXPECT_TRUE(!r.err.empty() && r.err.back() == '\n') << r.err;
    for (const std::string& name : named)
      EXPECT_NE(r.err.find(name), std::string::npos) << "names " << name << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << "a refused merge wrote " << out;
    EXPECT_EQ(entriesOf(dir_->path), before) << "a refused merge left a file behind";
    const std::string previous = "the previous image, which a refused merge leaves alone\n";
    std::ofstream(out, std::ios::binary | std::ios::trunc) << previous;
    EXPECT_EQ(runGridifs(args + " -o " + quote(out.string())).exitCode, 2);
    EXPECT_EQ(slurp(out), previous) << "a refused merge changed the existing output";
    fs::remove(out);
  }

  static std::unique_ptr<ScratchDir> dir_;
  static std::vector<fs::path> parts_;
  static fs::path otherSeed_, otherProject_, otherCount_, otherSize_, volumePart_;
};

std::unique_ptr<ScratchDir> MergeRefusals::dir_;
std::vector<fs::path> MergeRefusals::parts_;
fs::path MergeRefusals::otherSeed_, MergeRefusals::otherProject_, MergeRefusals::otherCount_, MergeRefusals::otherSize_,
    MergeRefusals::volumePart_;

TEST_F(MergeRefusals, TheCompleteSetMerges) {
  ASSERT_EQ(parts_.size(), 3u);
  const fs::path out = dir_->path / "complete.png";
  EXPECT_TRUE(succeeds("merge " + quote(parts_[2].string()) + " " + quote(parts_[0].string()) + " " +
                       quote(parts_[1].string()) + " -o " + quote(out.string())));
  EXPECT_TRUE(fs::exists(out));
  fs::remove(out);
}

TEST_F(MergeRefusals, AMissingPart) {
  // No file to name: the message names the part and the render.
  expectRefused({parts_[0], parts_[2]}, {"part 1 of 3", "missing", "twisted_functions.gridifs"});
  expectRefused({parts_[1]}, {"parts 0, 2 of 3", "missing"});
}

TEST_F(MergeRefusals, TheSameFileTwice) {
  expectRefused({parts_[0], parts_[1], parts_[1], parts_[2]}, {parts_[1].string() + " is given 2 times"});
}

TEST_F(MergeRefusals, TwoCopiesOfOnePart) {
  const fs::path copy = editedCopy(parts_[1], "copy_of_p1.gpart", [](std::string&) {});
  expectRefused({parts_[0], parts_[1], copy, parts_[2]}, {parts_[1].string(), copy.string()});
  fs::remove(copy);
}

TEST_F(MergeRefusals, APartCutInHalf) {
  const fs::path cut = editedCopy(parts_[1], "half.gpart", [](std::string& b) { b.resize(b.size() / 2); });
  expectRefused({parts_[0], cut, parts_[2]}, {cut.string(), "truncated"});
  fs::remove(cut);
}

TEST_F(MergeRefusals, APartWithoutItsLastByte) {
  const fs::path cut = editedCopy(parts_[1], "short.gpart", [](std::string& b) { b.pop_back(); });
  expectRefused({parts_[0], cut, parts_[2]}, {cut.string(), "truncated"});
  fs::remove(cut);
}

TEST_F(MergeRefusals, APartWithAFlippedByte) {
  // In the middle of the compressed payload (past the header, whose checksum would catch it first).
  const fs::path payload = editedCopy(parts_[1], "flipped.gpart", [](std::string& b) {
    const auto [begin, end] = payloadOf(b);
    ASSERT_LT(begin + 100, end);
    b[(begin + end) / 2] = char(b[(begin + end) / 2] ^ 0x5A);
  });
  expectRefused({parts_[0], payload, parts_[2]}, {payload.string(), "damaged"});
  // In the header (the embedded project), and in the trailer's checksum.
  const fs::path header =
      editedCopy(parts_[1], "flipped_header.gpart", [](std::string& b) { b[200] = char(b[200] ^ 1); });
  expectRefused({parts_[0], header, parts_[2]}, {header.string(), "damaged"});
  const fs::path trailer = editedCopy(parts_[1], "flipped_crc.gpart",
                                      [](std::string& b) { b[b.size() - 12] = char(b[b.size() - 12] ^ 0x80); });
  expectRefused({parts_[0], trailer, parts_[2]}, {trailer.string(), "damaged"});
  for (const fs::path& p : {payload, header, trailer}) fs::remove(p);
}

TEST_F(MergeRefusals, ForeignParts) {
  for (const fs::path& foreign : {otherSeed_, otherProject_, otherCount_, otherSize_}) {
    SCOPED_TRACE(foreign.filename().string());
    // In place of part 1, and in addition to the three parts.
    expectRefused({parts_[0], foreign, parts_[2]}, {foreign.string()});
    expectRefused({parts_[0], parts_[1], parts_[2], foreign}, {foreign.string()});
  }
  expectRefused({parts_[0], volumePart_, parts_[2]}, {volumePart_.string()});
}

// The render is the one most files belong to: a foreign part given first is the one named as
// foreign, not the three good parts after it.
TEST_F(MergeRefusals, AForeignPartGivenFirstIsTheOneNamed) {
  expectRefused({otherSeed_, parts_[0], parts_[1], parts_[2]}, {otherSeed_.string()});
  const CommandResult r = runGridifs("merge " + quote(otherSeed_.string()) + " " + quote(parts_[0].string()) + " " +
                                     quote(parts_[1].string()) + " " + quote(parts_[2].string()) + " -o " +
                                     quote((dir_->path / "merged.png").string()));
  EXPECT_NE(r.err.find(otherSeed_.string() + " belongs to another render"), std::string::npos) << r.err;
}

TEST_F(MergeRefusals, FilesThatAreNoParts) {
  const fs::path png = dir_->path / "image.png";
  ASSERT_TRUE(succeeds("merge " + quote(parts_[0].string()) + " " + quote(parts_[1].string()) + " " +
                       quote(parts_[2].string()) + " -o " + quote(png.string())));
  expectRefused({parts_[0], png, parts_[2]}, {png.string(), "not a GridIFS render part"});
  expectRefused({parts_[0], dir_->path / "no_such.gpart", parts_[2]}, {(dir_->path / "no_such.gpart").string()});
  fs::remove(png);
}

TEST_F(MergeRefusals, OutputsOfTheWrongKind) {
  // Image parts make images, volume parts volumes.
  expectRefused({parts_[0], parts_[1], parts_[2]}, {"merged.vdb"}, "vdb");
  expectRefused({parts_[0], parts_[1], parts_[2]}, {"merged.gpart"}, "gpart");
}

// ---------------------------------------------------------------------------------------------
// --part on the command line.

TEST(RenderPartOption, BadFormsAreRefused) {
  ScratchDir dir("parts-option");
  for (const std::string part : {"3/3", "-1/2", "a/b", "1/0", "1/2/3", "1", "0/100001", ""}) {
    SCOPED_TRACE("--part \"" + part + "\"");
    const fs::path out = dir.path / "out.gpart";
    for (const std::string& verb : {"render " + quote(kTwisted) + " --samples 1e5 --width 32 --height 24",
                                    "volume " + quote(kPineTrees) + " --samples 1e5 --resolution 16"}) {
      const CommandResult r =
          runGridifs(verb + " -o " + quote(out.string()) + " --device cpu -q --part=" + quote(part));
      EXPECT_EQ(r.exitCode, 2) << r.err;
      EXPECT_NE(r.err.find("--part"), std::string::npos) << r.err;
    }
    // Written as two arguments as well ("--part -1/2").
    if (!part.empty()) {
      EXPECT_EQ(runGridifs("render " + quote(kTwisted) + " -o " + quote(out.string()) +
                           " --samples 1e5 --device cpu -q --part " + quote(part))
                    .exitCode,
                2);
    }
  }
  EXPECT_TRUE(entriesOf(dir.path).empty()) << "a refused --part wrote a file";
}

TEST(RenderPartOption, APartIsWrittenOnlyAsGpart) {
  ScratchDir dir("parts-ext");
  for (const std::string ext : {"png", "exr", "tif"}) {
    const CommandResult r =
        runGridifs("render " + quote(kTwisted) + " -o " + quote((dir.path / ("out." + ext)).string()) +
                   " --samples 1e5 --device cpu -q --part 0/2");
    EXPECT_EQ(r.exitCode, 2) << ext;
    EXPECT_NE(r.err.find(".gpart"), std::string::npos) << r.err;
  }
  EXPECT_EQ(runGridifs("volume " + quote(kPineTrees) + " -o " + quote((dir.path / "out.vdb").string()) +
                       " --samples 1e5 --device cpu -q --part 0/2")
                .exitCode,
            2);
  // The other way round: a .gpart output needs --part.
  EXPECT_EQ(runGridifs("render " + quote(kTwisted) + " -o " + quote((dir.path / "out.gpart").string()) +
                       " --samples 1e5 --device cpu -q")
                .exitCode,
            2);
  EXPECT_TRUE(entriesOf(dir.path).empty());
}

// A chaos-game volume splits; a volume of median functions is a set iteration and does not.
TEST(RenderPartOption, MedianVolumesDoNotSplit) {
  ScratchDir dir("parts-median");
  const CommandResult r = runGridifs("volume " + quote(asset("volumes/two_sets.gridifs")) + " -o " +
                                     quote((dir.path / "v.gpart").string()) + " -q --part 0/2");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("median"), std::string::npos) << r.err;
  EXPECT_TRUE(entriesOf(dir.path).empty());
}

// ---------------------------------------------------------------------------------------------
// A killed part writer.

// SIGKILL while the part renders, and at random moments up to the end of its writing: the target
// is then absent or the complete part (the same bytes as an undisturbed run), never a file that
// merge would have to refuse; temporaries are hidden (dot-prefixed).
TEST(RenderPartKill, AKilledPartWriterLeavesNoPartFile) {
  ScratchDir dir("parts-kill");
  const fs::path work = dir.path / "work";
  fs::create_directories(work);
  const fs::path target = work / "part.gpart", reference = dir.path / "reference.gpart";
  // A flame part (colour sums: the largest buffers) big enough to take a while to write.
  auto args = [&](const fs::path& out, const std::string& samples = "3e7") {
    return std::vector<std::string>{"render",    kTwisted,  "-o",       out.string(), "--part", "0/1",       "--mode",
                                    "flame",     "--width", "1280",     "--height",   "720",    "--samples", samples,
                                    "--threads", "1",       "--device", "cpu",        "-q"};
  };
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(waitFor(spawnGridifs(args(reference))), 0);
  const double fullSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_NO_THROW(verifyRenderPart(reference));
  const std::string complete = slurp(reference);

  auto check = [&](const std::string& when) {
    for (const std::string& entry : entriesOf(work))
      EXPECT_TRUE(entry == "part.gpart" || entry.front() == '.')
          << when << ": a temporary file is not hidden: " << entry;
    if (!fs::exists(target)) return false;
    EXPECT_TRUE(slurp(target) == complete)
        << when << ": the part file under the target's name is not the complete part";
    return true;
  };

  // Mid-render: ten times the samples, killed when the reference run was 40 % through, so the
  // kill falls in the render however the machine's load changes between the runs.
  const pid_t pid = spawnGridifs(args(target, "3e8"));
  std::this_thread::sleep_for(std::chrono::duration<double>(fullSeconds * 0.4));
  ::kill(pid, SIGKILL);
  EXPECT_EQ(waitFor(pid), -SIGKILL) << "the part finished before it was killed";
  EXPECT_FALSE(check("killed mid-render")) << "a killed render left " << target;

  // Random moments over the whole run, writing included.
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> moment(fullSeconds * 0.5, fullSeconds * 1.3);
  int absent = 0, completeParts = 0;
  for (int k = 0; k < 6; ++k) {
    fs::remove(target);
    const pid_t p = spawnGridifs(args(target));
    std::this_thread::sleep_for(std::chrono::duration<double>(moment(rng)));
    ::kill(p, SIGKILL);
    waitFor(p);
    (check("kill " + std::to_string(k)) ? completeParts : absent) += 1;
  }
  std::printf("part writer killed: %d times no part, %d times the complete part (a full run: %.1f s)\n", absent,
              completeParts, fullSeconds);
  std::fflush(stdout);  // before the next fork
  // The next run removes what the killed ones left behind.
  fs::remove(target);
  ASSERT_EQ(waitFor(spawnGridifs(args(target))), 0);
  EXPECT_EQ(slurp(target), complete);
  EXPECT_EQ(entriesOf(work), std::set<std::string>{"part.gpart"}) << "stale temporary files were not removed";
}

}  // namespace
}  // namespace gridifs
