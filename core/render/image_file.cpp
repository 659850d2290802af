#include "render/image_file.h"

#include <OpenImageIO/imageio.h>

#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/text_format.h"

namespace gridifs {
namespace {

OIIO::TypeDesc typeOf(StoredSample s) {
  switch (s) {
    case StoredSample::UInt8:
      return OIIO::TypeDesc::UINT8;
    case StoredSample::UInt16:
      return OIIO::TypeDesc::UINT16;
    case StoredSample::Half:
      return OIIO::TypeDesc::HALF;
    case StoredSample::Float:
      return OIIO::TypeDesc::FLOAT;
  }
  return OIIO::TypeDesc::UINT8;
}

void write(const std::filesystem::path& file, const ImageFileLayout& layout, OIIO::TypeDesc given, const void* pixels) {
  OIIO::ImageSpec spec(layout.width, layout.height, int(layout.channels.size()), typeOf(layout.stored));
  spec.channelnames = layout.channels;
  spec.alpha_channel = layout.alphaChannel;
  spec.z_channel = layout.zChannel;
  spec.attribute("Software", "GridIFS");
  if (!layout.description.empty()) spec.attribute("ImageDescription", layout.description);
  const std::string ext = lowerExtension(file);
  if (ext == "exr" || ext == "tif" || ext == "tiff") spec.attribute("compression", "zip");
  AtomicFile atomic(file);
  const std::string temporary = atomic.temporaryPath().string();
  auto out = OIIO::ImageOutput::create(temporary);
  if (!out) throw IoError("cannot write " + file.string() + ": " + OIIO::geterror());
  const bool ok = out->open(temporary, spec) && out->write_image(given, pixels) && out->close();
  if (!ok) {
    std::string message = out->geterror();
    if (message.empty()) message = "the image library reported an error";
    while (!message.empty() && message.back() == '\n') message.pop_back();
    throw IoError("cannot write " + file.string() + ": " + message);
  }
  out.reset();
  atomic.commit();
}

}  // namespace

void writeImageFile(const std::filesystem::path& file, const ImageFileLayout& layout, const std::uint8_t* pixels) {
  write(file, layout, OIIO::TypeDesc::UINT8, pixels);
}

void writeImageFile(const std::filesystem::path& file, const ImageFileLayout& layout, const float* pixels) {
  write(file, layout, OIIO::TypeDesc::FLOAT, pixels);
}

}  // namespace gridifs
