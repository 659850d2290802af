#pragma once
// A small picture of a project as the preview draws it in its display mode (the flame display
// develops its histogram; the others show the z-buffer), for the Explore window's grid of variants
// and anything else that shows many projects at once.
//
// Thread-safety: touches only its arguments; several may run at once on separate threads.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "model/project.h"
#include "render/renderer.h"

namespace gridifs {

struct Thumbnail {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // 4 per pixel, rows top first
};

/// Renders `project` at width × height with `samples` chaos-game samples on `threads` threads, or
/// on `renderer` when one is given (the GPU compute renderer, which the caller opened); relative
/// set and palette files are found in `folder`. Returns an empty thumbnail when `cancel` was set
/// meanwhile. Throws ModelError when the project cannot be rendered.
Thumbnail renderThumbnail(const Project& project, const std::filesystem::path& folder, int width, int height,
                          std::int64_t samples, int threads = 1, const std::atomic<bool>* cancel = nullptr,
                          Renderer* renderer = nullptr);

}  // namespace gridifs
