#include "render/renderer.h"

#include <algorithm>

#include "render/chaos_renderer.h"

namespace gridifs {

bool Renderer::waitForBudget(const std::function<bool(const RenderStats&)>& progress, double intervalSeconds,
                             const std::function<bool(double)>& waitForProgress) {
  const double interval = std::max(0.001, intervalSeconds);
  for (;;) {
    const RenderStats s = stats();
    if (s.done) {
      if (progress) progress(s);
      return true;
    }
    // Without a job the stats have no budget.
    if (s.budget <= 0 || s.paused) return false;
    if (progress && !progress(s)) {
      pause();
      return false;
    }
    if (!waitForProgress(interval)) return false;
  }
}

}  // namespace gridifs
