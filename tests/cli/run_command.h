#pragma once
// Runs the real gridifs executable (or any command) and captures its outcome.
#include <unistd.h>

#include <sys/wait.h>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace gridifs::test_support {

struct CommandResult {
  int exitCode = -1;
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Writes `text` to `file` byte for byte (the tests' inputs, good and bad); slurp's inverse.
inline void writeText(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

inline std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// Runs `gridifs ARGS` (already quoted as needed) with `input` on stdin and `env` ("NAME=value
/// ...") set for the child only. A watchdog (timeout 60 s) turns a hang into a failure instead of
/// a stuck test run.
inline CommandResult runGridifs(const std::string& args, const std::string& input = "", const std::string& env = "") {
  namespace fs = std::filesystem;
  static int counter = 0;
  const fs::path base =
      fs::temp_directory_path() / ("gridifs-cli-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  { std::ofstream(base.string() + ".in", std::ios::binary) << input; }
  const std::string cmd = (env.empty() ? "" : "env " + env + " ") + "timeout 60 " + quote(GRIDIFS_EXE) + " " + args +
                          " < " + quote(base.string() + ".in") + " > " + quote(base.string() + ".out") + " 2> " +
                          quote(base.string() + ".err");
  const int status = std::system(cmd.c_str());
  CommandResult r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(base.string() + ".out");
  r.err = slurp(base.string() + ".err");
  fs::remove(base.string() + ".in");
  fs::remove(base.string() + ".out");
  fs::remove(base.string() + ".err");
  return r;
}

/// What ffprobe says of `file`: the `entries` asked for ("-select_streams v:0 -show_entries
/// stream=width,height"), as comma-separated values without their names or the final line end; ""
/// when ffprobe cannot run.
inline std::string ffprobe(const std::filesystem::path& file, const std::string& entries) {
  const std::string cmd = "ffprobe -v error " + entries + " -of csv=p=0 " + quote(file.string()) + " 2>/dev/null";
  std::string out;
  if (FILE* pipe = ::popen(cmd.c_str(), "r")) {
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
    ::pclose(pipe);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

/// Starts `gridifs args...` as a child process (stdout and stderr to /dev/null).
inline pid_t spawnGridifs(const std::vector<std::string>& args) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    std::vector<std::string> all{GRIDIFS_EXE};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(GRIDIFS_EXE, argv.data());
    ::_exit(127);
  }
  return pid;
}

/// Waits for `pid`; returns its exit status, or -signal when a signal ended it.
inline int waitFor(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

/// A fresh temporary folder removed at scope exit.
struct ScratchDir {
  std::filesystem::path path;
  explicit ScratchDir(const std::string& name) {
    path = std::filesystem::temp_directory_path() / ("gridifs-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~ScratchDir() { std::filesystem::remove_all(path); }
};

}  // namespace gridifs::test_support
