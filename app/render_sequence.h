#pragma once
// `gridifs render --frames A:B`: frame ranges, the printf pattern that names each frame's file,
// and assembling the frames into a video with ffmpeg.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace gridifs::cli {

/// The sequence options of `render`.
struct SequenceOptions {
  std::optional<std::string> frames;  // "A:B"
  std::optional<int> motionBlur;      // time samples per frame (default: the project's animation.motion_blur)
  std::optional<std::string> video;   // OUT.mp4, assembled with ffmpeg
};

constexpr std::int64_t kMaxSequenceFrames = 100000;

/// Frames first..last, both included.
struct FrameRange {
  std::int64_t first = 0, last = 0;
  std::int64_t count() const { return last - first + 1; }
};

/// Parses "A:B" (whole numbers, B ≥ A, at most kMaxSequenceFrames frames). Throws CliError(2).
FrameRange parseFrameRange(const std::string& text);

/// Requires exactly one integer conversion (%d, %4d, %04d) in `pattern` and no other % but
/// "%%" (framePatternProblem, base/text_format.h). Throws CliError(2) naming the pattern.
void checkFramePattern(const std::string& pattern);

/// Checks before anything is rendered that `video` can be written: ffmpeg on PATH, a known video
/// extension, an existing writable folder. Throws CliError(2).
void checkVideoOutput(const std::string& video);

/// Runs ffmpeg on the written frames (H.264 for .mp4/.mov/.mkv, VP9 for .webm) into a temporary file
/// beside `video`, renamed over it only when ffmpeg succeeds. Throws CliError(1) on failure.
void assembleVideo(const std::string& pattern, const FrameRange& frames, double fps, const std::string& video,
                   const std::filesystem::path& audio = {});

}  // namespace gridifs::cli
