// Time on the command line: --time, frame sequences, motion blur, export-field, and the bad
// input of sequences (nothing is written then).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "io/project_io.h"
#include "tests/cli/run_command.h"

namespace gridifs {
namespace {

using test_support::quote;
using test_support::runGridifs;
using test_support::ScratchDir;
using test_support::slurp;
namespace fs = std::filesystem;

/// One function displaced by a field with wind, 24 fps, and the render kept small.
fs::path writeFieldProject(const fs::path& folder) {
  Project p;
  Function f;
  f.resolution = {5, 5, 5};
  f.placement.scale = Vec3{0.5};
  FieldOp field;
  field.amplitude = {0.3, 0.3, 0.3};
  field.scale = 0.8;
  field.octaves = 3;
  field.wind = {1.0, 0.0, 0.0};
  field.seed = 4;
  Operation op;
  op.params = field;
  f.ops.push_back(op);
  p.functions.push_back(f);
  Function g = f;
  g.placement.translate = {0.4, 0.0, 0.0};
  p.functions.push_back(g);
  p.render.width = 48;
  p.render.height = 40;
  p.render.samples = 20000;
  p.animation = AnimationSettings{};
  const fs::path file = folder / "field.gridifs";
  saveProject(p, file);
  return file;
}

std::size_t fileCount(const fs::path& folder) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(folder)) ++n;
  return n;
}

TEST(AnimationCli, AFrameRenderedAloneEqualsThatFrameOfASequence) {
  ScratchDir dir("anim-frames");
  const fs::path project = writeFieldProject(dir.path);
  const std::string common = " --threads 2 --seed 5 -q";
  const auto seq = runGridifs("render " + quote(project.string()) + " -o " + quote((dir.path / "f_%03d.png").string()) +
                              " --frames 2:4" + common);
  ASSERT_EQ(seq.exitCode, 0) << seq.err;
  for (int f = 2; f <= 4; ++f) EXPECT_TRUE(fs::exists(dir.path / ("f_00" + std::to_string(f) + ".png"))) << f;
  EXPECT_FALSE(fs::exists(dir.path / "f_001.png"));
  EXPECT_FALSE(fs::exists(dir.path / "f_005.png"));
  // Frame 3 at t = 3/24 = 0.125, alone.
  const auto alone = runGridifs("render " + quote(project.string()) + " -o " +
                                quote((dir.path / "alone.png").string()) + " --time 0.125" + common);
  ASSERT_EQ(alone.exitCode, 0) << alone.err;
  EXPECT_EQ(slurp(dir.path / "alone.png"), slurp(dir.path / "f_003.png"));
  const auto single = runGridifs("render " + quote(project.string()) + " -o " +
                                 quote((dir.path / "one_%d.png").string()) + " --frames 3:3" + common);
  ASSERT_EQ(single.exitCode, 0) << single.err;
  EXPECT_EQ(slurp(dir.path / "one_3.png"), slurp(dir.path / "f_003.png"));
  // The field moves with the wind: another frame is another image.
  EXPECT_NE(slurp(dir.path / "f_002.png"), slurp(dir.path / "f_004.png"));
}

TEST(AnimationCli, MotionBlurMergesTimeSamples) {
  ScratchDir dir("anim-blur");
  const fs::path project = writeFieldProject(dir.path);
  // The attractor is a thin curve: at the project's 48×40 it covers a handful of pixels, which
  // the motion within half a frame interval need not change; at 96×80 it moves by pixels.
  const std::string common = " --threads 2 --seed 5 -q --time 0.5 --width 96 --height 80";
  const auto sharp =
      runGridifs("render " + quote(project.string()) + " -o " + quote((dir.path / "sharp.png").string()) + common);
  const auto blur = runGridifs("render " + quote(project.string()) + " -o " + quote((dir.path / "blur.png").string()) +
                               common + " --motion-blur 4");
  const auto again = runGridifs("render " + quote(project.string()) + " -o " +
                                quote((dir.path / "again.png").string()) + common + " --motion-blur 4");
  ASSERT_EQ(sharp.exitCode, 0) << sharp.err;
  ASSERT_EQ(blur.exitCode, 0) << blur.err;
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_NE(slurp(dir.path / "sharp.png"), slurp(dir.path / "blur.png"));
  EXPECT_EQ(slurp(dir.path / "blur.png"), slurp(dir.path / "again.png"));
  const auto flame = runGridifs("render " + quote(project.string()) + " -o " +
                                quote((dir.path / "flame.png").string()) + common + " --motion-blur 3 --mode flame");
  EXPECT_EQ(flame.exitCode, 0) << flame.err;
}

