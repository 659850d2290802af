// `--device auto|gpu|cpu` on render, export-points, volume and info (the GPU path runs on Mesa's llvmpipe
// where there is no GPU). Failures are forced through the real EGL stack: libglvnd finds no EGL
// vendor when __EGL_VENDOR_LIBRARY_FILENAMES names none, and Mesa hides compute shaders (and with
// them OpenGL 4.3) with MESA_EXTENSION_OVERRIDE.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/run_command.h"

namespace gridifs {
namespace {

using test_support::CommandResult;
using test_support::quote;
using test_support::runGridifs;
using test_support::ScratchDir;
using test_support::slurp;
namespace fs = std::filesystem;

/// runGridifs with environment variables set for the child only.
CommandResult runWithEnv(const std::string& env, const std::string& args) { return runGridifs(args, "", env); }

const std::string kNoEgl = "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json";
const std::string kNoCompute = "MESA_EXTENSION_OVERRIDE=-GL_ARB_compute_shader";

std::string example() { return quote(std::string(GRIDIFS_ASSETS) + "/sierpinski_tetrahedron.gridifs"); }

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

TEST(DeviceCli, RenderOnEachDevice) {
  ScratchDir dir("device-render");
  for (const char* device : {"gpu", "cpu", "auto"}) {
    SCOPED_TRACE(device);
    const fs::path out = dir.path / (std::string(device) + ".png");
    const CommandResult r = runGridifs("render " + example() + " -o " + quote(out.string()) +
                                       " --width 64 --height 48 --samples 200000 --device " + device);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(out));
    if (std::string(device) != "auto") {
      EXPECT_EQ(r.err, "");
    }
    // auto says at most once why it did not take the GPU.
    EXPECT_LE(count(r.err, "note: rendered on the CPU"), 1u) << r.err;
  }
}

TEST(DeviceCli, BadDeviceIsBadUsage) {
  ScratchDir dir("device-bad");
  const CommandResult r = runGridifs("render " + example() + " -o " + quote((dir.path / "x.png").string()) +
                                     " --samples 1000 --device tpu");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--device must be auto, gpu or cpu, not \"tpu\""), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path / "x.png"));
  EXPECT_EQ(runGridifs("export-points " + example() + " -o " + quote((dir.path / "x.ply").string()) + " --device GPU")
                .exitCode,
            2);
  EXPECT_EQ(runGridifs("info " + example() + " --device fast").exitCode, 2);
}

TEST(DeviceCli, NoEglFailsOnGpuAndFallsBackOnAuto) {
  ScratchDir dir("device-noegl");
  const std::string args = " -o " + quote((dir.path / "a.png").string()) + " --width 32 --height 32 --samples 50000";
  const CommandResult gpu = runWithEnv(kNoEgl, "render " + example() + args + " --device gpu");
  EXPECT_EQ(gpu.exitCode, 1) << gpu.err;
  EXPECT_EQ(gpu.err.rfind("gridifs: cannot render on the GPU: ", 0), 0u) << gpu.err;
  EXPECT_EQ(count(gpu.err, "\n"), 1u) << "one sentence: " << gpu.err;
  EXPECT_FALSE(fs::exists(dir.path / "a.png"));
  const CommandResult fallback = runWithEnv(kNoEgl, "render " + example() + args + " --device auto");
  EXPECT_EQ(fallback.exitCode, 0) << fallback.err;
  EXPECT_EQ(count(fallback.err, "note: rendered on the CPU: "), 1u) << fallback.err;
  EXPECT_TRUE(fs::exists(dir.path / "a.png"));
  const CommandResult info = runWithEnv(kNoEgl, "info " + example());
  EXPECT_EQ(info.exitCode, 0);
  EXPECT_NE(info.out.find("render device (--device auto): cpu: "), std::string::npos) << info.out;
}

TEST(DeviceCli, NoComputeShadersFailsOnGpu) {
  ScratchDir dir("device-nocompute");
  const CommandResult r = runWithEnv(kNoCompute, "render " + example() + " -o " + quote((dir.path / "a.png").string()) +
                                                     " --width 32 --height 32 --samples 50000 --device gpu");
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("compute"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path / "a.png"));
}

TEST(DeviceCli, ImageTooLargeForTheGpuFailsOnGpu) {
  // 8000×8000 with the flame gutter: 246 MB of z-buffer and 2 GB of colour sums, each in one
  // storage buffer; llvmpipe allows 128 MB. (Auto's fallback for this case: tests/gpu.)
  ScratchDir dir("device-large");
  const std::string args =
      " -o " + quote((dir.path / "a.png").string()) + " --width 8000 --height 8000 --samples 1000 --mode flame";
  const CommandResult gpu = runGridifs("render " + example() + args + " --device gpu");
  if (gpu.exitCode == 0) GTEST_SKIP() << "this GPU holds a 2 GB image";
  EXPECT_EQ(gpu.exitCode, 1) << gpu.err;
  EXPECT_NE(gpu.err.find("cannot render on the GPU: the GPU cannot hold"), std::string::npos) << gpu.err;
  EXPECT_FALSE(fs::exists(dir.path / "a.png"));
}

