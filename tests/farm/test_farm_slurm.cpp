// The farm tier: `gridifs farm --submit` against a real one-node Slurm (munge, slurmctld, slurmd
// from Debian, on 127.0.0.1) that a ctest fixture starts with scripts/slurm-local before the tier
// and stops after it. The farm's images must be the bytes of a render on one machine.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "cli/run_command.h"

namespace gridifs {
namespace {

using test_support::CommandResult;
using test_support::quote;
using test_support::ScratchDir;
using test_support::slurp;
namespace fs = std::filesystem;

const std::string kSlurmEnv = std::string("SLURM_CONF=") + GRIDIFS_SLURM_DIR + "/slurm.conf";

CommandResult gridifs(const std::string& args) { return test_support::runGridifs(args, "", kSlurmEnv); }

/// Runs a Slurm client command and returns its standard output.
std::string slurm(const std::string& command) {
  const std::string cmd = "env " + kSlurmEnv + " " + command + " 2>/dev/null";
  std::string out;
  if (FILE* p = ::popen(cmd.c_str(), "r")) {
    char buffer[4096];
    std::size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, p)) > 0) out.append(buffer, n);
    ::pclose(p);
  }
  return out;
}

/// Waits until Slurm has no job of `jobs` (the job folder's `jobs` file) left but those whose
/// dependency can never be satisfied; returns false after `seconds`.
bool waitForJobs(const fs::path& dir, double seconds = 240) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    std::string ids;
    std::istringstream in(slurp(dir / "jobs"));
    std::string line;
    while (std::getline(in, line)) ids += (ids.empty() ? "" : ",") + line.substr(0, line.find(' '));
    bool busy = false;
    std::istringstream queue(slurm("squeue -h -j " + ids + " -o '%T %r'"));
    while (std::getline(queue, line))
      if (!line.empty() && line.find("DependencyNeverSatisfied") == std::string::npos) busy = true;
    if (!busy) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
  return false;
}

std::string asset(const std::string& name) { return quote(std::string(GRIDIFS_ASSETS) + "/" + name); }

/// The frames of a local render and of the farm must be the same files, byte for byte.
void expectSameFiles(const fs::path& a, const fs::path& b) {
  ASSERT_TRUE(fs::exists(a)) << a;
  ASSERT_TRUE(fs::exists(b)) << b;
  EXPECT_TRUE(slurp(a) == slurp(b)) << a << " and " << b << " differ";
}

TEST(Farm, SlurmIsRunning) {
  // The fixture started it; sinfo shows the node (the other tests would time out otherwise).
  EXPECT_NE(slurm("sinfo -h -o '%T'").find("idle"), std::string::npos) << slurm("sinfo");
}

TEST(Farm, AnimationOfThreeFramesInFourPartsEqualsTheLocalRender) {
  ScratchDir dir("farm-animation");
  const std::string options = " --samples 2e6 --width 160 --height 120";
  const std::string project = asset("animation/breathing_twist.gridifs");
  ASSERT_EQ(
      gridifs("render " + project + " -q --frames 0:2 -o " + quote((dir.path / "local_%03d.png").string()) + options)
          .exitCode,
      0);
  const CommandResult farm =
      gridifs("farm " + project + " --frames 0:2 --parts 4 --dir " + quote((dir.path / "job").string()) + " -o " +
              quote((dir.path / "farm_%03d.png").string()) + options + " --submit");
  ASSERT_EQ(farm.exitCode, 0) << farm.err;
  EXPECT_NE(farm.out.find("12 render tasks, 3 frames to merge"), std::string::npos) << farm.out;
  EXPECT_NE(farm.out.find("submitted job"), std::string::npos) << farm.out;
  ASSERT_TRUE(waitForJobs(dir.path / "job"));
  for (const char* f : {"000", "001", "002"})
    expectSameFiles(dir.path / ("local_" + std::string(f) + ".png"), dir.path / ("farm_" + std::string(f) + ".png"));
  const CommandResult status = gridifs("farm --status " + quote((dir.path / "job").string()));
  EXPECT_EQ(status.exitCode, 0);
  EXPECT_NE(status.out.find("3 of 3 frames have every part, 3 merged"), std::string::npos) << status.out;
  // The same command again has nothing left to do.
  const CommandResult again =
      gridifs("farm " + project + " --frames 0:2 --parts 4 --dir " + quote((dir.path / "job").string()) + " -o " +
              quote((dir.path / "farm_%03d.png").string()) + options + " --submit");
  EXPECT_EQ(again.exitCode, 0);
  EXPECT_NE(again.out.find("nothing to submit"), std::string::npos) << again.out;
}