TEST(AnimationCli, BadSequencesWriteNothing) {
  ScratchDir dir("anim-bad");
  const fs::path project = writeFieldProject(dir.path);
  const std::size_t before = fileCount(dir.path);
  const std::string render = "render " + quote(project.string()) + " -q --threads 1";
  const std::string pattern = " -o " + quote((dir.path / "f_%04d.png").string());
  struct Case {
    std::string args, says;
  };
  const Case cases[] = {
      {pattern + " --frames 5:2", "ends before it starts"},
      {pattern + " --frames 0:100000", "more than the limit of 100000"},
      {pattern + " --frames a:b", "two whole frame numbers"},
      {pattern + " --frames 3", "two whole frame numbers"},
      {" -o " + quote((dir.path / "frame.png").string()) + " --frames 0:3", "has no frame number"},
      {" -o " + quote((dir.path / "f_%d_%d.png").string()) + " --frames 0:3", "more than one frame number"},
      {" -o " + quote((dir.path / "f_%s.png").string()) + " --frames 0:3", "not a frame number"},
      {pattern + " --frames 0:3 --motion-blur 0", "--motion-blur must be between 1"},
      {pattern + " --frames 0:3 --time 1", "exclude each other"},
      {" -o " + quote((dir.path / "one.png").string()) + " --video " + quote((dir.path / "v.mp4").string()),
       "needs a frame sequence"},
  };
  for (const Case& c : cases) {
    const auto r = runGridifs(render + c.args);
    EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  // Without ffmpeg on the PATH (one that holds only `timeout`, which the test runner needs),
  // --video is refused before any frame is rendered.
  ScratchDir bin("anim-bin");
  fs::create_symlink("/usr/bin/timeout", bin.path / "timeout");
  const auto video = runGridifs(render + pattern + " --frames 0:2 --video " + quote((dir.path / "v.mp4").string()), "",
                                "PATH=" + quote(bin.path.string()));
  EXPECT_EQ(video.exitCode, 2) << video.err;
  EXPECT_NE(video.err.find("no ffmpeg on the PATH"), std::string::npos) << video.err;
  EXPECT_EQ(std::count(video.err.begin(), video.err.end(), '\n'), 1) << video.err;
  EXPECT_EQ(fileCount(dir.path), before);
}

/// What ffprobe says of a video's first stream: "width,height,frames", or "" when it cannot run.
std::string probeVideo(const fs::path& video) {
  return test_support::ffprobe(video,
                               "-select_streams v:0 -count_frames -show_entries stream=width,height,nb_read_frames");
}

TEST(AnimationCli, VideoAssemblesTheFrames) {
  // ffmpeg is a declared dependency (scripts/deps.sh): its absence fails here rather than skips.
  ASSERT_EQ(std::system("command -v ffmpeg >/dev/null && command -v ffprobe >/dev/null"), 0)
      << "ffmpeg and ffprobe must be installed (scripts/deps.sh)";
  ScratchDir dir("anim-video");
  const fs::path project = writeFieldProject(dir.path);
  const fs::path video = dir.path / "clip.mp4";
  const auto r =
      runGridifs("render " + quote(project.string()) + " -q --threads 1 --device cpu -o " +
                 quote((dir.path / "f_%04d.png").string()) + " --frames 2:6 --video " + quote(video.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // Five frames of 48 × 40 (the project's size), and the frames stay beside the video.
  EXPECT_EQ(probeVideo(video), "48,40,5");
  for (int f = 2; f <= 6; ++f) EXPECT_TRUE(fs::exists(dir.path / ("f_000" + std::to_string(f) + ".png"))) << f;
  for (const auto& e : fs::directory_iterator(dir.path))
    EXPECT_NE(e.path().filename().string().rfind(".~", 0), 0u) << "temporary left behind: " << e.path();
}

TEST(AnimationCli, AFailedVideoKeepsTheFrames) {
  // An ffmpeg that fails (as on a full disk or a missing encoder) after every frame is written.
  ScratchDir dir("anim-video-fail");
  ScratchDir bin("anim-video-bin");
  fs::create_symlink("/usr/bin/timeout", bin.path / "timeout");
  {
    std::ofstream script(bin.path / "ffmpeg");
    script << "#!/bin/sh\necho 'encoder not found' >&2\nexit 1\n";
  }
  fs::permissions(bin.path / "ffmpeg", fs::perms::owner_all);
  const fs::path project = writeFieldProject(dir.path);
  const fs::path video = dir.path / "clip.mp4";
  const auto r =
      runGridifs("render " + quote(project.string()) + " -q --threads 1 --device cpu -o " +
                     quote((dir.path / "f_%04d.png").string()) + " --frames 0:2 --video " + quote(video.string()),
                 "", "PATH=" + quote(bin.path.string()));
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("ffmpeg failed"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("clip.mp4"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("encoder not found"), std::string::npos) << r.err;  // ffmpeg's reason
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  for (int f = 0; f <= 2; ++f) EXPECT_TRUE(fs::exists(dir.path / ("f_000" + std::to_string(f) + ".png"))) << f;
  EXPECT_FALSE(fs::exists(video));
  for (const auto& e : fs::directory_iterator(dir.path))
    EXPECT_NE(e.path().filename().string().rfind(".~", 0), 0u) << "temporary left behind: " << e.path();
}

TEST(AnimationCli, TimeMovesTheNodes) {
  ScratchDir dir("anim-time");
  const fs::path project = writeFieldProject(dir.path);
  const auto at0 = runGridifs("nodes " + quote(project.string()) + " --function 0");
  const auto at1 = runGridifs("nodes " + quote(project.string()) + " --function 0 --time 1");
  const auto again = runGridifs("nodes " + quote(project.string()) + " --function 0 --time 1");
  ASSERT_EQ(at0.exitCode, 0) << at0.err;
  ASSERT_EQ(at1.exitCode, 0) << at1.err;
  EXPECT_NE(at0.out, at1.out);
  EXPECT_EQ(at1.out, again.out);
  const auto eval = runGridifs("eval " + quote(project.string()) + " --function 0 --time 0.5", "0 0 0\n");
  EXPECT_EQ(eval.exitCode, 0) << eval.err;
  const auto bad = runGridifs("nodes " + quote(project.string()) + " --function 0 --time nan");
  EXPECT_NE(bad.exitCode, 0);
}

TEST(AnimationCli, ExportFieldWritesAHeightfield) {
  ScratchDir dir("anim-field");
  const fs::path project = writeFieldProject(dir.path);
  const fs::path out = dir.path / "terrain.ply";
  const auto r = runGridifs("export-field " + quote(project.string()) + " --op 'functions[1].ops[0]' -o " +
                            quote(out.string()) + " --size 33 --ascii --time 0.25");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string ply = slurp(out);
  EXPECT_NE(ply.find("element vertex 1089"), std::string::npos);
  EXPECT_NE(ply.find("element face 1024"), std::string::npos);
  for (const char* bad : {"functions[2].ops[0]", "functions[0].ops[3]", "final.ops[0]", "ops[0]"}) {
    const auto e = runGridifs("export-field " + quote(project.string()) + " --op " + quote(bad) + " -o " +
                              quote((dir.path / "x.ply").string()));
    EXPECT_EQ(e.exitCode, 2) << bad << e.err;
    EXPECT_FALSE(fs::exists(dir.path / "x.ply"));
  }
  const auto size = runGridifs("export-field " + quote(project.string()) + " --op 'functions[0].ops[0]' -o " +
                               quote((dir.path / "x.ply").string()) + " --size 1");
  EXPECT_EQ(size.exitCode, 2) << size.err;
}

}  // namespace
}  // namespace gridifs