TEST(DeviceCli, InfoNamesTheDevice) {
  const CommandResult gpu = runGridifs("info " + example() + " --device gpu --json");
  EXPECT_EQ(gpu.exitCode, 0) << gpu.err;
  EXPECT_NE(gpu.out.find("\"render_device\": \"gpu\""), std::string::npos) << gpu.out;
  const CommandResult cpu = runGridifs("info " + example() + " --device cpu");
  EXPECT_NE(cpu.out.find("render device (--device cpu): cpu"), std::string::npos) << cpu.out;
}

TEST(DeviceCli, VolumeOnEachDevice) {
  ScratchDir dir("device-volume");
  for (const char* device : {"gpu", "cpu", "auto"}) {
    SCOPED_TRACE(device);
    const fs::path out = dir.path / (std::string(device) + ".vdb");
    const CommandResult r = runGridifs("volume " + example() + " -o " + quote(out.string()) +
                                       " --resolution 32 --samples 200000 -q --device " + device);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_GT(fs::file_size(out), 1000u);
    if (std::string(device) != "auto") {
      EXPECT_EQ(r.err, "");
    }
    EXPECT_LE(count(r.err, "note: rendered on the CPU"), 1u) << r.err;
  }
  EXPECT_EQ(
      runGridifs("volume " + example() + " -o " + quote((dir.path / "x.vdb").string()) + " --device npu").exitCode, 2);
  EXPECT_FALSE(fs::exists(dir.path / "x.vdb"));
}

TEST(DeviceCli, VolumeOfWhatTheGpuDoesNotRunFailsOnGpuAndFallsBackOnAuto) {
  ScratchDir dir("device-volume-cpu-only");
  const std::string volumes = std::string(GRIDIFS_ASSETS) + "/volumes/";
  // Median functions iterate voxel sets (no chaos game); condensation functions sample meshes.
  for (const auto& [file, why] : {std::pair<std::string, std::string>{"two_sets.gridifs", "median functions"},
                                  {"pine_trees.gridifs", "condensation functions"}}) {
    SCOPED_TRACE(file);
    const fs::path out = dir.path / (file + ".vdb");
    const std::string args = "volume " + quote(volumes + file) + " -o " + quote(out.string()) +
                             " --resolution 16 --iterations 20 --samples 100000 -q";
    const CommandResult gpu = runGridifs(args + " --device gpu");
    EXPECT_EQ(gpu.exitCode, 1) << gpu.err;
    EXPECT_EQ(gpu.err.rfind("gridifs: cannot render on the GPU: ", 0), 0u) << gpu.err;
    EXPECT_NE(gpu.err.find(why), std::string::npos) << gpu.err;
    EXPECT_EQ(count(gpu.err, "\n"), 1u) << "one sentence: " << gpu.err;
    EXPECT_FALSE(fs::exists(out));
    const CommandResult fallback = runGridifs(args + " --device auto");
    EXPECT_EQ(fallback.exitCode, 0) << fallback.err;
    EXPECT_EQ(count(fallback.err, "note: rendered on the CPU: "), 1u) << fallback.err;
    EXPECT_TRUE(fs::exists(out));
  }
  const CommandResult noEgl = runWithEnv(kNoEgl, "volume " + example() + " -o " + quote((dir.path / "e.vdb").string()) +
                                                     " --resolution 16 --samples 10000 -q --device gpu");
  EXPECT_EQ(noEgl.exitCode, 1) << noEgl.err;
  EXPECT_FALSE(fs::exists(dir.path / "e.vdb"));
}

TEST(DeviceCli, ExportPointsOnTheGpu) {
  ScratchDir dir("device-points");
  const fs::path out = dir.path / "p.ply";
  const CommandResult r =
      runGridifs("export-points " + example() + " -o " + quote(out.string()) + " --samples 100000 --device gpu");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string ply = slurp(out);
  const auto at = ply.find("element vertex ");
  ASSERT_NE(at, std::string::npos);
  const long n = std::stol(ply.substr(at + 15));
  EXPECT_GT(n, 90'000);
  EXPECT_LE(n, 100'000);
  EXPECT_EQ(ply.size(), ply.find("end_header\n") + 11 + std::size_t(n) * 15);
}

}  // namespace
}  // namespace gridifs
