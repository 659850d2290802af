#include "render/field_image.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "render/image_file.h"

namespace gridifs {
namespace {

std::uint8_t byteOf(double c) { return std::uint8_t(std::lround(std::clamp(c, 0.0, 1.0) * 255.0)); }

}  // namespace

std::vector<std::uint8_t> colourFieldPlanes(const std::vector<FieldPlane>& planes, int size, const Palette& palette) {
  const auto n = std::size_t(size);
  std::vector<double> rgb(n * n * 3, 0.0);
  const auto ground = std::find_if(planes.begin(), planes.end(), [&](const FieldPlane& p) {
    return p.role != FieldRole::Cloud || planes.size() == 1;
  });
  if (ground != planes.end()) {
    const auto [lo, hi] = std::minmax_element(ground->values.begin(), ground->values.end());
    const double range = *hi - *lo;
    for (std::size_t v = 0; v < n * n; ++v) {
      const Rgb c = palette.lookup(range > 0.0 ? (ground->values[v] - *lo) / range : 0.5);
      rgb[3 * v] = c.r;
      rgb[3 * v + 1] = c.g;
      rgb[3 * v + 2] = c.b;
    }
  }
  for (auto plane = planes.begin(); plane != planes.end(); ++plane) {
    if (plane == ground || plane->role != FieldRole::Cloud) continue;
    for (std::size_t v = 0; v < n * n; ++v) {
      const double a = std::clamp(plane->strength * plane->values[v], 0.0, 1.0);
      for (int c = 0; c < 3; ++c) rgb[3 * v + std::size_t(c)] += a * (1.0 - rgb[3 * v + std::size_t(c)]);
    }
  }
  std::vector<std::uint8_t> pixels(n * n * 3);
  for (std::size_t row = 0; row < n; ++row) {
    const std::size_t j = n - 1 - row;  // the image's top row is y = +1
    for (std::size_t i = 0; i < n * 3; ++i) pixels[row * n * 3 + i] = byteOf(rgb[j * n * 3 + i]);
  }
  return pixels;
}

bool isRawFieldImage(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".exr";
}

void writeFieldImage(const std::filesystem::path& file, const std::vector<FieldPlane>& planes, int size,
                     const Palette& palette) {
  ImageFileLayout layout;
  layout.width = layout.height = size;
  layout.description = "GridIFS fractal field";
  if (!isRawFieldImage(file)) {
    layout.channels = {"R", "G", "B"};
    const std::vector<std::uint8_t> pixels = colourFieldPlanes(planes, size, palette);
    writeImageFile(file, layout, pixels.data());
    return;
  }
  const auto n = std::size_t(size);
  for (const FieldPlane& plane : planes) layout.channels.push_back(plane.name);
  layout.stored = StoredSample::Float;
  const std::size_t channels = planes.size();
  std::vector<float> pixels(n * n * channels);
  for (std::size_t row = 0; row < n; ++row)
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t c = 0; c < channels; ++c)
        pixels[(row * n + i) * channels + c] = float(planes[c].values[(n - 1 - row) * n + i]);
  writeImageFile(file, layout, pixels.data());
}

}  // namespace gridifs
