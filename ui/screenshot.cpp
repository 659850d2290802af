#include "ui/screenshot.h"

#include <epoxy/gl.h>

#include <OpenImageIO/imageio.h>

#include <cstring>
#include <vector>

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
  auto out = OIIO::ImageOutput::create(file);
  if (!out) return "cannot write " + file + ": " + OIIO::geterror();
  const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  if (!out->open(file, spec) || !out->write_image(OIIO::TypeDesc::UINT8, flipped.data()) || !out->close())
    return "cannot write " + file + ": " + out->geterror();
  return {};
}

}  // namespace gridifs::ui
