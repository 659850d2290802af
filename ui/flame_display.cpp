#include "ui/flame_display.h"

#include <chrono>
#include <memory>

#include "render/flame_render.h"
#include "flame/palette.h"

namespace gridifs::ui {

FlameDeveloper::FlameDeveloper() : thread_([this] { run(); }) {}

FlameDeveloper::~FlameDeveloper() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

bool FlameDeveloper::submit(const RenderImage& snapshot, const FlameSettings& settings, const Camera& camera,
                            const Vec3& background) {
  {
    std::lock_guard lock(mutex_);
    if (pending_ || working_) return false;
    input_ = snapshot;  // reuses the worker's buffers (same size most of the time)
    settings_ = settings;
    settings_.supersample = 1;
    camera_ = camera;
    background_ = background;
    pending_ = true;
  }
  wake_.notify_all();
  return true;
}

bool FlameDeveloper::take(std::vector<std::uint8_t>& rgba, int& width, int& height) {
  std::lock_guard lock(mutex_);
  if (!ready_) return false;
  rgba.swap(output_);
  width = outWidth_;
  height = outHeight_;
  ready_ = false;
  return true;
}

bool FlameDeveloper::busy() const {
  std::lock_guard lock(mutex_);
  return pending_ || working_;
}

std::string FlameDeveloper::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

double FlameDeveloper::lastMs() const {
  std::lock_guard lock(mutex_);
  return lastMs_;
}

void FlameDeveloper::run() {
  std::vector<std::uint8_t> texels;
  for (;;) {
    std::unique_lock lock(mutex_);
    wake_.wait(lock, [this] { return stop_ || pending_; });
    if (stop_) return;
    pending_ = false;
    working_ = true;
    lock.unlock();
    // input_ and the settings are only written by submit() while neither pending nor working.
    const auto start = std::chrono::steady_clock::now();
    std::string error;
    int w = input_.width, h = input_.height;
    try {
      const FlameImage image = developFlameSnapshot(input_, settings_, camera_, w, h, background_, false, 1);
      flameImageToRgba8(image, texels);
    } catch (const std::exception& e) {
      error = e.what();
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    lock.lock();
    working_ = false;
    error_ = error;
    lastMs_ = ms;
    if (error.empty()) {
      output_.swap(texels);
      outWidth_ = w;
      outHeight_ = h;
      ready_ = true;
    }
  }
}

}  // namespace gridifs::ui