TEST(Farm, StillInSixteenPartsEqualsTheLocalRenderAndADamagedPartIsRenderedAgain) {
  ScratchDir dir("farm-still");
  const std::string options = " --samples 3e6 --width 200 --height 150 --mode flame";
  const std::string project = asset("default.gridifs");
  const std::string job = quote((dir.path / "job").string());
  const std::string farmCommand =
      "farm " + project + " --parts 16 --dir " + job + " -o " + quote((dir.path / "farm.png").string()) + options;
  ASSERT_EQ(gridifs("render " + project + " -q -o " + quote((dir.path / "local.png").string()) + options).exitCode, 0);
  const CommandResult farm = gridifs(farmCommand + " --submit");
  ASSERT_EQ(farm.exitCode, 0) << farm.err;
  ASSERT_TRUE(waitForJobs(dir.path / "job"));
  expectSameFiles(dir.path / "local.png", dir.path / "farm.png");

  // A damaged part: the merge refuses it; the status, which reads parts' headers and trailers
  // only, still counts it; the farm command, which checks every part's data, renders only it.
  const fs::path part = dir.path / "job" / "parts" / "s_p5.gpart";
  {
    std::fstream f(part, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(std::streamoff(fs::file_size(part) / 2));
    f.put('\x5A').put('\xA5');
  }
  std::string parts;
  for (int k = 0; k < 16; ++k)
    parts += " " + quote((dir.path / "job" / "parts" / ("s_p" + std::to_string(k) + ".gpart")).string());
  const CommandResult merge = gridifs("merge" + parts + " -o " + quote((dir.path / "again.png").string()));
  EXPECT_EQ(merge.exitCode, 2);
  EXPECT_NE(merge.err.find("s_p5.gpart"), std::string::npos) << merge.err;
  EXPECT_FALSE(fs::exists(dir.path / "again.png"));
  EXPECT_NE(gridifs("farm --status " + job).out.find("still: 16/16 parts"), std::string::npos);
  fs::remove(dir.path / "farm.png");
  const CommandResult again = gridifs(farmCommand + " --submit");
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_NE(again.out.find("1 render task, 1 frame to merge"), std::string::npos) << again.out;
  ASSERT_TRUE(waitForJobs(dir.path / "job"));
  expectSameFiles(dir.path / "local.png", dir.path / "farm.png");
}

TEST(Farm, ACancelledTaskKeepsItsMergeWaitingAndTheSameCommandFinishesWithTheSameBytes) {
  ScratchDir dir("farm-cancel");
  // Enough samples that the tasks run for seconds, so one can be cancelled while it runs (a task of
  // 10^8 samples took 0.8 s, and the cancel sometimes came after it had written its part; one of
  // 2.5·10^8 takes about 2 s, and the cancel comes within a tenth of a second of its start).
  const std::string options = " --samples 1e9 --width 160 --height 120";
  const std::string project = asset("default.gridifs");
  const std::string job = quote((dir.path / "job").string());
  const std::string farmCommand = "farm " + project + " --parts 4 --dir " + job + " -o " +
                                  quote((dir.path / "farm.png").string()) + options + " --submit";
  ASSERT_EQ(gridifs(farmCommand).exitCode, 0);
  std::string renderJob = slurp(dir.path / "job" / "jobs");
  renderJob = renderJob.substr(0, renderJob.find(' '));
  // Cancel element 2 once its render runs: Slurm reports the element RUNNING while it still
  // launches the batch script, and a cancel in that window can leave the script to run to its end
  // unsignalled (the job shows COMPLETING while the render writes its part). So wait for the
  // render's own process (this machine is the test cluster's only node).
  // "[s]" keeps pgrep's pattern from matching the shell that runs pgrep.
  const std::string partTwo = (dir.path / "job" / "parts").string() + "/[s]_p2.gpart";
  bool cancelled = false;
  for (int i = 0; i < 1000 && !cancelled; ++i) {
    if (slurm("squeue -h -j " + renderJob + "_2 -o '%T'").find("RUNNING") != std::string::npos &&
        !slurm("pgrep -f " + quote(partTwo)).empty()) {
      slurm("scancel " + renderJob + "_2");
      cancelled = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_TRUE(cancelled) << "element 2 never ran";
  ASSERT_TRUE(waitForJobs(dir.path / "job"));
  const CommandResult status = gridifs("farm --status " + job);
  EXPECT_NE(status.out.find("still: 3/4 parts, not merged; failed task 2 (part 2): cancelled"), std::string::npos)
      << status.out;
  EXPECT_NE(status.out.find("DependencyNeverSatisfied"), std::string::npos) << status.out;  // the merge waits
  EXPECT_FALSE(fs::exists(dir.path / "farm.png"));

  const CommandResult again = gridifs(farmCommand);
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_NE(again.out.find("1 render task, 1 frame to merge"), std::string::npos) << again.out;
  ASSERT_TRUE(waitForJobs(dir.path / "job"));
  ASSERT_EQ(gridifs("render " + project + " -q -o " + quote((dir.path / "local.png").string()) + options).exitCode, 0);
  expectSameFiles(dir.path / "local.png", dir.path / "farm.png");
}

TEST(Farm, AFailedTaskIsNamedAndItsFrameIsNotMerged) {
  ScratchDir dir("farm-failed");
  const fs::path project = dir.path / "project.gridifs";
  fs::copy_file(std::string(GRIDIFS_ASSETS) + "/default.gridifs", project);
  const std::string job = quote((dir.path / "job").string());
  const std::string farmCommand = "farm " + quote(project.string()) + " --parts 2 --dir " + job + " -o " +
                                  quote((dir.path / "farm.png").string()) + " --samples 1e6 --width 96 --height 72";
  // Held jobs: the project is gone when they are released, so both render tasks fail.
  ASSERT_EQ(gridifs(farmCommand + " --submit --sbatch=--hold").exitCode, 0);
  const std::string saved = slurp(project);
  fs::remove(project);
  std::istringstream jobs(slurp(dir.path / "job" / "jobs"));
  std::string line;
  while (std::getline(jobs, line)) slurm("scontrol release " + line.substr(0, line.find(' ')));
  ASSERT_TRUE(waitForJobs(dir.path / "job"));
  const CommandResult status = gridifs("farm --status " + job);
  EXPECT_NE(
      status.out.find("still: 0/2 parts, not merged; failed task 0 (part 0): exit 2; failed task 1 (part 1): exit 2"),
      std::string::npos)
      << status.out;
  EXPECT_FALSE(fs::exists(dir.path / "farm.png"));
  // The project back, the same command finishes the render.
  { std::ofstream(project, std::ios::binary) << saved; }
  const CommandResult again = gridifs(farmCommand + " --submit");
  ASSERT_EQ(again.exitCode, 0) << again.err;
  ASSERT_TRUE(waitForJobs(dir.path / "job"));
  EXPECT_TRUE(fs::exists(dir.path / "farm.png"));
  EXPECT_NE(gridifs("farm --status " + job).out.find("still: 2/2 parts, merged"), std::string::npos);
}

TEST(Farm, RefusesAFolderOfAnotherRenderAndBadRequests) {
  ScratchDir dir("farm-refuse");
  const std::string project = asset("default.gridifs");
  const std::string job = quote((dir.path / "job").string());
  const std::string out = " -o " + quote((dir.path / "farm.png").string());
  ASSERT_EQ(gridifs("farm " + project + " --parts 2 --dir " + job + out + " --samples 1e6").exitCode, 0);
  const CommandResult other = gridifs("farm " + project + " --parts 2 --dir " + job + out + " --samples 2e6");
  EXPECT_EQ(other.exitCode, 2);
  EXPECT_NE(other.err.find("holds the job of another render"), std::string::npos) << other.err;
  EXPECT_EQ(gridifs("farm " + project + " --parts 0 --dir " + job + out).exitCode, 2);
  EXPECT_EQ(gridifs("farm " + project + " --parts 2 --dir " + job + out + " --mode sepia").exitCode, 2);
  EXPECT_EQ(gridifs("farm --status " + quote(dir.path.string())).exitCode, 2);
  // Without --submit the commands are printed, nothing is submitted.
  const CommandResult dry = gridifs("farm " + project + " --parts 2 --dir " + job + out + " --samples 1e6");
  EXPECT_EQ(dry.exitCode, 0);
  EXPECT_NE(dry.out.find("sbatch --array=0-1"), std::string::npos) << dry.out;
  EXPECT_FALSE(fs::exists(dir.path / "job" / "jobs"));
}

}  // namespace
}  // namespace gridifs
