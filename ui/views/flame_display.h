#pragma once
// The flame display of the preview (Draves & Reckase 2003, §4–8): the same chaos game as the
// z-buffer preview, with color sums always accumulated, developed into a flame image on a worker
// thread every few hundred milliseconds, so switching modes never restarts the renderer and
// developing never blocks the UI (docs/FLAME.md "For the GUI").
#include <cstdint>
#include <string>
#include <vector>

#include "base/background_job.h"
#include "edit/document.h"
#include "model/flame_settings.h"
#include "render/chaos_renderer.h"
#include "tone/density_histogram.h"

namespace gridifs::ui {

/// What the tone popup's density plot draws (Draves & Reckase 2003, figure 4): the pixels by
/// density of the last develop and the density scale it used.
struct DensityPlotData {
  DensityHistogram histogram;
  LogDensityScale scale;
  bool valid = false;
};

/// Develops renderer snapshots into RGBA8 flame images on one worker thread (a BackgroundJob).
/// UI thread only; submit() and take() never wait for a develop.
class FlameDeveloper {
 public:
  /// Hands a copy of `snapshot` to the worker; false (nothing copied) while it is still busy, so
  /// a develop is never superseded half-way and the picture keeps coming while points stream.
  bool submit(const RenderImage& snapshot, const FlameSettings& settings, const Camera& camera, const Vec3& background);
  /// The newest finished image, once: true and `rgba`/size filled when there is one. A failed
  /// develop sets error() and returns false.
  bool take(std::vector<std::uint8_t>& rgba, int& width, int& height);
  bool busy() const { return job_.busy(); }
  /// Why the last develop failed ("" when it did not).
  const std::string& error() const { return error_; }
  /// Milliseconds the last develop took.
  double lastMs() const { return lastMs_; }
  /// The density histogram of the last develop taken.
  const DensityPlotData& densityPlot() const { return plot_; }

 private:
  struct Input {
    RenderImage snapshot;
    FlameSettings settings;
    Camera camera;
    Vec3 background{0.0};
  };
  struct Output {
    std::vector<std::uint8_t> rgba;
    int width = 0, height = 0;
    std::string error;
    double ms = 0.0;
    DensityPlotData plot;
  };
  using DevelopJob = BackgroundJob<Input, Output>;
  static void develop(const Input& input, DevelopJob::Context& context);

  // UI-thread state: what the last develop taken said.
  std::string error_;
  double lastMs_ = 0.0;
  DensityPlotData plot_;
  DevelopJob job_{&FlameDeveloper::develop};  // last: destroyed first, it joins the worker
};

/// What the preview texture shows in flame mode: decides when to develop (at once after an
/// edit or a settings change, then every ~300 ms while points stream in) and uploads results.
class FlameDisplay {
 public:
  /// Called every frame in flame mode after the renderer fetch (`fetched`: `image` changed).
  /// Returns true when the texture was re-uploaded.
  template <class Upload>
  bool update(const Document& document, double now, const RenderImage& image, bool fetched, Upload upload);
  /// Forget what was developed (the next update develops at once).
  void invalidate() { developedSamples_ = -1; }
  const FlameDeveloper& developer() const { return developer_; }
  std::uint64_t developed() const { return developed_; }

 private:
  FlameDeveloper developer_;
  std::vector<std::uint8_t> rgba_;
  std::int64_t developedSamples_ = -1;
  std::uint64_t developedGeneration_ = 0;
  FlameSettings developedSettings_;
  Vec3 developedBackground_{-1.0};
  double lastSubmit_ = -1.0;
  std::uint64_t developed_ = 0;
};

template <class Upload>
bool FlameDisplay::update(const Document& document, double now, const RenderImage& image, bool, Upload upload) {
  bool uploaded = false;
  int w = 0, h = 0;
  if (developer_.take(rgba_, w, h)) {
    upload(w, h, rgba_.data());
    ++developed_;
    uploaded = true;
  }
  if (image.width <= 0 || image.colorSums.empty()) return uploaded;
  const Project& p = document.project();
  // While a slider or the camera is dragged, develop without density estimation (docs/FLAME.md:
  // about half the cost), so the picture follows the hand; the full develop follows on release.
  FlameSettings settings = p.render.flame;
  if (document.inGesture()) settings.estimator_radius = 0.0;
  const bool changed = image.generation != developedGeneration_ || !(settings == developedSettings_) ||
                       !(p.render.background == developedBackground_) || developedSamples_ < 0;
  const bool more = image.stats.samples != developedSamples_;
  // A few hundred ms between develops while the picture streams (docs/FLAME.md: 60–130 ms of CPU
  // at 1024² with density estimation); a settings change or a new generation develops at once.
  if ((changed || (more && now - lastSubmit_ >= 0.3)) && !developer_.busy()) {
    if (developer_.submit(image, settings, p.camera, p.render.background)) {
      developedGeneration_ = image.generation;
      developedSamples_ = image.stats.samples;
      developedSettings_ = settings;
      developedBackground_ = p.render.background;
      lastSubmit_ = now;
    }
  }
  return uploaded;
}

}  // namespace gridifs::ui
