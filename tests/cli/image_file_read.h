#pragma once
// An image file as the CLI tests read it back: every channel as float, with its channel names.
#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <string>
#include <vector>

namespace gridifs::test_support {

struct ImageFile {
  int width = 0, height = 0, channels = 0;
  std::vector<std::string> names;
  std::vector<float> pixels;
};

/// The file's pixels (empty when it cannot be read). `straightAlpha`: the file's own values, as
/// PNG keeps them; otherwise OpenImageIO premultiplies colour by alpha on reading.
inline ImageFile readImageFile(const std::filesystem::path& file, bool straightAlpha = false) {
  ImageFile image;
  OIIO::ImageSpec config;
  if (straightAlpha) config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(file.string(), &config);
  if (!in) return image;
  const OIIO::ImageSpec& spec = in->spec();
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.nchannels;
  image.names = spec.channelnames;
  image.pixels.resize(std::size_t(spec.width) * spec.height * spec.nchannels);
  in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data());
  return image;
}

}  // namespace gridifs::test_support
