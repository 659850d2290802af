#include "ui/gl/screenshot.h"

#include <epoxy/gl.h>

#include <cstring>
#include <vector>

#include "base/errors.h"
#include "render/image_file.h"

namespace gridifs::ui {

std::string writeFramebuffer(const std::string& file, int width, int height) {
  if (width < 1 || height < 1) return "the window has no pixels to capture";
  std::vector<unsigned char> pixels(std::size_t(width) * height * 3);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  // OpenGL's row 0 is the bottom row; image files start at the top.
  const std::size_t row = std::size_t(width) * 3;
  std::vector<unsigned char> flipped(pixels.size());
  for (int y = 0; y < height; ++y)
    std::memcpy(flipped.data() + std::size_t(y) * row, pixels.data() + std::size_t(height - 1 - y) * row, row);
  ImageFileLayout layout;
  layout.width = width;
  layout.height = height;
  layout.channels = {"R", "G", "B"};
  try {
    writeImageFile(file, layout, flipped.data());
  } catch (const IoError& e) {
    return e.what();
  }
  return {};
}

}  // namespace gridifs::ui
