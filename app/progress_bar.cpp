#include "app/progress_bar.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/cli.h"
#include "render/chaos_renderer.h"

namespace gridifs::cli {

ProgressBar::ProgressBar(std::string label, bool quiet)
    : label_(std::move(label)), enabled_(!quiet && stderrIsTerminal()) {}

bool ProgressBar::report(const RenderStats& s) {
  update(s.samples, s.budget, s.pointsPerSecond, s.done);
  return true;
}

bool ProgressBar::fraction(double done) {
  constexpr std::int64_t kSteps = 1000;
  update(std::int64_t(std::clamp(done, 0.0, 1.0) * kSteps), kSteps, 0.0, done >= 1.0);
  return true;
}

void ProgressBar::message(const std::string& text) {
  if (!enabled_) return;
  std::fprintf(stderr, "\r%s: %s\033[K", label_.c_str(), text.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

ProgressBar::~ProgressBar() { finish(); }

std::string humanCount(double value) {
  char buffer[32];
  if (value >= 1e9)
    std::snprintf(buffer, sizeof buffer, "%.2f G", value / 1e9);
  else if (value >= 1e6)
    std::snprintf(buffer, sizeof buffer, "%.1f M", value / 1e6);
  else if (value >= 1e3)
    std::snprintf(buffer, sizeof buffer, "%.1f k", value / 1e3);
  else
    std::snprintf(buffer, sizeof buffer, "%.0f ", value);
  return buffer;
}

void ProgressBar::update(std::int64_t done, std::int64_t total, double pointsPerSecond, bool force) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (!force && drawn_ && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  const double fraction = total > 0 ? std::clamp(double(done) / double(total), 0.0, 1.0) : 0.0;
  constexpr int kWidth = 30;
  const int filled = int(fraction * kWidth);
  std::string bar(std::size_t(filled), '#');
  bar.resize(kWidth, '.');
  char eta[32] = "";
  if (pointsPerSecond > 0.0 && done < total) {
    const double seconds = double(total - done) / pointsPerSecond;
    if (seconds >= 3600)
      std::snprintf(eta, sizeof eta, "ETA %dh%02dm", int(seconds / 3600), int(std::fmod(seconds, 3600) / 60));
    else if (seconds >= 60)
      std::snprintf(eta, sizeof eta, "ETA %dm%02ds", int(seconds / 60), int(std::fmod(seconds, 60)));
    else
      std::snprintf(eta, sizeof eta, "ETA %.0fs", std::ceil(seconds));
  }
  if (pointsPerSecond > 0.0)
    std::fprintf(stderr, "\r%s [%s] %5.1f%%  %spoints/s  %s\033[K", label_.c_str(), bar.c_str(), 100.0 * fraction,
                 humanCount(pointsPerSecond).c_str(), eta);
  else
    std::fprintf(stderr, "\r%s [%s] %5.1f%%\033[K", label_.c_str(), bar.c_str(), 100.0 * fraction);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::finish() {
  if (drawn_) {
    std::fputc('\n', stderr);
    std::fflush(stderr);
    drawn_ = false;
  }
}

}  // namespace gridifs::cli
