#pragma once
// Internal to the renderer (chaos_renderer.cpp, benchmarks, tests): the chaos-game inner loop
// (seed 004 §3.1, seed 002 §2 and §5). Everything here is inline and templated on the plot
// target, so the hot loop has no virtual calls and no atomics with ordering; one worker owns one
// ChainState and one set of buffers.
//
// Per iteration: pick a function by weight (alias table, one 64-bit random number); p = f(p)
// (clamp to X, 4 × 32-byte node-pair loads, trilinear lerps in float); mix the running colour
// (r, g, b, c) towards the function's (color, palette_index) with its color_speed; a non-finite or
// escaped point restarts the chain; past `skip`, apply the final function (not in the loop) and
// hand the point to the plotter.
#include <atomic>
#include <bit>
#include <cstdint>
#include <cstring>

#include "core/compiled_ifs.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace gridifs::kernel {

typedef float v4f __attribute__((vector_size(16)));
typedef float v8f __attribute__((vector_size(32)));
typedef std::int32_t v4i __attribute__((vector_size(16)));

/// wyrand (Wang Yi): one 64×64→128 multiply per number; passes BigCrush/PractRand and is much
/// cheaper than mt19937. Stream = (seed, worker) through splitmix64.
struct Rng {
  std::uint64_t state = 0;
  static std::uint64_t splitmix(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
  }
  static Rng forStream(std::uint64_t seed, std::uint64_t worker) {
    return Rng{splitmix(splitmix(seed) ^ splitmix(worker + 0x5851F42D4C957F2Dull))};
  }
  std::uint64_t next() {
    state += 0xA0761D6478BD642Full;
    const unsigned __int128 m = (unsigned __int128)state * (state ^ 0xE7037ED1A0B428DBull);
    return std::uint64_t(m >> 64) ^ std::uint64_t(m);
  }
  /// Uniform in [-1, 1) from 24 random bits.
  static float signedUnit(std::uint64_t bits) { return float(std::uint32_t(bits & 0xFFFFFF)) * (2.0f / 16777216.0f) - 1.0f; }
};

/// A compiled function laid out for the loop (64 bytes + the pair pointer).
struct alignas(64) HotFunction {
  v4f toLattice;
  v4f maxCell;
  v4f color;  // r g b c
  v4f speed;  // color_speed in all lanes
  const NodePair* pairs;
  std::uint32_t strideJ, strideK;
};

inline HotFunction makeHot(const CompiledFunction& f) {
  HotFunction h{};
  for (int d = 0; d < 4; ++d) {
    h.toLattice[d] = f.toLattice[d];
    h.maxCell[d] = f.maxCell[d];
    h.color[d] = f.color[d];
    h.speed[d] = f.colorSpeed;
  }
  h.pairs = f.pairs.data();
  h.strideJ = f.pairStrideJ;
  h.strideK = f.pairStrideK;
  return h;
}

/// p = f(p): the same float operations as CompiledFunction::evaluate (lane 3 is ignored).
[[gnu::always_inline]] inline v4f apply(const HotFunction& f, v4f p) {
  const v4f lo = {-1.0f, -1.0f, -1.0f, -1.0f}, hi = {1.0f, 1.0f, 1.0f, 1.0f};
  p = p > lo ? p : lo;  // NaN → -1
  p = p < hi ? p : hi;
  const v4f s = (p + hi) * f.toLattice;
  v4f c = __builtin_convertvector(__builtin_convertvector(s, v4i), v4f);
  c = f.maxCell < c ? f.maxCell : c;
  const v4f t = s - c;
  const v4i ci = __builtin_convertvector(c, v4i);
  const std::size_t idx = std::uint32_t(ci[0]) + f.strideJ * std::uint32_t(ci[1]) + f.strideK * std::uint32_t(ci[2]);
  const NodePair* base = f.pairs + idx;
  v8f p00, p10, p01, p11;
  std::memcpy(&p00, base, 32);
  std::memcpy(&p10, base + f.strideJ, 32);
  std::memcpy(&p01, base + f.strideK, 32);
  std::memcpy(&p11, base + f.strideJ + f.strideK, 32);
  const v8f ty = {t[1], t[1], t[1], t[1], t[1], t[1], t[1], t[1]};
  const v8f tz = {t[2], t[2], t[2], t[2], t[2], t[2], t[2], t[2]};
  const v8f e0 = p00 + (p10 - p00) * ty;
  const v8f e1 = p01 + (p11 - p01) * ty;
  const v8f e = e0 + (e1 - e0) * tz;
  const v4f a = {e[0], e[1], e[2], e[3]}, b = {e[4], e[5], e[6], e[7]};
  const v4f tx = {t[0], t[0], t[0], t[0]};
  return a + (b - a) * tx;
}

