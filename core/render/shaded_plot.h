#pragma once
// Internal to the renderer: the plotter of the shaded display. Each chaos-game sample is plotted
// into the camera's z-buffer as ZBufferPlot does and, in the same step, into one depth buffer per
// shadowed light (one extra projection per sample and light: Williams 1978, shadow maps filled by
// the samples themselves). Depth of field moves each sample, before the camera plot, by a random
// point of a disc of radius aperture · |depth − focus| in the image plane — a chaos-game effect
// that costs no extra pass (as IFSRenderer does it).
#include "render/chaos_kernel.h"
#include "render/light_view.h"

namespace gridifs::kernel {

inline constexpr int kMaxShadowLights = 3;

/// A light's rows for the hot loop: r = cx·x + cy·y + cz·z + c1 gives (u, v, depth, 0).
struct HotLight {
  v4f cx, cy, cz, c1;
  std::uint32_t* depth = nullptr;  // size × size float bits of the nearest light depth; ~0u empty
};

inline HotLight makeHotLight(const LightView& view, std::uint32_t* depth) {
  const LightView::Rows rows = view.rows();
  HotLight h{};
  v4f* columns[4] = {&h.cx, &h.cy, &h.cz, &h.c1};
  for (int c = 0; c < 4; ++c) *columns[c] = v4f{rows.rowU[c], rows.rowV[c], rows.rowD[c], 0.0f};
  h.depth = depth;
  return h;
}

/// Depth-of-field jitter: the camera's view axes in world space and the lens.
struct HotLens {
  v4f right, up;  // world unit vectors of the image plane
  v4f depthRow;   // view depth = dot(depthRow, (x, y, z, 1))
  float aperture = 0.0f, focus = 0.0f;
};

template <bool kAccumulateColor>
struct ShadedPlot {
  ZBufferPlot<kAccumulateColor> camera;
  HotLight lights[kMaxShadowLights] = {};
  int lightCount = 0;
  float lightSize = 0.0f;  // texels per side
  std::uint32_t lightStride = 0;
  HotLens lens;
  bool jitter = false;
  Rng rng;  // the lens samples: its own stream, so the chaos game's sequence is unchanged

  /// Light-buffer writes are deferred behind a prefetch as the camera's are (the maps are larger
  /// than the caches); the minimum does not depend on the order.
  static constexpr unsigned kDefer = 8;
  struct Pending {
    std::uint32_t* texel = nullptr;
    std::uint32_t key = 0;
  };
  Pending pending[kDefer] = {};
  unsigned next = 0;

  [[gnu::always_inline]] static void commit(std::uint32_t* texel, std::uint32_t key) {
    std::atomic_ref<std::uint32_t> z(*texel);
    if (key < z.load(std::memory_order_relaxed)) z.store(key, std::memory_order_relaxed);
  }

  void flush() {
    camera.flush();
    for (Pending& p : pending)
      if (p.texel) {
        commit(p.texel, p.key);
        p.texel = nullptr;
      }
  }

  [[gnu::always_inline]] void plotLight(const HotLight& light, v4f q) {
    const v4f r = light.cx * splat<0>(q) + light.cy * splat<1>(q) + light.cz * splat<2>(q) + light.c1;
    const v4f size = {lightSize, lightSize, 1.0f, 1.0f};
    if ((laneMask((r >= v4f{}) & (r < size)) & 3) != 3) return;  // NaN fails too
    const v4i iuv = __builtin_convertvector(r, v4i);
    std::uint32_t* texel = light.depth + std::size_t(std::uint32_t(iuv[1])) * lightStride + std::uint32_t(iuv[0]);
    const float depth = r[2] > 0.0f ? r[2] : 0.0f;  // rounding at the sphere's edge
    __builtin_prefetch(texel, 1);
    Pending& slot = pending[next++ % kDefer];
    if (slot.texel) commit(slot.texel, slot.key);
    slot = {texel, std::bit_cast<std::uint32_t>(depth)};
  }

  [[gnu::always_inline]] int operator()(v4f q, v4f col) {
    for (int l = 0; l < lightCount; ++l) plotLight(lights[l], q);
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
