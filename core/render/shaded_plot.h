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

/// Depth-of-field jitter: the camera's view axes in world space and the lens. A sample at view
/// depth d moves in the image plane by at most aperture · |d − focus| world units.
struct HotLens {
  v4f right, up;  // world unit vectors of the image plane
  v4f depthRow;   // view depth = dot(depthRow, (x, y, z, 1))
  float aperture = 0.0f, focus = 0.0f;
  /// false: a uniform point of that disc (a thin lens: the shaded display's depth of field).
  /// true: a uniform angle and a uniform distance up to the radius, as the flame camera's
  /// cam_dof draws them (Apophysis 7X's 3D camera; the camera's lens_blur).
  bool uniformRadius = false;
};

/// The light half of the shaded plotter. Samples are collected in chunks and projected into the
/// lights' maps a chunk at a time, away from the chaos game's loop: the loop only stores the point.
/// The projection takes eight samples at once into every light in one pass over the chunk (the
/// light count is a template parameter, so that loop is unrolled): one sample at a time, its
/// arithmetic, not the maps' cache misses, was most of a light's cost (an attractor fills a few
/// percent of a map's texels, which mostly stay in a core's L2 cache). Every texel of the chunk,
/// in every map, is prefetched before any is written, for attractors that fill their maps. A
/// minimum does not depend on the order, so the maps are those of plotting sample by sample. On
/// its own it is the plotter of a light-only pass (the chaos game replayed to re-fill the maps of
/// lights that moved, the camera's buffers kept).
struct LightPlot {
  HotLight lights[kMaxShadowLights] = {};
  int lightCount = 0;
  float lightSize = 0.0f;  // texels per side
  std::uint32_t lightStride = 0;

  static constexpr int kChunk = 256;
  static constexpr int kGroup = 8;  // samples projected at once
  static_assert(kChunk % kGroup == 0);
  v4f points[kChunk];
  int count = 0;

  /// Projects the collected points into every light's map. Out of line (once per chunk), and
  /// compiled for the CPU like the chaos game's kernel.
  [[gnu::noinline]] GRIDIFS_KERNEL_CLONES void drain() {
    switch (lightCount) {
      case 1:
        drainInto<1>();
        break;
      case 2:
        drainInto<2>();
        break;
      case 3:
        drainInto<3>();
        break;
      default:
        break;
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

 private:
  typedef std::int32_t v8i __attribute__((vector_size(32)));
  typedef std::uint16_t v8k __attribute__((vector_size(16)));

  /// A light's rows with each coefficient in eight lanes: rows[4·r + c] is coefficient c (x, y, z,
  /// constant) of row r (u, v, depth step).
  [[gnu::always_inline]] static void broadcastRows(const HotLight& light, v8f (&rows)[12]) {
    const v4f* columns[4] = {&light.cx, &light.cy, &light.cz, &light.c1};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) rows[4 * r + c] = v8f{} + (*columns[c])[r];
  }

  /// Points i … i+7 as x, y, z rows.
  [[gnu::always_inline]] void transpose(int i, v8f& x, v8f& y, v8f& z) const {
    v8f unused;
    transposeEight(points + i, x, y, z, unused);
  }

  template <int kLights>
  [[gnu::always_inline]] void drainInto() {
    // The last chunk of a batch may be partial: its tail is padded with NaN points, which fall
    // outside every map and so write nothing.
    const int n = (count + kGroup - 1) / kGroup * kGroup;
    for (int i = count; i < n; ++i) points[i] = v4f{} + __builtin_nanf("");
    alignas(32) std::uint32_t texels[kLights][kChunk];
    alignas(16) std::uint16_t keys[kLights][kChunk];
    const v8f size = v8f{} + lightSize;
    const v8i stride = v8i{} + std::int32_t(lightStride);
    v8f rows[kLights][12];
    for (int l = 0; l < kLights; ++l) broadcastRows(lights[l], rows[l]);
    for (int i = 0; i < n; i += kGroup) {
      v8f x, y, z;
      transpose(i, x, y, z);
      for (int l = 0; l < kLights; ++l) {
        const v8f* row = rows[l];
        // The same float operations, in the same order, as one sample at a time:
        // r = cx·x + cy·y + cz·z + c1 per row (FMA is not enabled, so nothing is contracted).
        const v8f u = row[0] * x + row[1] * y + row[2] * z + row[3];
        const v8f v = row[4] * x + row[5] * y + row[6] * z + row[7];
        const v8f d = row[8] * x + row[9] * y + row[10] * z + row[11];
        const v8i inside = (u >= v8f{}) & (u < size) & (v >= v8f{}) & (v < size);  // NaN fails too
        // Outside the map: texel 0 and an empty key, which never lowers a texel.
        const v8i iu = __builtin_convertvector(inside ? u : v8f{}, v8i);
        const v8i iv = __builtin_convertvector(inside ? v : v8f{}, v8i);
        // Clamped for rounding at the sphere's edges; truncation stores a step nearer the light.
        v8f steps = inside ? d : v8f{};
        steps = steps > v8f{} ? steps : v8f{};
        steps = steps < kLightSteps ? steps : v8f{} + kLightSteps;
        const v8i key = inside ? __builtin_convertvector(steps, v8i) : v8i{} + std::int32_t(kLightEmpty);
        const v8i texel = iv * stride + iu;
        std::memcpy(&texels[l][i], &texel, sizeof texel);
        const v8k narrow = __builtin_convertvector(key, v8k);
        std::memcpy(&keys[l][i], &narrow, sizeof narrow);
        for (int k = 0; k < kGroup; ++k) __builtin_prefetch(lights[l].depth + texels[l][i + k], 1);
      }
    }
    for (int l = 0; l < kLights; ++l) {
      std::uint16_t* depth = lights[l].depth;
      for (int i = 0; i < n; ++i) {
        std::atomic_ref<std::uint16_t> z(depth[texels[l][i]]);
        if (keys[l][i] < z.load(std::memory_order_relaxed)) z.store(keys[l][i], std::memory_order_relaxed);
      }
    }
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
  std::int64_t takePlotted() { return camera.takePlotted(); }

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
      if (lens.uniformRadius) {
        // A disc point's distance s from the centre has P(s ≤ t) = t², so s² is uniform on
        // [0, 1]: scaling the point by s moves it to distance s² at the same angle.
        const float s = std::sqrt(x * x + y * y);
        x *= s;
        y *= s;
      }
      q = q + lens.right * (x * radius) + lens.up * (y * radius);
    }
    return camera(q, col);
  }
};

}  // namespace gridifs::kernel