/// Whether every coordinate is finite and within the escape bound (NaN fails).
[[gnu::always_inline]] inline bool inBounds(v4f p, float bound) {
  const v4f b = {bound, bound, bound, bound};
  const v4f zero = {0.0f, 0.0f, 0.0f, 0.0f};
  const v4f a = p < zero ? -p : p;
  const v4i ok = a <= b;  // false for NaN
  return (ok[0] & ok[1] & ok[2]) != 0;
}

/// One worker's chain: position, running colour, iterations left to skip.
struct ChainState {
  Rng rng;
  v4f p{0, 0, 0, 0};
  v4f color{0.5f, 0.5f, 0.5f, 0.0f};
  int skipLeft = 0;

  void restart(int skip) {
    const std::uint64_t a = rng.next(), b = rng.next();
    p = v4f{Rng::signedUnit(a), Rng::signedUnit(a >> 24), Rng::signedUnit(b), 0.0f};
    // seed 002 §5: c starts at a random point of [0, 1]; the RGB blend starts mid-grey (both are
    // forgotten geometrically, by (1 - color_speed)^skip).
    color = v4f{0.5f, 0.5f, 0.5f, float(std::uint32_t(b >> 40)) * (1.0f / 16777216.0f)};
    skipLeft = skip;
  }
};

struct HotIfs {
  const HotFunction* functions = nullptr;
  const AliasEntry* alias = nullptr;
  std::uint32_t count = 0;
  const HotFunction* finalFunction = nullptr;  // null when none
  int skip = 20;
  float escapeBound = 1e5f;

  [[gnu::always_inline]] std::uint32_t choose(std::uint64_t r) const {
    const std::uint32_t column = std::uint32_t((std::uint64_t(std::uint32_t(r >> 32)) * count) >> 32);
    const AliasEntry e = alias[column];
    return std::uint32_t(r) < e.threshold ? column : e.alias;
  }
};

struct ChainCounters {
  std::int64_t samples = 0, bad = 0, plotted = 0;
};

/// Runs `count` iterations of the chain. `plot(q, color)` receives each point past `skip` (after
/// the final function) and returns whether it was plotted (counted in `plotted`).
template <class Plot>
inline void runChain(ChainState& st, const HotIfs& ifs, std::int64_t count, Plot& plot, ChainCounters& counters) {
  v4f p = st.p, col = st.color;
  int skipLeft = st.skipLeft;
  std::int64_t bad = 0, plotted = 0;
  for (std::int64_t n = 0; n < count; ++n) {
    const HotFunction& f = ifs.functions[ifs.choose(st.rng.next())];
    p = apply(f, p);
    col = col + (f.color - col) * f.speed;  // seed 002 §5: c = mix(c, c_i, speed)
    if (!inBounds(p, ifs.escapeBound)) [[unlikely]] {
      ++bad;
      st.restart(ifs.skip);
      p = st.p;
      col = st.color;
      skipLeft = st.skipLeft;
      continue;
    }
    if (skipLeft > 0) {
      --skipLeft;
      continue;
    }
    if (ifs.finalFunction) {
      const HotFunction& g = *ifs.finalFunction;
      const v4f q = apply(g, p);
      if (!inBounds(q, ifs.escapeBound)) [[unlikely]] {
        ++bad;
        continue;
      }
      plotted += plot(q, col + (g.color - col) * g.speed);
    } else {
      plotted += plot(p, col);
    }
  }
  st.p = p;
  st.color = col;
  st.skipLeft = skipLeft;
  counters.samples += count;
  counters.bad += bad;
  counters.plotted += plotted;
}

