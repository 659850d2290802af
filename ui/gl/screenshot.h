#pragma once
// Reads the window's framebuffer back and writes it as an image (render/image_file:
// OpenImageIO; `--screenshot`). Call after ImGui has rendered and before the buffers are swapped.
#include <string>

namespace gridifs::ui {

/// Writes the current back buffer (width × height pixels) to `file` (PNG, or any format
/// OpenImageIO knows by extension). Returns an error sentence, or empty on success.
std::string writeFramebuffer(const std::string& file, int width, int height);

}  // namespace gridifs::ui
