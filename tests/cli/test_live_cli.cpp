// Sound on the command line: `render --frames` follows the audio bindings, and
// `--video` carries the project's sound; bad bindings and a missing sound are refused with exit
// 2 and one sentence, before any frame is written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>

#include "io/project_io.h"
#include "tests/cli/image_file_read.h"
#include "tests/cli/run_command.h"
#include "tests/support/sound_file.h"

namespace gridifs {
namespace {

using test_support::ffprobe;
using test_support::quote;
using test_support::runGridifs;
using test_support::ScratchDir;
namespace fs = std::filesystem;

/// A small two-function project whose camera yaw is bound to the 200–2000 Hz band of a sound
/// that is silent for a second, then a 440 Hz tone for a second (24 fps).
Project boundProject() {
  Project p;
  Function f;
  f.resolution = {4, 4, 4};
  f.placement.scale = Vec3{0.5};
  p.functions.push_back(f);
  f.placement.translate = {0.5, 0.2, 0.0};
  p.functions.push_back(f);
  p.render.width = 48;
  p.render.height = 40;
  p.render.samples = 20000;
  p.animation = AnimationSettings{};
  p.audio = AudioSettings{"song.wav", {{20, 200}, {200, 2000}}};
  p.bindings.push_back(Binding{"camera.yaw", "audio:1", 0.0, 90.0, 0.0});
  return p;
}

fs::path writeBound(const fs::path& folder, const Project& p) {
  test_support::writeWav(folder / "song.wav", test_support::silenceThenTone(1.0, 440.0, 22050), 22050);
  const fs::path file = folder / "bound.gridifs";
  saveProject(p, file);
  return file;
}

TEST(LiveCli, FramesFollowTheSound) {
  ScratchDir dir("live-frames");
  const Project p = boundProject();
  const fs::path project = writeBound(dir.path, p);
  const std::string common = " -q --threads 1 --device cpu --seed 3";
  const auto seq = runGridifs("render " + quote(project.string()) + " -o " + quote((dir.path / "f_%02d.png").string()) +
                              " --frames 4:40" + common);
  ASSERT_EQ(seq.exitCode, 0) << seq.err;
  // A silent frame is the project at the binding's min, byte for byte.
  Project atMin = p;
  atMin.bindings.clear();
  atMin.audio.reset();
  atMin.camera.yaw = 0.0;
  saveProject(atMin, dir.path / "min.gridifs");
  const auto plain =
      runGridifs("render " + quote((dir.path / "min.gridifs").string()) + " -o " +
                 quote((dir.path / "min.png").string()) + " --time " + std::to_string(4.0 / 24.0) + common);
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  // (Pixels: the files' descriptions name their projects.)
  const auto pixels = [&](const char* name) { return test_support::readImageFile(dir.path / name).pixels; };
  ASSERT_FALSE(pixels("f_04.png").empty());
  EXPECT_EQ(pixels("f_04.png"), pixels("min.png"));
  EXPECT_EQ(pixels("f_04.png"), pixels("f_20.png"));
  // In the tone the camera has turned.
  EXPECT_NE(pixels("f_30.png"), pixels("f_04.png"));
}

TEST(LiveCli, VideoCarriesTheSound) {
  ASSERT_EQ(std::system("command -v ffmpeg >/dev/null && command -v ffprobe >/dev/null"), 0)
      << "ffmpeg and ffprobe must be installed (scripts/deps.sh)";
  ScratchDir dir("live-video");
  const fs::path project = writeBound(dir.path, boundProject());
  const fs::path video = dir.path / "clip.mp4";
  const auto r =
      runGridifs("render " + quote(project.string()) + " -q --threads 1 --device cpu -o " +
                 quote((dir.path / "f_%02d.png").string()) + " --frames 12:35 --video " + quote(video.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(ffprobe(video, "-select_streams a:0 -show_entries stream=codec_type,codec_name"), "aac,audio");
  EXPECT_EQ(ffprobe(video, "-select_streams v:0 -count_frames -show_entries stream=nb_read_frames"), "24");
  // The sound starts at the first frame's time and ends with the frames: one second.
  const double seconds = std::atof(ffprobe(video, "-select_streams a:0 -show_entries stream=duration").c_str());
  EXPECT_NEAR(seconds, 1.0, 0.06);
}

TEST(LiveCli, BadBindingsAndAMissingSoundAreRefusedBeforeAnyFrame) {
  ScratchDir dir("live-bad");
  Project p = boundProject();
  p.bindings[0].path = "functions[5].weight";
  writeBound(dir.path, boundProject());
  // The file is written by hand: saving validates, as a file edited elsewhere would not be.
  std::string text = serializeProject(boundProject());
  const std::string good = "\"path\": \"camera.yaw\"";
  ASSERT_NE(text.find(good), std::string::npos);
  text.replace(text.find(good), good.size(), "\"path\": \"functions[5].weight\"");
  { std::ofstream(dir.path / "bad.gridifs") << text; }
  const auto bad = runGridifs("render " + quote((dir.path / "bad.gridifs").string()) + " -o " +
                              quote((dir.path / "f_%02d.png").string()) + " --frames 0:3");
  EXPECT_EQ(bad.exitCode, 2) << bad.err;
  EXPECT_NE(bad.err.find("bindings[0].path: names no parameter of this project (functions[5].weight)"),
            std::string::npos)
      << bad.err;
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;

  fs::remove(dir.path / "song.wav");
  const auto missing = runGridifs("render " + quote((dir.path / "bound.gridifs").string()) + " -o " +
                                  quote((dir.path / "f_%02d.png").string()) + " --frames 0:3");
  EXPECT_EQ(missing.exitCode, 2) << missing.err;
  EXPECT_NE(missing.err.find("song.wav"), std::string::npos) << missing.err;
  EXPECT_EQ(std::count(missing.err.begin(), missing.err.end(), '\n'), 1) << missing.err;
  EXPECT_FALSE(fs::exists(dir.path / "f_00.png"));
}

}  // namespace
}  // namespace gridifs
