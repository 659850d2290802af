#pragma once
// What the chaos game leaves in a renderer's buffers before anything is developed from it: the
// z-buffer keys, hit counts, fixed-point colour sums and the shadow maps' depths. Every field
// combines exactly and in any order (a minimum or an integer sum), so the accumulations of render
// parts (gridifs render --part) add up to the accumulation of the whole render, bit for bit, and
// developing the sum (toRenderImage) gives the image a single render gives.
//
// Not thread-safe; a value type.
#include <cstdint>
#include <string>
#include <vector>

#include "render/light_view.h"

namespace gridifs {

struct RenderImage;
struct DisplaySettings;

/// Colour sums are fixed point with this many fraction bits: each sample adds round(v · 2^16) per
/// channel, v clamped to [0, 1] (the same on the CPU and the GPU). 64-bit sums hold 2^48 hits.
inline constexpr double kColorFixedScale = 65536.0;

struct Accumulation {
  int width = 0, height = 0;
  /// The z-buffer, one of two forms. `keys`: 64-bit keys (view-depth bits << 32 | packed r g b c,
  /// r in the low byte; ~0 where no point), from the CPU and GPUs with 64-bit atomics. `keys32`:
  /// a GPU's 32-bit keys (16-bit depth step << 16 | RGB565; ~0 where none), the depth step being
  /// depthMin + step / depthScale.
  std::vector<std::uint64_t> keys;
  std::vector<std::uint32_t> keys32;
  float depthMin = 0.0f, depthScale = 0.0f;
  std::vector<std::uint32_t> density;    // hits per pixel, saturating at 2^32 − 1
  std::vector<std::uint64_t> colorSums;  // 4 per pixel (Σr, Σg, Σb, Σc), fixed point; empty without colour
  std::vector<LightView> lightViews;     // the shadowed lights' views
  std::vector<std::vector<std::uint16_t>> lightDepth;  // per light, size² depth steps (0xFFFF: none)
  std::int64_t samples = 0, badSamples = 0, plotted = 0;

  /// Adds `other` in: keys and light depths by minimum, counts and sums by addition. Throws
  /// std::invalid_argument when the two do not have the same size, key form, colour and lights.
  void add(const Accumulation& other);
  /// Why `other` cannot be added to this one, or "" when it can.
  std::string mismatch(const Accumulation& other) const;
};

/// Develops `acc` into an image as the renderers' snapshots do: depth and packed colour from the
/// nearest key, density, colour sums as floats, the depth range, the light depth buffers, then
/// depth cueing over the background (shadeRenderImage). `stats` gets samples, bad and plotted.
void toRenderImage(const Accumulation& acc, const DisplaySettings& display, RenderImage& out);

}  // namespace gridifs
