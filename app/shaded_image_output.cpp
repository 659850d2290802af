#include "app/shaded_image_output.h"

#include <OpenImageIO/imageio.h>

#include "app/cli.h"
#include "app/render_setup.h"
#include "base/atomic_file.h"

namespace gridifs::cli {
namespace {

/// The Z value of pixels without points (Blender's convention for "background"), as `render` writes.
constexpr float kEmptyZ = 1e10f;

}  // namespace

void writeShadedImage(const ShadedImage& image, const RenderImage& snapshot, const std::filesystem::path& out,
                      const std::string& description) {
  const std::string ext = lowerExtension(out);
  AtomicFile output(out);
  const std::string temp = output.temporaryPath().string();
  auto writer = OIIO::ImageOutput::create(temp);
  if (!writer) throw CliError(kFailure, "cannot write " + out.string() + ": " + OIIO::geterror());
  const std::size_t n = std::size_t(image.width) * std::size_t(image.height);
  bool ok = false;
  if (ext == "exr") {
    constexpr int kChannels = 10;
    OIIO::ImageSpec spec(image.width, image.height, kChannels, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"R", "G", "B", "A", "Z", "N.x", "N.y", "N.z", "AO", "shadow"};
    spec.alpha_channel = 3;
    spec.z_channel = 4;
    spec.attribute("Software", "GridIFS");
    spec.attribute("ImageDescription", description);
    spec.attribute("compression", "zip");
    std::vector<float> pixels(n * kChannels);
    for (std::size_t i = 0; i < n; ++i) {
      float* px = &pixels[i * kChannels];
      for (int c = 0; c < 4; ++c) px[c] = image.linear[i * 4 + std::size_t(c)];
      const bool hit = image.rgba[i * 4 + 3] != 0;
      px[4] = hit ? snapshot.depth[i] : kEmptyZ;
      for (int c = 0; c < 3; ++c) px[5 + c] = image.normals[i * 3 + std::size_t(c)];
      px[8] = image.occlusion[i];
      px[9] = image.shadow[i];
    }
    ok = writer->open(temp, spec) && writer->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) && writer->close();
  } else {
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("Software", "GridIFS");
    spec.attribute("ImageDescription", description);
    if (ext == "tif" || ext == "tiff") spec.attribute("compression", "zip");
    std::vector<std::uint8_t> pixels(n * 3);
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) pixels[i * 3 + std::size_t(c)] = image.rgba[i * 4 + std::size_t(c)];
    ok = writer->open(temp, spec) && writer->write_image(OIIO::TypeDesc::UINT8, pixels.data()) && writer->close();
  }
  if (!ok) {
    std::string message = writer->geterror();
    if (message.empty()) message = "the image library reported an error";
    while (!message.empty() && message.back() == '\n') message.pop_back();
    throw CliError(kFailure, "cannot write " + out.string() + ": " + message);
  }
  writer.reset();
  try {
    output.commit();
  } catch (const IoError& e) {
    throw CliError(kFailure, e.what());
  }
}

}  // namespace gridifs::cli
