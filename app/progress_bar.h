#pragma once
// The one progress bar of the long CLI verbs (render, export-points, export-mesh): a line on
// stderr with percent and, for the chaos game, points/s and ETA, redrawn at most ten times a
// second. Silent with --quiet and when stderr is not a terminal.
#include <chrono>
#include <cstdint>
#include <string>

namespace gridifs {
struct RenderStats;
}

namespace gridifs::cli {

class ProgressBar {
 public:
  /// `label` is printed before the bar ("render", "export-points"). Drawn only when not `quiet`
  /// and stderr is a terminal.
  ProgressBar(std::string label, bool quiet);
  ~ProgressBar();  // finishes the line if something was drawn

  /// The chaos game's progress callback: draws `stats` (the bar ends with the run); always true.
  bool report(const RenderStats& stats);
  /// Progress without a rate (a fraction in [0, 1]); always true, so it can answer "go on".
  bool fraction(double done);
  /// Replaces the bar with a note ("writing out.ply") until the next update.
  void message(const std::string& text);
  /// done/total samples at `pointsPerSecond`; redraws when 0.1 s have passed (or force).
  void update(std::int64_t done, std::int64_t total, double pointsPerSecond, bool force = false);
  /// Ends the line (a no-op when nothing was drawn).
  void finish();

 private:
  std::string label_;
  bool enabled_, drawn_ = false;
  std::chrono::steady_clock::time_point last_{};
};

/// "12.3 M" style formatting of a rate or count.
std::string humanCount(double value);

}  // namespace gridifs::cli
