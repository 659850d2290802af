#include "ui/views/flame_display.h"

#include <algorithm>
#include <chrono>
#include <memory>

#include "render/flame_render.h"
#include "tone/palette.h"

namespace gridifs::ui {

bool FlameDeveloper::submit(const RenderImage& snapshot, const FlameSettings& settings, const Camera& camera,
                            const Vec3& background) {
  if (job_.busy()) return false;
  Input input{snapshot, settings, camera, background};
  input.settings.supersample = 1;
  job_.submit(std::move(input));
  return true;
}

bool FlameDeveloper::take(std::vector<std::uint8_t>& rgba, int& width, int& height) {
  auto published = job_.poll();
  if (!published) return false;
  Output& out = published->value;
  error_ = out.error;
  lastMs_ = out.ms;
  if (!out.error.empty()) return false;
  plot_ = std::move(out.plot);
  rgba.swap(out.rgba);
  width = out.width;
  height = out.height;
  return true;
}

void FlameDeveloper::develop(const Input& input, DevelopJob::Context& context) {
  // A develop is short (tens of ms) and never superseded (submit() waits for it), so it runs
  // to the end without polling stale().
  const auto start = std::chrono::steady_clock::now();
  Output out;
  out.width = input.snapshot.width;
  out.height = input.snapshot.height;
  try {
    const FlameImage image = developFlameSnapshot(input.snapshot, input.settings, input.camera, out.width, out.height,
                                                  input.background, false, 1);
    flameImageToRgba8(image, out.rgba);
    // The histogram of figure 4 and the scale the develop used (one pass over the hit counts).
    out.plot.histogram = densityHistogram(input.snapshot.density);
    out.plot.scale = densityScale(input.settings, double(std::max<std::int64_t>(1, input.snapshot.stats.samples)),
                                  flamePixelsPerUnit(input.camera, out.height) * input.settings.density_unit,
                                  double(out.plot.histogram.maxHits));
    out.plot.valid = true;
  } catch (const std::exception& e) {
    out.error = e.what();
  }
  out.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  context.publish(std::move(out));
}

}  // namespace gridifs::ui
