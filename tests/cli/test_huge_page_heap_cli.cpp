// A render starts itself again with glibc's `glibc.malloc.hugetlb` tunable, whose heap on huge
// pages saves most of a short render's page faults (app/huge_page_heap.h). What a user can see of
// that: the running render's environment (what /proc shows of it), its arguments unchanged, the
// user's own tunables kept, a value the user chose for that tunable left alone, its name in ps
// unchanged, a quick verb left as it started, and the same picture as without it.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <thread>

#include "example_projects.h"
#include "run_command.h"

using namespace gridifs::test_support;

namespace {

// A /proc/PID file whose entries are separated by NUL bytes, as a list of strings.
std::vector<std::string> procEntries(pid_t pid, const char* file) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/" + file, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::string> entries;
  std::string entry;
  for (char c : text) {
    if (c == '\0') {
      entries.push_back(entry);
      entry.clear();
    } else {
      entry += c;
    }
  }
  return entries;
}

// GLIBC_TUNABLES as the process was started with it. glibc, parsing it, ends each tunable's value
// with a NUL where it lies, so /proc shows the tunables after the first as entries of their own.
std::string tunablesOf(const std::vector<std::string>& environment) {
  for (std::size_t i = 0; i < environment.size(); ++i) {
    if (environment[i].rfind("GLIBC_TUNABLES=", 0) != 0) continue;
    std::string tunables = environment[i].substr(15);
    for (std::size_t j = i + 1; j < environment.size() && environment[j].rfind("glibc.", 0) == 0; ++j)
      tunables += ":" + environment[j];
    return tunables;
  }
  return "(unset)";
}

struct RunningRender {
  std::string tunables;
  std::vector<std::string> arguments;
  std::string name;  // what ps and top show
};

// Starts a render that would run for minutes with GLIBC_TUNABLES as given ("" for unset), waits
// until the process has settled (its environment names the tunable, or 3 s went by), reads what
// /proc shows of it, and stops it.
RunningRender watchRender(const std::string& tunables, const std::filesystem::path& out) {
  const char* saved = std::getenv("GLIBC_TUNABLES");
  const std::string before = saved ? saved : "";
  if (tunables.empty())
    ::unsetenv("GLIBC_TUNABLES");
  else
    ::setenv("GLIBC_TUNABLES", tunables.c_str(), 1);
  const pid_t pid = spawnGridifs({"render", kSierpinski, "-o", out.string(), "--width", "64", "--height", "64",
                                  "--samples", "100000000000", "--threads", "1", "--device", "cpu"});
  if (saved)
    ::setenv("GLIBC_TUNABLES", before.c_str(), 1);
  else
    ::unsetenv("GLIBC_TUNABLES");
  RunningRender seen;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  do {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    seen.tunables = tunablesOf(procEntries(pid, "environ"));
    seen.arguments = procEntries(pid, "cmdline");
    std::ifstream(("/proc/" + std::to_string(pid) + "/comm").c_str()) >> seen.name;
  } while (seen.tunables.find("glibc.malloc.hugetlb") == std::string::npos &&
           std::chrono::steady_clock::now() < deadline);
  ::kill(pid, SIGKILL);
  waitFor(pid);
  return seen;
}

TEST(HugePageHeap, ARenderRunsWithTheTunableAndItsOwnArguments) {
  ScratchDir dir("huge-page-heap-args");
  const RunningRender seen = watchRender("", dir.path / "out.png");
  EXPECT_EQ(seen.tunables, "glibc.malloc.hugetlb=1");
  ASSERT_GE(seen.arguments.size(), 4u);
  EXPECT_EQ(seen.arguments[1], "render");
  EXPECT_EQ(seen.arguments[2], kSierpinski);
  EXPECT_EQ(seen.arguments.back(), "cpu");
  EXPECT_EQ(seen.name, std::filesystem::path(GRIDIFS_EXE).filename().string().substr(0, 15));
}

TEST(HugePageHeap, TheUsersOwnTunablesAreKept) {
  ScratchDir dir("huge-page-heap-keep");
  EXPECT_EQ(watchRender("glibc.malloc.tcache_count=0", dir.path / "out.png").tunables,
            "glibc.malloc.hugetlb=1:glibc.malloc.tcache_count=0");
}

TEST(HugePageHeap, AValueTheUserChoseForItIsLeftAlone) {
  ScratchDir dir("huge-page-heap-chosen");
  EXPECT_EQ(watchRender("glibc.malloc.hugetlb=0", dir.path / "out.png").tunables, "glibc.malloc.hugetlb=0");
}

TEST(HugePageHeap, AQuickVerbDoesNotStartAgain) {
  // `eval` waits for points on its stdin: held open here, so the process can be looked at while
  // it runs. Half a second is many times what starting again takes.
  const char* saved = std::getenv("GLIBC_TUNABLES");
  const std::string before = saved ? saved : "";
  ::unsetenv("GLIBC_TUNABLES");
  int input[2];
  ASSERT_EQ(::pipe(input), 0);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(input[0], 0);
    ::close(input[1]);
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    std::string exe = GRIDIFS_EXE, verb = "eval", project = kSierpinski, option = "--function", index = "0";
    char* argv[] = {exe.data(), verb.data(), project.data(), option.data(), index.data(), nullptr};
    ::execv(GRIDIFS_EXE, argv);
    ::_exit(127);
  }
  ::close(input[0]);
  if (saved) ::setenv("GLIBC_TUNABLES", before.c_str(), 1);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  const std::string tunables = tunablesOf(procEntries(pid, "environ"));
  const bool running = ::waitpid(pid, nullptr, WNOHANG) == 0;
  ::close(input[1]);
  const int status = waitFor(pid);
  EXPECT_TRUE(running);
  EXPECT_EQ(tunables, "(unset)");
  EXPECT_EQ(status, 0);
}

TEST(HugePageHeap, TheImageIsTheSameWithoutIt) {
  ScratchDir dir("huge-page-heap-same");
  const std::string args = quote(kTwisted) + " --width 160 --height 120 --samples 200000 --seed 3 --threads 2";
  const CommandResult with = runGridifs("render " + args + " -o " + quote((dir.path / "with.png").string()));
  const CommandResult without = runGridifs("render " + args + " -o " + quote((dir.path / "without.png").string()), "",
                                           "GLIBC_TUNABLES=glibc.malloc.hugetlb=0");
  ASSERT_EQ(with.exitCode, 0) << with.err;
  ASSERT_EQ(without.exitCode, 0) << without.err;
  EXPECT_EQ(slurp(dir.path / "with.png"), slurp(dir.path / "without.png"));
}

}  // namespace
