// `--threads N` bounds every thread of a render, not only its workers: with --threads 1 nothing
// runs beside the one worker (the image library loads before it starts, and no helper warms the
// heap), so the process's CPU time (user + system) cannot exceed its wall time, in every display
// mode. This checks that invariant of one running thread, not a speed: a second thread running
// at the same time is what would break it, whatever the machine's load.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>

#include <chrono>
#include <thread>

#include "run_command.h"

using namespace gridifs::test_support;

namespace {

struct ProcessCost {
  int status = -1;
  double wall = 0.0, cpu = 0.0;
};

ProcessCost runMeasured(const std::vector<std::string>& args) {
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = spawnGridifs(args);
  int status = 0;
  rusage usage{};
  ::wait4(pid, &status, 0, &usage);
  ProcessCost c;
  c.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  c.cpu = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
          1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  c.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return c;
}

}  // namespace

TEST(ThreadsBound, OneThreadMeansOneCoreInEveryMode) {
  const ScratchDir dir("threads-bound");
  const std::string project = std::string(GRIDIFS_ASSETS) + "/default.gridifs";
  for (const char* mode : {"zbuffer", "flame", "shaded"}) {
    const std::string out = (dir.path / (std::string(mode) + ".png")).string();
    const ProcessCost c =
        runMeasured({"render", project, "-o", out, "--mode", mode, "--threads", "1", "--samples", "30000000"});
    ASSERT_EQ(c.status, 0) << mode;
    ASSERT_TRUE(std::filesystem::exists(out)) << mode;
    std::printf("[threads 1, %s] wall %.3f s, CPU %.3f s\n", mode, c.wall, c.cpu);
    // The kernel accounts CPU time in ticks: allow one of them and a hair.
    EXPECT_LE(c.cpu, c.wall * 1.02 + 0.02) << mode << ": more than one thread ran at once";
  }
}

TEST(ThreadsBound, MoreThreadsThanCoresRenderWithoutTheThreadPoolsWarning) {
  // The flame develop's parallel loops run in a oneTBB arena; one larger than the machine's cores
  // made oneTBB print "TBB Warning: ... The request for N workers is ignored" on stderr.
  const ScratchDir dir("threads-more-than-cores");
  const int threads = int(std::thread::hardware_concurrency()) + 1;
  const CommandResult r =
      runGridifs("render " + quote(std::string(GRIDIFS_ASSETS) + "/default.gridifs") + " -o " +
                 quote((dir.path / "flame.png").string()) +
                 " --mode flame --samples 200000 -q --device cpu --threads " + std::to_string(threads));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err.find("TBB"), std::string::npos) << r.err;
}
