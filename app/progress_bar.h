#pragma once
// A one-line progress bar on stderr for long CLI verbs (render, export-points): percent, points/s
// and ETA, redrawn at most ten times a second. Silent when stderr is not a terminal.
#include <chrono>
#include <cstdint>
#include <string>

namespace gridifs::cli {

class ProgressBar {
 public:
  /// `label` is printed before the bar ("render", "export-points"). Enabled only on a terminal.
  explicit ProgressBar(std::string label, bool enabled);
  ~ProgressBar();  // finishes the line if something was drawn

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