/// Packs r g b c in [0, 1] into 4 bytes (r in the low byte).
[[gnu::always_inline]] inline std::uint32_t packColor(v4f c) {
#if defined(__SSE2__)
  const __m128 scaled = _mm_add_ps(_mm_mul_ps(__m128(c), _mm_set1_ps(255.0f)), _mm_set1_ps(0.5f));
  const __m128i i32 = _mm_cvttps_epi32(_mm_max_ps(scaled, _mm_setzero_ps()));
  const __m128i i16 = _mm_packs_epi32(i32, i32);
  return std::uint32_t(_mm_cvtsi128_si32(_mm_packus_epi16(i16, i16)));
#else
  std::uint32_t out = 0;
  for (int d = 0; d < 4; ++d) {
    float v = c[d] * 255.0f + 0.5f;
    v = v < 0.0f ? 0.0f : (v > 255.0f ? 255.0f : v);
    out |= std::uint32_t(v) << (8 * d);
  }
  return out;
#endif
}

/// Projection rows as columns for a 4×4 matrix–vector product: r = cx·x + cy·y + cz·z + c1, giving
/// (pixel x · w, pixel y · w, w, depth).
struct HotCamera {
  v4f cx, cy, cz, c1;
  float width, height, nearPlane;
  std::uint32_t stride;
};

/// The z-buffer plotter (seed 004 §3.1). Keys are (depth bits << 32 | packed colour): depth is
/// positive, so unsigned order is depth order and equal depths fall back to the colour, which makes
/// the per-pixel minimum independent of sample and worker order. Buffer accesses go through
/// std::atomic_ref with relaxed order: plain moves on x86, but snapshot() may read them while
/// the worker writes.
template <bool kAccumulateColor>
struct ZBufferPlot {
  HotCamera cam;
  std::uint64_t* zbuffer;
  std::uint32_t* density;
  float* colorSums;  // 4 per pixel, only with kAccumulateColor

  [[gnu::always_inline]] int operator()(v4f q, v4f col) const {
    const v4f r = cam.cx * q[0] + cam.cy * q[1] + cam.cz * q[2] + cam.c1;
    const float w = r[2], depth = r[3];
    if (!(depth > cam.nearPlane)) return 0;
    const float x = r[0] / w, y = r[1] / w;
    if (!(x >= 0.0f && x < cam.width && y >= 0.0f && y < cam.height)) return 0;
    const std::size_t pixel = std::size_t(std::uint32_t(y)) * cam.stride + std::uint32_t(x);
    const std::uint64_t key = (std::uint64_t(std::bit_cast<std::uint32_t>(depth)) << 32) | packColor(col);
    std::atomic_ref<std::uint64_t> z(zbuffer[pixel]);
    if (key < z.load(std::memory_order_relaxed)) z.store(key, std::memory_order_relaxed);
    std::atomic_ref<std::uint32_t> d(density[pixel]);
    const std::uint32_t n = d.load(std::memory_order_relaxed);
    d.store(n + (n != 0xFFFFFFFFu), std::memory_order_relaxed);  // saturating
    if constexpr (kAccumulateColor) {
      for (int k = 0; k < 4; ++k) {
        std::atomic_ref<float> s(colorSums[pixel * 4 + k]);
        s.store(s.load(std::memory_order_relaxed) + col[k], std::memory_order_relaxed);
      }
    }
    return 1;
  }
};

inline constexpr std::uint64_t kEmptyKey = ~std::uint64_t(0);

}  // namespace gridifs::kernel
