#include "app/render_sequence.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "app/cli.h"
#include "app/render_setup.h"
#include "base/text_format.h"

extern char** environ;

namespace gridifs::cli {
namespace {

bool parseWhole(const std::string& text, std::int64_t& out) {
  if (text.empty() || text.size() > 12) return false;
  std::size_t i = text[0] == '-' ? 1 : 0;
  if (i == text.size()) return false;
  for (std::size_t c = i; c < text.size(); ++c)
    if (!std::isdigit(static_cast<unsigned char>(text[c]))) return false;
  out = std::strtoll(text.c_str(), nullptr, 10);
  return true;
}

std::optional<std::filesystem::path> findOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  std::string all = path;
  std::size_t start = 0;
  while (start <= all.size()) {
    const std::size_t end = std::min(all.find(':', start), all.size());
    const std::filesystem::path candidate = std::filesystem::path(all.substr(start, end - start)) / program;
    if (end > start && ::access(candidate.c_str(), X_OK) == 0) return candidate;
    start = end + 1;
  }
  return std::nullopt;
}

// The last non-empty line of a small log file, without its line end ("" if none).
std::string lastLine(const std::filesystem::path& file) {
  std::FILE* in = std::fopen(file.c_str(), "r");
  if (!in) return {};
  std::string last;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, in)) {
    std::string line = buffer;
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
    if (!line.empty()) last = line;
  }
  std::fclose(in);
  return last;
}

}  // namespace

FrameRange parseFrameRange(const std::string& text) {
  const std::size_t colon = text.find(':');
  FrameRange r;
  if (colon == std::string::npos || !parseWhole(text.substr(0, colon), r.first) ||
      !parseWhole(text.substr(colon + 1), r.last))
    throw CliError(kBadInput, "--frames must be two whole frame numbers A:B such as 0:23, not \"" + text + "\"");
  if (r.last < r.first) throw CliError(kBadInput, "--frames " + text + " ends before it starts (B must be at least A)");
  if (r.count() > kMaxSequenceFrames)
    throw CliError(kBadInput, "--frames " + text + " is " + std::to_string(r.count()) +
                                  " frames, more than the limit of " + std::to_string(kMaxSequenceFrames));
  return r;
}

void checkFramePattern(const std::string& pattern) {
  if (const auto problem = framePatternProblem(pattern))
    throw CliError(kBadInput, "the output name " + pattern + " " + *problem);
}

void checkVideoOutput(const std::string& video) {
  checkOutputPath(video, {"mp4", "mov", "mkv", "webm"}, "the video");
  if (!findOnPath("ffmpeg"))
    throw CliError(kBadInput, "cannot write " + video + ": --video needs ffmpeg, and there is no ffmpeg on the PATH");
}

void assembleVideo(const std::string& pattern, const FrameRange& frames, double fps, const std::string& video,
                   const std::filesystem::path& audio) {
  const auto ffmpeg = findOnPath("ffmpeg");
  if (!ffmpeg) throw CliError(kFailure, "cannot write " + video + ": ffmpeg is no longer on the PATH");
  const std::filesystem::path target(video);
  // The temporary keeps the extension: ffmpeg picks the container by it.
  const std::filesystem::path temporary =
      target.parent_path() /
      (".~" + target.stem().string() + "." + std::to_string(::getpid()) + target.extension().string());
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.17g", fps);
  const bool webm = lowerExtension(target) == "webm";
  std::vector<std::string> args = {"ffmpeg",     "-loglevel", "error",         "-y",
                                   "-framerate", rate,        "-start_number", std::to_string(frames.first),
                                   "-i",         pattern};
  if (!audio.empty()) {
    // The sound from the first frame's time on, and both streams cut at the frames' length (a
    // frame count would stop the sound short, where the muxer had buffered it behind the frames).
    char offset[32], duration[32];
    std::snprintf(offset, sizeof offset, "%.17g", double(frames.first) / fps);
    std::snprintf(duration, sizeof duration, "%.17g", double(frames.count()) / fps);
    args.insert(args.end(), {"-ss", offset, "-i", audio.string(), "-map", "0:v:0", "-map", "1:a:0", "-t", duration,
                             "-c:a", webm ? "libopus" : "aac", "-b:a", "192k"});
  } else {
    args.insert(args.end(), {"-frames:v", std::to_string(frames.count())});
  }
  if (webm) {
    args.insert(args.end(), {"-c:v", "libvpx-vp9", "-b:v", "0", "-crf", "30"});
  } else {
    // Even sizes for 4:2:0 chroma, which every player expects.
    args.insert(args.end(),
                {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "18", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2"});
  }
  args.push_back(temporary.string());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  // ffmpeg's own complaint goes to a log beside the video, so the user reads one sentence that
  // ends with ffmpeg's reason; the frames stay whatever happens.
  std::filesystem::path log = temporary;
  log += ".log";
  posix_spawn_file_actions_t actions;
  ::posix_spawn_file_actions_init(&actions);
  ::posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  pid_t pid = 0;
  const int spawned = ::posix_spawn(&pid, ffmpeg->c_str(), &actions, nullptr, argv.data(), environ);
  ::posix_spawn_file_actions_destroy(&actions);
  std::error_code ec;
  if (spawned != 0) {
    std::filesystem::remove(log, ec);
    throw CliError(kFailure, "cannot write " + video + ": ffmpeg could not be started");
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  const std::string reason = lastLine(log);
  std::filesystem::remove(log, ec);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::filesystem::remove(temporary, ec);
    throw CliError(kFailure, "cannot write " + video + ": ffmpeg failed on the frames " + pattern +
                                 (reason.empty() ? std::string() : " (" + reason + ")") + "; the frames are kept");
  }
  std::filesystem::rename(temporary, target, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    throw CliError(kFailure, "cannot write " + video + ": " + ec.message());
  }
}

}  // namespace gridifs::cli
