#pragma once
// Internal to the renderer: the plotter of the shaded display. Each chaos-game sample is plotted
// into the camera's z-buffer as ZBufferPlot does and, a chunk of samples later, into one depth buffer per
// shadowed light (one extra projection per sample and light: Williams 1978, shadow maps filled by
// the samples themselves). Depth of field moves each sample, before the camera plot, by a random
// point of a disc of radius aperture · |depth − focus| in the image plane — a chaos-game effect
// that costs no extra pass (as IFSRenderer does it).
#include "render/chaos_kernel.h"
#include "render/light_view.h"

namespace gridifs::kernel {

inline constexpr int kMaxShadowLights = 3;

/// Light depths are stored as 16-bit steps of the light view's depth range [0, 2·radius]
/// (kLightEmpty: no sample): a step is 1/128 of a texel even at 512² texels, far below the shadow
/// test's bias, and a quarter of a 64-bit key's bytes keeps the randomly written maps in cache.
inline constexpr std::uint16_t kLightEmpty = 0xFFFF;
inline constexpr float kLightSteps = 65534.0f;

/// A light's rows for the hot loop: r = cx·x + cy·y + cz·z + c1 gives (u, v, depth step, 0).
struct HotLight {
  v4f cx, cy, cz, c1;
  std::uint16_t* depth = nullptr;  // size × size nearest light depths in steps; kLightEmpty empty
};

/// World units of light depth per stored step.
inline double lightDepthStep(const LightView& view) { return 2.0 * view.bounds().radius / double(kLightSteps); }

inline HotLight makeHotLight(const LightView& view, std::uint16_t* depth) {
  const LightView::Rows rows = view.rows();
  const float steps = float(1.0 / lightDepthStep(view));
  HotLight h{};
  v4f* columns[4] = {&h.cx, &h.cy, &h.cz, &h.c1};
  for (int c = 0; c < 4; ++c) *columns[c] = v4f{rows.rowU[c], rows.rowV[c], rows.rowD[c] * steps, 0.0f};
  h.depth = depth;
  return h;
}

/// Depth-of-field jitter: the camera's view axes in world space and the lens.
struct HotLens {
  v4f right, up;  // world unit vectors of the image plane
  v4f depthRow;   // view depth = dot(depthRow, (x, y, z, 1))
  float aperture = 0.0f, focus = 0.0f;
};

/// The light half of the shaded plotter. Samples are collected in chunks and projected into each
/// light's map a chunk at a time, away from the chaos game's loop: the loop only stores the point,
/// and the projection runs as a tight loop per light that prefetches every texel of the chunk before
/// it writes any (the maps are larger than the caches; a minimum does not depend on the order, so
/// the maps are those of plotting sample by sample). On its own it is the plotter of a light-only
/// pass (the chaos game replayed to re-fill the maps of lights that moved, the camera's buffers kept).
struct LightPlot {
  HotLight lights[kMaxShadowLights] = {};
  int lightCount = 0;
  float lightSize = 0.0f;  // texels per side
  std::uint32_t lightStride = 0;

  static constexpr int kChunk = 256;
  v4f points[kChunk];
  int count = 0;

  /// Projects the collected points into every light's map.
  void drain() {
    std::uint32_t texels[kChunk];
    std::uint16_t keys[kChunk];
    const v4f size = {lightSize, lightSize, 1.0f, 1.0f};
    for (int l = 0; l < lightCount; ++l) {
      const HotLight& light = lights[l];
      int m = 0;
      for (int i = 0; i < count; ++i) {
        const v4f q = points[i];
        const v4f r = light.cx * splat<0>(q) + light.cy * splat<1>(q) + light.cz * splat<2>(q) + light.c1;
        const bool inside = (laneMask((r >= v4f{}) & (r < size)) & 3) == 3;  // NaN fails too
        const v4i iuv = __builtin_convertvector(inside ? r : v4f{}, v4i);
        texels[m] = std::uint32_t(iuv[1]) * lightStride + std::uint32_t(iuv[0]);
        // Clamped for rounding at the sphere's edges; truncation stores a step nearer the light.
        keys[m] = std::uint16_t(std::min(std::max(r[2], 0.0f), kLightSteps));
        __builtin_prefetch(light.depth + texels[m], 1);
        m += inside;
      }
      for (int i = 0; i < m; ++i) {
        std::atomic_ref<std::uint16_t> z(light.depth[texels[i]]);
        if (keys[i] < z.load(std::memory_order_relaxed)) z.store(keys[i], std::memory_order_relaxed);
      }
    }
    count = 0;
  }

  void flush() { drain(); }

  [[gnu::always_inline]] void add(v4f q) {
    if (lightCount == 0) return;
    points[count++] = q;
    if (count == kChunk) [[unlikely]]
      drain();
  }

  /// As a plotter of its own (the light-only pass): every sample counts as plotted.
  [[gnu::always_inline]] int operator()(v4f q, v4f) {
    add(q);
    return 1;
  }
};

template <bool kAccumulateColor>
struct ShadedPlot {
  ZBufferPlot<kAccumulateColor> camera;
  LightPlot light;
  HotLens lens;
  bool jitter = false;
  Rng rng;  // the lens samples: its own stream, so the chaos game's sequence is unchanged

  void flush() {
    camera.flush();
    light.flush();
  }

  [[gnu::always_inline]] int operator()(v4f q, v4f col) {
    light.add(q);  // before the lens: the light buffers do not depend on it
    if (jitter) {
      const v4f d = lens.depthRow * q;
      const float depth = d[0] + d[1] + d[2] + lens.depthRow[3];
      const float radius = lens.aperture * (depth > lens.focus ? depth - lens.focus : lens.focus - depth);
      // A uniform point of the unit disc by rejection from the square (π/4 accepted on average).
      float x, y;
      do {
        const std::uint64_t bits = rng.next();
        x = Rng::signedUnit(bits);
        y = Rng::signedUnit(bits >> 32);
      } while (x * x + y * y > 1.0f);
      q = q + lens.right * (x * radius) + lens.up * (y * radius);
    }
    return camera(q, col);
  }
};

}  // namespace gridifs::kernel
