#include "render/accumulation.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "render/chaos_renderer.h"
#include "render/shaded_plot.h"

namespace gridifs {

std::string Accumulation::mismatch(const Accumulation& other) const {
  if (width != other.width || height != other.height)
    return "a " + std::to_string(other.width) + "×" + std::to_string(other.height) +
           " accumulation cannot be added to a " + std::to_string(width) + "×" + std::to_string(height) + " one";
  if (keys.empty() != other.keys.empty() || keys32.empty() != other.keys32.empty())
    return "the z-buffers have different key forms (64-bit and 32-bit keys)";
  if (!keys32.empty() && (depthMin != other.depthMin || depthScale != other.depthScale))
    return "the 32-bit z-buffers quantize depth differently";
  if (colorSums.empty() != other.colorSums.empty()) return "one accumulation has colour sums and the other none";
  if (lightViews != other.lightViews) return "the shadowed lights differ";
  return "";
}

void Accumulation::add(const Accumulation& other) {
  if (const std::string why = mismatch(other); !why.empty()) throw std::invalid_argument(why);
  for (std::size_t i = 0; i < keys.size(); ++i) keys[i] = std::min(keys[i], other.keys[i]);
  for (std::size_t i = 0; i < keys32.size(); ++i) keys32[i] = std::min(keys32[i], other.keys32[i]);
  for (std::size_t i = 0; i < density.size(); ++i) {
    const std::uint64_t sum = std::uint64_t(density[i]) + other.density[i];
    density[i] = std::uint32_t(std::min<std::uint64_t>(sum, 0xFFFFFFFFu));  // saturating, as the plotters
  }
  for (std::size_t i = 0; i < colorSums.size(); ++i) colorSums[i] += other.colorSums[i];
  for (std::size_t l = 0; l < lightDepth.size(); ++l)
    for (std::size_t i = 0; i < lightDepth[l].size(); ++i)
      lightDepth[l][i] = std::min(lightDepth[l][i], other.lightDepth[l][i]);
  samples += other.samples;
  badSamples += other.badSamples;
  plotted += other.plotted;
}

void toRenderImage(const Accumulation& acc, const DisplaySettings& display, RenderImage& out) {
  const std::size_t n = std::size_t(acc.width) * std::size_t(acc.height);
  out.width = acc.width;
  out.height = acc.height;
  out.rgba.resize(n * 4);
  out.depth.resize(n);
  out.density = acc.density;
  out.density.resize(n, 0);
  // Pass 1: depth and packed colour of the nearest point; the packed colour waits in `rgba`
  // (4 bytes per pixel) for shadeRenderImage.
  std::uint32_t* packed = reinterpret_cast<std::uint32_t*>(out.rgba.data());
  float minDepth = std::numeric_limits<float>::infinity(), maxDepth = -minDepth;
  std::int64_t hits = 0;
  auto keep = [&](std::size_t i, float depth, std::uint32_t colour) {
    out.depth[i] = depth;
    packed[i] = colour;
    if (depth == std::numeric_limits<float>::infinity()) return;
    minDepth = std::min(minDepth, depth);
    maxDepth = std::max(maxDepth, depth);
    ++hits;
  };
  constexpr float kNone = std::numeric_limits<float>::infinity();
  if (acc.keys.size() == n) {
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint64_t key = acc.keys[i];
      if (key == ~std::uint64_t(0))
        keep(i, kNone, 0);
      else
        keep(i, std::bit_cast<float>(std::uint32_t(key >> 32)), std::uint32_t(key));
    }
  } else if (acc.keys32.size() == n) {
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t key = acc.keys32[i];
      if (key == 0xFFFFFFFFu) {
        keep(i, kNone, 0);
        continue;
      }
      const float depth = acc.depthMin + (acc.depthScale > 0.0f ? float(key >> 16) / acc.depthScale : 0.0f);
      const std::uint32_t c5r = (key >> 11) & 31u, c6g = (key >> 5) & 63u, c5b = key & 31u;
      keep(i, depth, (c5r * 255u + 15u) / 31u | ((c6g * 255u + 31u) / 63u) << 8 | ((c5b * 255u + 15u) / 31u) << 16);
    }
  } else {
    for (std::size_t i = 0; i < n; ++i) keep(i, kNone, 0);
  }
  if (acc.colorSums.size() == n * 4) {
    out.colorSums.resize(n * 4);
    for (std::size_t i = 0; i < n * 4; ++i)
      out.colorSums[i] = float(double(acc.colorSums[i]) * (1.0 / kColorFixedScale));
  } else {
    out.colorSums.clear();
  }
  // The light depth buffers as view depths (the nearest sample per texel; +inf where none).
  out.lightViews = acc.lightViews;
  out.lightDepth.resize(acc.lightDepth.size());
  for (std::size_t l = 0; l < acc.lightDepth.size(); ++l) {
    const float step = float(kernel::lightDepthStep(acc.lightViews[l]));
    const std::vector<std::uint16_t>& src = acc.lightDepth[l];
    std::vector<float>& dst = out.lightDepth[l];
    dst.resize(src.size());
    for (std::size_t i = 0; i < src.size(); ++i)
      dst[i] = src[i] == kernel::kLightEmpty ? std::numeric_limits<float>::infinity() : float(src[i]) * step;
  }
  out.hitPixels = hits;
  out.minDepth = hits ? minDepth : 0.0f;
  out.maxDepth = hits ? maxDepth : 0.0f;
  out.stats.samples = acc.samples;
  out.stats.badSamples = acc.badSamples;
  out.stats.plotted = acc.plotted;
  shadeRenderImage(out, display);
}

}  // namespace gridifs
