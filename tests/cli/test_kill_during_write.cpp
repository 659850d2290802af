// Nothing is lost on a crash: SIGKILL at random moments while `render`, `export-points` and
// `export-mesh` write their file, and while a project is saved (the modeller's Save and autosave
// use the same writer). The target is always either the previous file, byte for byte, or the
// complete new one — never a truncated file under the target's name. Temporary files are hidden
// (dot-prefixed) and the next run that writes into the folder removes the stale ones.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "io/project_io.h"
#include "tests/cli/example_projects.h"
#include "tests/cli/run_command.h"

namespace fs = std::filesystem;
using namespace gridifs::test_support;

namespace {

void writeBytes(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

std::vector<std::string> folderEntries(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(folder)) names.push_back(e.path().filename().string());
  return names;
}

/// A writing command, killed `kills` times at random moments within the time a complete run takes.
/// `args(out)` builds the command line writing to `out`.
void killWhileWriting(const std::string& name, const std::function<std::vector<std::string>(const fs::path&)>& args,
                      int kills, std::uint32_t seed) {
  ScratchDir dir("kill-" + name);
  const fs::path reference = dir.path / ("reference-" + name);
  const fs::path work = dir.path / "work";
  fs::create_directories(work);
  const fs::path target = work / ("out-" + name);

  // The complete new file, and how long a complete run takes.
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(waitFor(spawnGridifs(args(reference))), 0) << name;
  const double fullSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string complete = slurp(reference);
  ASSERT_FALSE(complete.empty());
  const std::string previous = "the previous " + name + " file, which a killed run must leave intact\n";

  std::mt19937 rng(seed);
  // Moments up to 1.5× a complete run: most kills fall inside the run, some after it.
  std::uniform_real_distribution<double> moment(0.0, fullSeconds * 1.5);
  int intact = 0, replaced = 0, finished = 0;
  for (int k = 0; k < kills; ++k) {
    writeBytes(target, previous);
    const pid_t pid = spawnGridifs(args(target));
    std::this_thread::sleep_for(std::chrono::duration<double>(moment(rng)));
    ::kill(pid, SIGKILL);
    if (waitFor(pid) == 0) ++finished;
    const std::string now = slurp(target);
    if (now == previous) {
      ++intact;
    } else {
      ASSERT_EQ(now.size(), complete.size())
          << name << ": kill " << k << " left a truncated file under the target's name";
      ASSERT_TRUE(now == complete) << name << ": kill " << k << " left a file that is neither the old nor the new one";
      ++replaced;
    }
    for (const std::string& entry : folderEntries(work))
      EXPECT_TRUE(entry == target.filename().string() || entry.front() == '.')
          << name << ": a temporary file is not hidden: " << entry;
  }
  // Some kills fell before the new file was complete (how many runs finished first depends on
  // the machine's load, so that count is only reported).
  EXPECT_GT(intact, 0) << name;
  std::printf("%s: %d kills left the old file, %d the new one, %d runs finished first\n", name.c_str(), intact,
              replaced, finished);
  std::fflush(stdout);  // before the next fork, whose child would flush this buffer again
  // The next complete run removes what the killed ones left behind.
  ASSERT_EQ(waitFor(spawnGridifs(args(target))), 0) << name;
  EXPECT_EQ(slurp(target), complete) << name;
  EXPECT_EQ(folderEntries(work), std::vector<std::string>{target.filename().string()})
      << name << ": stale temporary files were not removed by the next run";
}

}  // namespace

TEST(KillDuringWrite, RenderLeavesTheOldImageOrTheNewOne) {
  const std::string project = kTwisted;
  killWhileWriting(
      "render.png",
      [&](const fs::path& out) {
        return std::vector<std::string>{"render",   project, "-o",        out.string(), "--width",   "640",
                                        "--height", "480",   "--samples", "1500000",    "--threads", "1"};
      },
      20, 11);
}

TEST(KillDuringWrite, ExportPointsLeavesTheOldCloudOrTheNewOne) {
  const std::string project = kSierpinski;
  killWhileWriting(
      "points.ply",
      [&](const fs::path& out) {
        return std::vector<std::string>{"export-points", project,   "-o",        out.string(),
                                        "--samples",     "1000000", "--threads", "1"};
      },
      20, 12);
}

TEST(KillDuringWrite, ExportMeshLeavesTheOldMeshOrTheNewOne) {
  const std::string project = kSierpinski;
  killWhileWriting(
      "mesh.ply",
      [&](const fs::path& out) {
        return std::vector<std::string>{"export-mesh", project, "-o", out.string(), "--depth", "7"};
      },
      20, 13);
}

// The modeller's Save and autosave call saveProject: a child process saves two versions in turn
// and is killed at random moments; the file always loads as one of them.
TEST(KillDuringWrite, ProjectSaveLeavesTheOldProjectOrTheNewOne) {
  ScratchDir dir("kill-save");
  const fs::path file = dir.path / "plate.gridifs";
  gridifs::Project a = gridifs::loadProject(asset("universal_calculator.gridifs"));
  gridifs::Project b = a;
  b.functions[0].name = "renamed";
  b.render.seed = a.render.seed + 1;
  gridifs::saveProject(a, file);
  const std::string textA = gridifs::serializeProject(a), textB = gridifs::serializeProject(b);
  std::mt19937 rng(14);
  std::uniform_int_distribution<int> micros(0, 20'000);
  for (int k = 0; k < 20; ++k) {
    const pid_t pid = ::fork();
    if (pid == 0) {
      for (int i = 0;; ++i) gridifs::saveProject(i % 2 ? a : b, file);
    }
    std::this_thread::sleep_for(std::chrono::microseconds(micros(rng)));
    ::kill(pid, SIGKILL);
    waitFor(pid);
    const std::string text = gridifs::serializeProject(gridifs::loadProject(file));
    EXPECT_TRUE(text == textA || text == textB) << "kill " << k << " left a project that is neither version";
    for (const std::string& entry : folderEntries(dir.path))
      EXPECT_TRUE(entry == "plate.gridifs" || entry == "plate.gridifs~" || entry.front() == '.')
          << "a temporary file is not hidden: " << entry;
  }
  gridifs::saveProject(a, file);  // the next save removes the stale temporaries
  for (const std::string& entry : folderEntries(dir.path))
    EXPECT_TRUE(entry == "plate.gridifs" || entry == "plate.gridifs~") << "stale temporary left: " << entry;
}
