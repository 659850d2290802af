#pragma once
// Internal to the renderer (chaos_renderer.cpp, benchmarks, tests): the chaos-game inner loop
// (Gröller & Wegenkittl 1994, §3.1; Draves & Reckase 2003, §2 and §5). Everything here is inline and templated on the
// plot target, so the hot loop has no virtual calls and no atomics with ordering; one worker owns one ChainState and
// one set of buffers.
//
// Per iteration: pick a function by weight (alias table, one 64-bit random number); p = f(p)
// (clamp to X, 4 × 32-byte node-pair loads, trilinear lerps in float); mix the running colour
// (r, g, b, c) towards the function's (color, palette_index) with its color_speed; a non-finite or
// escaped point restarts the chain; past `skip`, apply the final function (not in the loop) and
// hand the point to the plotter.
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "base/hash.h"
#include "render/batched_variations.h"
#include "render/camera.h"
#include "render/compiled_ifs.h"
#include "variations/lane_math.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#include <xmmintrin.h>
#endif

// Callers of runChain compile it twice, picked at load time: AVX2 (the 32-byte node-pair loads and
// lerps are single instructions) and the portable baseline. FMA is deliberately not used: contracted
// into fused multiply-adds, a + (b - a)·t would round differently, and images would then depend
// on the CPU (the build also passes -ffp-contract=off). An AVX-512 (x86-64-v4) clone was measured
// on an AVX-512 CPU: without contraction it ran no faster than AVX2 (docs/RENDERER.md).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GRIDIFS_NO_KERNEL_CLONES)
#define GRIDIFS_KERNEL_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define GRIDIFS_KERNEL_CLONES
#endif

namespace gridifs::kernel {

typedef float v4f __attribute__((vector_size(16)));
typedef float v8f __attribute__((vector_size(32)));
typedef float v16f __attribute__((vector_size(64)));
typedef std::int32_t v4i __attribute__((vector_size(16)));

/// Flushes denormal floats to zero (FTZ) and reads denormal inputs as zero (DAZ) on the calling
/// thread while it lives, then restores the previous mode. Why: the running colour
/// c <- c + (c_i - c)·speed decays geometrically wherever a function's channel is 0 (palette index 0,
/// the default, or an all-red IFS) and settles on the smallest denormal, where the step rounds back
/// to c; from then on every colour operation takes a microcode assist (about 3× slower). Flushing
/// is as deterministic as IEEE arithmetic: the same inputs give the same bits on every x86 CPU.
class DenormalsAreZero {
 public:
#if defined(__SSE2__)
  DenormalsAreZero() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | kFlushToZero | kDenormalsAreZero); }
  ~DenormalsAreZero() { _mm_setcsr(saved_); }
#else
  DenormalsAreZero() = default;
#endif
  DenormalsAreZero(const DenormalsAreZero&) = delete;
  DenormalsAreZero& operator=(const DenormalsAreZero&) = delete;

 private:
#if defined(__SSE2__)
  static constexpr unsigned kFlushToZero = 0x8000u, kDenormalsAreZero = 0x0040u;
  unsigned saved_;
#endif
};

/// wyrand (Wang Yi): one 64×64→128 multiply per number; passes BigCrush/PractRand and is much
/// cheaper than mt19937. Stream = (seed, worker) through splitmix64.
struct Rng {
  std::uint64_t state = 0;
  static Rng forStream(std::uint64_t seed, std::uint64_t worker) {
    return Rng{splitmix64(splitmix64(seed) ^ splitmix64(worker + 0x5851F42D4C957F2Dull))};
  }
  std::uint64_t next() {
    state += 0xA0761D6478BD642Full;
#if defined(__x86_64__) && defined(__GNUC__)
    // The same product with its halves in two registers: GCC's 128-bit value went through the
    // stack between the multiply and the xor, in the chaos game's loop.
    asm("" : "+r"(state));  // one add per draw, not four constants per round of the unrolled loop
    std::uint64_t low = state, high;
    asm("mulq %2" : "+a"(low), "=d"(high) : "rm"(state ^ 0xE7037ED1A0B428DBull) : "cc");
    return high ^ low;
#else
    const unsigned __int128 m = (unsigned __int128)state * (state ^ 0xE7037ED1A0B428DBull);
    return std::uint64_t(m >> 64) ^ std::uint64_t(m);
#endif
  }
  /// Uniform in [-1, 1) from 24 random bits.
  static float signedUnit(std::uint64_t bits) {
    return float(std::uint32_t(bits & 0xFFFFFF)) * (2.0f / 16777216.0f) - 1.0f;
  }
};

/// A compiled function laid out for the loop (two 64-byte lines).
struct alignas(64) HotFunction {
  v4f toLattice;
  v4i lastCell;  // CompiledFunction::maxCell as whole numbers: the last cell in each axis
  v4f color;     // r g b c
  v4f speed;     // color_speed in all lanes
  /// Byte offsets between node pairs (32 bytes each): the next cell in x, in y (a row of
  /// CompiledFunction::pairStrideJ pairs), in z (pairStrideK), and in y and z together. A cell's
  /// four x-edges are at its offset plus 0 and the last three.
  v4i pairBytes;
  const NodePair* pairs;
  const float* matrix;  // a free-form IFS's matrix rows (CompiledFunction::matrix), else null
  const float* points;  // a condensation function's samples of its set (x y z 0 each), else null
  std::uint32_t pointCount;
  const CompiledVariations* variations;  // the flame variation stage, else null
  const float* affine;                   // CompiledFunction::affineColumns when the grid's map is affine, else null
};

inline HotFunction makeHot(const CompiledFunction& f) {
  HotFunction h{};
  for (int d = 0; d < 4; ++d) {
    h.toLattice[d] = f.toLattice[d];
    h.lastCell[d] = int(f.maxCell[d]);
    h.color[d] = f.color[d];
    h.speed[d] = f.colorSpeed;
  }
  h.pairs = f.pairs.data();
  static_assert(sizeof(NodePair) == 32);
  const std::int32_t row = std::int32_t(32 * f.pairStrideJ), layer = std::int32_t(32 * f.pairStrideK);
  h.pairBytes = v4i{32, row, layer, row + layer};
  h.matrix = f.matrix.empty() ? nullptr : f.matrix.data();
  h.points = f.points.empty() ? nullptr : f.points.data();
  h.pointCount = std::uint32_t(f.points.size() / 4);
  h.variations = f.variations.get();
  h.affine = f.affine ? &f.affineColumns[0][0] : nullptr;
  return h;
}

/// Lane I of v in all four lanes.
template <int I>
[[gnu::always_inline]] inline v4f splat(v4f v) {
  return __builtin_shufflevector(v, v, I, I, I, I);
}

[[gnu::always_inline]] inline v4f load4(const float* p) {
  v4f v;
  std::memcpy(&v, p, 16);
  return v;
}

/// Bit mask of the lanes of a comparison result (lane 0 → bit 0).
[[gnu::always_inline]] inline int laneMask(v4i m) {
#if defined(__SSE2__)
  return _mm_movemask_ps(_mm_castsi128_ps(__m128i(m)));
#else
  return (m[0] ? 1 : 0) | (m[1] ? 2 : 0) | (m[2] ? 4 : 0) | (m[3] ? 8 : 0);
#endif
}

/// The node pair `bytes` past `base` (HotFunction::pairBytes).
[[gnu::always_inline]] inline const NodePair* pairAt(const NodePair* base, std::int32_t bytes) {
  return reinterpret_cast<const NodePair*>(reinterpret_cast<const char*>(base) + bytes);
}

/// The byte offset of the node pair at cell c (at least 0 in lanes 0 to 2): c · (32, row bytes,
/// layer bytes), one vector multiply and a horizontal sum.
[[gnu::always_inline]] inline std::uint32_t pairOffset(const HotFunction& f, v4i c) {
  const v4i bytes = c * f.pairBytes;
  const v4i sums = bytes + __builtin_shufflevector(bytes, bytes, 2, 2, 2, 2);
  return std::uint32_t(sums[0] + bytes[1]);
}

/// p = f(p): the same float operations as CompiledFunction::evaluate (lane 3 is ignored). The
/// node pairs are 32 bytes apart in x, so each corner pair is one 32-byte (two 16-byte) load.
[[gnu::always_inline]] inline v4f apply(const HotFunction& f, v4f p) {
  const v4f lo = {-1.0f, -1.0f, -1.0f, -1.0f}, hi = {1.0f, 1.0f, 1.0f, 1.0f};
#if defined(__SSE2__)
  // maxps returns its second operand when the first is NaN: NaN → -1, as Grid::evaluate.
  p = v4f(_mm_min_ps(_mm_max_ps(__m128(p), __m128(lo)), __m128(hi)));
#else
  p = p > lo ? p : lo;  // NaN → -1
  p = p < hi ? p : hi;
#endif
  const v4f s = (p + hi) * f.toLattice;  // at least 0
  // The cell clamped as whole numbers: the same cell and t as min(float(int(s)), maxCell), one
  // conversion fewer.
  v4i cell = __builtin_convertvector(s, v4i);
  cell = cell < f.lastCell ? cell : f.lastCell;
  const v4f t = s - __builtin_convertvector(cell, v4f);
  const char* base = reinterpret_cast<const char*>(f.pairs) + pairOffset(f, cell);
  v8f p00, p10, p01, p11;  // one 32-byte load per x-edge: both ends of the edge
  std::memcpy(&p00, base, 32);
  std::memcpy(&p10, base + f.pairBytes[1], 32);
  std::memcpy(&p01, base + f.pairBytes[2], 32);
  std::memcpy(&p11, base + f.pairBytes[3], 32);
  // t in both halves, then each half's lane 1 or 2: permutes within the halves.
  const v8f tt = __builtin_shufflevector(t, t, 0, 1, 2, 3, 0, 1, 2, 3);
  const v8f ty = __builtin_shufflevector(tt, tt, 1, 1, 1, 1, 5, 5, 5, 5);
  const v8f tz = __builtin_shufflevector(tt, tt, 2, 2, 2, 2, 6, 6, 6, 6);
  const v8f e0 = p00 + (p10 - p00) * ty;
  const v8f e1 = p01 + (p11 - p01) * ty;
  const v8f e = e0 + (e1 - e0) * tz;
  const v4f a = __builtin_shufflevector(e, e, 0, 1, 2, 3), b = __builtin_shufflevector(e, e, 4, 5, 6, 7);
  return a + (b - a) * splat<0>(t);
}

/// The grid map continued beyond X from its border cells (a function with variations, see
/// model/function_variations.h): the same float operations as CompiledFunction::evaluateExtrapolated.
[[gnu::always_inline]] inline v4f applyExtrapolated(const HotFunction& f, v4f p) {
  if (f.affine) {
    // An affine grid (CompiledFunction::affine): its map, continued beyond X, is affine.
    return load4(f.affine) * splat<0>(p) + load4(f.affine + 4) * splat<1>(p) + load4(f.affine + 8) * splat<2>(p) +
           load4(f.affine + 12);
  }
  const v4f one = {1.0f, 1.0f, 1.0f, 1.0f};
  const v4f s = (p + one) * f.toLattice;
  // The cell clamped to [0, lastCell] as whole numbers. NaN and values beyond the int range
  // convert to INT_MIN, so they land in cell 0, as min(float(int(s)), maxCell) then max(·, 0) did.
  v4i cell = __builtin_convertvector(s, v4i);
  cell = cell < f.lastCell ? cell : f.lastCell;
  cell = cell > 0 ? cell : v4i{};
  const v4f t = s - __builtin_convertvector(cell, v4f);
  const NodePair* base = pairAt(f.pairs, std::int32_t(pairOffset(f, cell)));
  // In 4-wide halves: applyVariations is not one of the kernel's AVX2 clones, and SSE2 builds
  // 8-wide broadcasts through the stack, a store-forwarding stall on every step. The same float
  // operations per lane as the 8-wide form.
  const NodePair* n10 = pairAt(base, f.pairBytes[1]);
  const NodePair* n01 = pairAt(base, f.pairBytes[2]);
  const NodePair* n11 = pairAt(base, f.pairBytes[3]);
  const v4f ty = splat<1>(t), tz = splat<2>(t);
  const v4f a0 = load4(base->a) + (load4(n10->a) - load4(base->a)) * ty;
  const v4f b0 = load4(base->b) + (load4(n10->b) - load4(base->b)) * ty;
  const v4f a1 = load4(n01->a) + (load4(n11->a) - load4(n01->a)) * ty;
  const v4f b1 = load4(n01->b) + (load4(n11->b) - load4(n01->b)) * ty;
  const v4f a = a0 + (a1 - a0) * tz, b = b0 + (b1 - b0) * tz;
  return a + (b - a) * splat<0>(t);
}

/// f(p) of a function with variations (Draves & Reckase 2003, §3): the extrapolated grid map, then
/// post(Σ w_i V_i) in double precision, drawing random variations from the chain's stream
/// (CompiledVariations::applyKernel: the bodies inlined, sin, cos and atan2 inline).
[[gnu::noinline]] inline v4f applyVariations(const HotFunction& f, v4f p, std::uint64_t& random) {
  const v4f q = applyExtrapolated(f, p);
  const std::array<float, 3> r = f.variations->applyKernel(q[0], q[1], q[2], random);
  return v4f{r[0], r[1], r[2], 0.0f};
}

/// Whether every coordinate is finite and within the escape bound (NaN fails).
[[gnu::always_inline]] inline bool inBounds(v4f p, float bound) {
  const v4f b = {bound, bound, bound, bound};
  const v4i magnitudeBits = v4i(p) & 0x7FFFFFFF;        // |p| without a compare and blend
  return (laneMask(v4f(magnitudeBits) <= b) & 7) == 7;  // false for NaN
}

/// One worker's chains. A single chain is latency-bound (every step waits for the previous
/// point: clamp → cell → 4 loads → lerps), so each worker advances kLanes independent chains in
/// turn and the CPU overlaps them. Sample n of a worker belongs to lane n % kLanes (batches are
/// multiples of kLanes except the very last), so the sequence does not depend on batch sizes.
inline constexpr int kLanes = 4;  // runChain unrolls exactly this many

struct ChainState {
  Rng rng;
  v4f p[kLanes] = {};
  v4f color[kLanes] = {};
  int skipLeft[kLanes] = {};
  /// Where in HotIfs::transitionWalk the row picking the lane's next function starts (the row
  /// after the function it applied last; 0, the first-function row, after a restart).
  std::uint32_t row[kLanes] = {};
  /// Steps since the lane's last restart (only counted when HotIfs::restartInterval is set).
  std::uint32_t age[kLanes] = {};

  void restartLane(int lane, int skip) {
    const std::uint64_t a = rng.next(), b = rng.next();
    p[lane] = v4f{Rng::signedUnit(a), Rng::signedUnit(a >> 24), Rng::signedUnit(b), 0.0f};
    // Draves & Reckase 2003, §5: c starts at a random point of [0, 1]; the RGB blend starts mid-grey (both are
    // forgotten geometrically, by (1 - color_speed)^skip).
    color[lane] = v4f{0.5f, 0.5f, 0.5f, float(std::uint32_t(b >> 40)) * (1.0f / 16777216.0f)};
    skipLeft[lane] = skip;
    row[lane] = 0;
    age[lane] = 0;
  }
  /// A bad value of a flame variation (spherical at 0, log of 0, …): flam3 replaces the point by a
  /// fresh random one and goes on without a new fuse (Draves & Reckase 2003, §2), so an IFS whose
  /// maps often fail still plots; colour, skip count and transition row stay.
  void replacePoint(int lane) {
    const std::uint64_t a = rng.next(), b = rng.next();
    p[lane] = v4f{Rng::signedUnit(a), Rng::signedUnit(a >> 24), Rng::signedUnit(b), 0.0f};
  }
  /// A fresh chain set for stream (seed, worker).
  static ChainState start(std::uint64_t seed, std::uint64_t worker, int skip) {
    ChainState st;
    st.rng = Rng::forStream(seed, worker);
    for (int l = 0; l < kLanes; ++l) st.restartLane(l, skip);
    return st;
  }
};

struct HotIfs {
  const HotFunction* functions = nullptr;
  const AliasEntry* alias = nullptr;
  /// CompiledIfs::transitionWalk ((count + 1) rows of count entries), null when unrestricted.
  const TransitionStep* transitionWalk = nullptr;
  std::uint32_t count = 0;
  const HotFunction* finalFunction = nullptr;  // null when none
  int skip = 20;
  float escapeBound = 1e5f;
  /// CompiledIfs::restartInterval: restart a lane after this many steps (0: never).
  std::uint32_t restartInterval = 0;
  /// CompiledIfs::stateRowsOffset.
  std::uint32_t stateRowsOffset = 0;
  /// Free-form IFS (barycentric_kernel.h): m coordinates and the padded size in blocks of 8
  /// floats; 0 blocks for a grid IFS.
  std::uint32_t barycentricSize = 0, barycentricBlocks = 0;
  /// Whether some function is a constant condensation (HotFunction::points) or has flame
  /// variations (HotFunction::variations): the loop that checks for them is a separate
  /// instantiation, so plain grid IFSs run the loop they always ran.
  bool condensation = false;
  bool variations = false;
  /// Whether every function is a plain grid map whose nodes lie within half the escape bound:
  /// the map of a clamped point blends nodes with weights in [0, 1], so no point of such an IFS
  /// can escape and no chain ever restarts (runBoundedRounds).
  bool boundedMaps = false;
  /// CompiledIfs::batchedVariations: the variation stage of a round's four chains at once.
  const BatchedVariations* batched = nullptr;

  [[gnu::always_inline]] std::uint32_t choose(std::uint64_t r) const { return chooseIn(alias, count, r); }
  /// choose() from an alias table held elsewhere (a loop's locals).
  [[gnu::always_inline]] static std::uint32_t chooseIn(const AliasEntry* alias, std::uint32_t count, std::uint64_t r) {
    const std::uint32_t column = std::uint32_t((std::uint64_t(std::uint32_t(r >> 32)) * count) >> 32);
    const AliasEntry e = alias[column];
    return std::uint32_t(r) < e.threshold ? column : e.alias;
  }
  /// The next function of a lane: by the transition row at `row` (kRestricted: `row` becomes the
  /// row after that function) or by weight alone. One random number either way.
  template <bool kRestricted>
  [[gnu::always_inline]] std::uint32_t pick(std::uint32_t& row, std::uint64_t r) const {
    if constexpr (kRestricted)
      return chooseAfter(row, r);
    else
      return choose(r);
  }
  /// The next function by the transition row at `row`, which becomes the row after that function.
  /// The same draws and choices as an alias table per row (choose()), without a multiply or a
  /// branch on the row: the step's latency stays off the chain of points.
  [[gnu::always_inline]] std::uint32_t chooseAfter(std::uint32_t& row, std::uint64_t r) const {
    const std::uint32_t column = std::uint32_t((std::uint64_t(std::uint32_t(r >> 32)) * count) >> 32);
    const TransitionStep e = transitionWalk[row + column];
    const bool keep = std::uint32_t(r) < e.threshold;
    row = keep ? e.keepRow : e.aliasRow;
    return keep ? column : e.alias;
  }
};

struct ChainCounters {
  std::int64_t samples = 0, bad = 0, plotted = 0;
};

/// The end of every step, for grid and free-form chains alike: the lane moves to p with its colour
/// (and transition row), and past `skip` the point goes to the plotter — through the final
/// function (not in the loop) when there is one. Returns what the plotter returned.
template <bool kRestricted, class Plot>
[[gnu::always_inline]] inline int advanceAndPlot(ChainState& st, int lane, const HotIfs& ifs, Plot& plot,
                                                 std::int64_t& bad, v4f p, v4f col, std::uint32_t nextRow) {
  if constexpr (kRestricted) {
    // An IFS matrix with states (freeform/state_expansion.h): a peek plots its image and leaves the
    // lane as it was (its point is not yet on the attractor while skipping); a hidden step moves
    // the lane without plotting.
    if (nextRow & kTransitionFlags) [[unlikely]] {
      if (nextRow & kTransitionSkipPhase) {
        st.p[lane] = p;
        st.color[lane] = col;
        st.row[lane] = (nextRow & kTransitionRowMask) + (st.skipLeft[lane] <= 1 ? ifs.stateRowsOffset : 0);
        if (st.skipLeft[lane] > 0) --st.skipLeft[lane];
        return 0;
      }
      if (nextRow & kTransitionPeek) {
        if (st.skipLeft[lane] > 0) return 0;
      } else {
        st.p[lane] = p;
        st.color[lane] = col;
        st.row[lane] = nextRow & kTransitionRowMask;
        if (st.skipLeft[lane] > 0) --st.skipLeft[lane];
        return 0;
      }
    } else {
      st.p[lane] = p;
      st.color[lane] = col;
      st.row[lane] = nextRow;
    }
  } else {
    st.p[lane] = p;
    st.color[lane] = col;
  }
  if (st.skipLeft[lane] > 0) {
    --st.skipLeft[lane];
    return 0;
  }
  if (ifs.finalFunction) {
    const HotFunction& g = *ifs.finalFunction;
    const v4f q = g.variations ? applyVariations(g, p, st.rng.state) : apply(g, p);
    if (!inBounds(q, ifs.escapeBound)) [[unlikely]] {
      ++bad;
      return 0;
    }
    return plot(q, col + (g.color - col) * g.speed);
  }
  return plot(p, col);
}

/// One iteration of all four lanes of an IFS whose variation stages run batched
/// (HotIfs::batched): each lane picks its function and maps its point through the function's grid,
/// then the variations of all four run at once, then each lane moves and plots as stepLane's do.
/// Returns the plotters' sum.
template <class Plot>
[[gnu::always_inline]] inline int stepBatchedRound(ChainState& st, const HotIfs& ifs, Plot& plot, std::int64_t& bad) {
  std::uint32_t fn[kLanes];
  v4f q[kLanes];
  for (int l = 0; l < kLanes; ++l) {
    fn[l] = ifs.choose(st.rng.next());
    const HotFunction& f = ifs.functions[fn[l]];
    q[l] = f.variations ? applyExtrapolated(f, st.p[l]) : apply(f, st.p[l]);
  }
  ifs.batched->apply(fn, q, st.rng.state);
  int plotted = 0;
  for (int l = 0; l < kLanes; ++l) {
    const HotFunction& f = ifs.functions[fn[l]];
    const v4f col = st.color[l] + (f.color - st.color[l]) * f.speed;  // Draves & Reckase 2003, §5
    if (!inBounds(q[l], ifs.escapeBound)) [[unlikely]] {
      ++bad;
      st.replacePoint(l);  // as flam3 does: a fresh random point, the chain goes on
      continue;
    }
    plotted += advanceAndPlot<false>(st, l, ifs, plot, bad, q[l], col, 0);
  }
  return plotted;
}

/// One iteration of one lane; returns what the plotter returned (1 when it plotted the point at once). kRestricted:
/// walk the transition matrix's Markov chain (Thollot et al. §3.2) instead of independent choices. kCondensation: the
/// loop for functions of other kinds: a function with points is Barnsley's condensation map (Sokolov & Gentil, §3.1),
/// the point jumps to a uniformly random sample of its set; a function with variations runs its variation stage.
template <bool kRestricted, bool kRestarts, bool kCondensation = false, class Plot>
[[gnu::always_inline]] inline int stepLane(ChainState& st, int lane, const HotIfs& ifs, Plot& plot, std::int64_t& bad) {
  if constexpr (kRestarts)
    if (++st.age[lane] > ifs.restartInterval) st.restartLane(lane, ifs.skip);
  std::uint32_t nextRow = kRestricted ? st.row[lane] : 0;
  const HotFunction& f = ifs.functions[ifs.pick<kRestricted>(nextRow, st.rng.next())];
  v4f p;
  if constexpr (kCondensation) {
    if (f.points) {
      const std::uint64_t r = std::uint32_t(st.rng.next());
      p = load4(f.points + 4 * ((r * f.pointCount) >> 32));
    } else if (f.variations) {
      p = applyVariations(f, st.p[lane], st.rng.state);
    } else {
      p = apply(f, st.p[lane]);
    }
  } else {
    p = apply(f, st.p[lane]);
  }
  const v4f col =
      st.color[lane] + (f.color - st.color[lane]) * f.speed;  // Draves & Reckase 2003, §5: c = mix(c, c_i, speed)
  if (!inBounds(p, ifs.escapeBound)) [[unlikely]] {
    ++bad;
    if (kCondensation && ifs.variations)
      st.replacePoint(lane);  // as flam3 does: a fresh random point, the chain goes on
    else
      st.restartLane(lane, ifs.skip);
    return 0;
  }
  return advanceAndPlot<kRestricted>(st, lane, ifs, plot, bad, p, col, nextRow);
}

/// A plotter that takes whole rounds of samples written in place (ZBufferPlot::freeRounds).
/// The type requirement comes first: the second is only checked for a plotter that has the type.
template <class Plot>
concept TakesWholeRounds = requires {
  typename Plot::ColourSlot;
}
&&requires(Plot& plot, v4f* points, typename Plot::ColourSlot* colours) { plot.freeRounds(points, colours); };

/// Rounds of an IFS of bounded grid maps (HotIfs::boundedMaps) without a final function, once
/// every lane is past its skip, for a plotter that takes whole rounds (ZBufferPlot): no lane can
/// escape, restart, skip or go through a final function, so a round is four picks, four grid maps
/// and four colour mixes written straight into the plotter's chunk. The same draws and float
/// operations in the same order as stepLane, without its checks, and with the chains' state, the
/// alias table and the functions in registers rather than reloaded around every plotted sample.
template <class Plot>
[[gnu::always_inline]] inline void runBoundedRounds(ChainState& st, const HotIfs& ifs, std::int64_t rounds,
                                                    Plot& plot) {
  static_assert(kLanes == 4);
  const HotFunction* const functions = ifs.functions;
  const AliasEntry* const alias = ifs.alias;
  const std::uint32_t count = ifs.count;
  Rng rng = st.rng;
  v4f p0 = st.p[0], p1 = st.p[1], p2 = st.p[2], p3 = st.p[3];
  v4f c0 = st.color[0], c1 = st.color[1], c2 = st.color[2], c3 = st.color[3];
  using ColourSlot = typename Plot::ColourSlot;
  const auto step = [&](v4f & p, v4f & col, v4f * pointSlot, ColourSlot * colorSlot) __attribute__((always_inline)) {
    const HotFunction& f = functions[HotIfs::chooseIn(alias, count, rng.next())];
    p = apply(f, p);
    col = col + (f.color - col) * f.speed;  // Draves & Reckase 2003, §5: c = mix(c, c_i, speed)
    *pointSlot = p;
    Plot::putColour(*colorSlot, col);
  };
  const auto round = [&](v4f * points, ColourSlot * colors, int n) __attribute__((always_inline)) {
    step(p0, c0, points + 4 * n, colors + 4 * n);
    step(p1, c1, points + 4 * n + 1, colors + 4 * n + 1);
    step(p2, c2, points + 4 * n + 2, colors + 4 * n + 2);
    step(p3, c3, points + 4 * n + 3, colors + 4 * n + 3);
  };
  while (rounds > 0) {
    v4f* points;
    ColourSlot* colors;
    const std::int64_t room = plot.freeRounds(points, colors);
    const int m = int(rounds < room ? rounds : room);
    int n = 0;
    if constexpr (requires { plot.takeStagedRounds(m); }) {
      // The staged chunk's writes, four between the steps of each round (ZBufferPlot::takeStagedRounds),
      // in loops of their own, so the rounds after them carry no check.
      const auto staged = plot.takeStagedRounds(m);
      if (staged.key)
        for (; n < staged.rounds; ++n) {
          round(points, colors, n);
          Plot::commitRound(staged, n);
        }
      else
        for (; n < staged.rounds; ++n) {
          round(points, colors, n);
          Plot::countRound(staged, n);
        }
    }
    for (; n < m; ++n) round(points, colors, n);
    plot.takeRounds(m);
    rounds -= m;
  }
  st.rng = rng;
  st.p[0] = p0, st.p[1] = p1, st.p[2] = p2, st.p[3] = p3;
  st.color[0] = c0, st.color[1] = c1, st.color[2] = c2, st.color[3] = c3;
}

/// The end of a run of a worker's chains (grid and free-form alike): the plotter's last chunk
/// drained and counted, the chains' state stored, the counters updated.
template <class Plot>
[[gnu::always_inline]] inline void finishRun(ChainState& st, const ChainState& local, Plot& plot, std::int64_t count,
                                             std::int64_t bad, std::int64_t plotted, ChainCounters& counters) {
  if constexpr (requires { plot.flush(); }) plot.flush();
  if constexpr (requires { plot.takePlotted(); }) plotted += plot.takePlotted();  // chunked plotters count late
  st = local;
  counters.samples += count;
  counters.bad += bad;
  counters.plotted += plotted;
}

/// Runs `count` iterations of the worker's chains (lane n % kLanes for the n-th one). `plot(q, color)`
/// receives each point past `skip` (after the final function) and returns whether it was plotted;
/// a plotter that plots in chunks returns 0 and reports its count through takePlotted() after flush().
template <class Plot>
[[gnu::always_inline]] inline void runChain(ChainState& st, const HotIfs& ifs, std::int64_t count, Plot& plot,
                                            ChainCounters& counters) {
  std::int64_t bad = 0, plotted = 0;
  // A local copy whose address never escapes stays in registers; the plotter's relaxed atomic
  // stores would otherwise make the compiler reload the state from memory after every plot.
  ChainState local = st;
  const std::int64_t rounds = count / kLanes;
  static_assert(kLanes == 4);
  if (ifs.batched) [[unlikely]] {
    // Flame variations, four lanes at a time; a last partial round lane by lane.
    for (std::int64_t n = 0; n < rounds; ++n) plotted += stepBatchedRound(local, ifs, plot, bad);
    for (int l = 0; l < int(count % kLanes); ++l) plotted += stepLane<false, false, true>(local, l, ifs, plot, bad);
  } else if (ifs.condensation || ifs.variations) [[unlikely]] {
    // Condensation maps (Sokolov & Gentil, §3.1) and flame variations in their own instantiations.
    auto lanes = [&]<bool kRestricted, bool kRestarts>() {
      for (std::int64_t n = 0; n < rounds; ++n)
        for (int l = 0; l < kLanes; ++l) plotted += stepLane<kRestricted, kRestarts, true>(local, l, ifs, plot, bad);
      for (int l = 0; l < int(count % kLanes); ++l)
        plotted += stepLane<kRestricted, kRestarts, true>(local, l, ifs, plot, bad);
    };
    if (ifs.transitionWalk && ifs.restartInterval)
      lanes.template operator()<true, true>();
    else if (ifs.transitionWalk)
      lanes.template operator()<true, false>();
    else
      lanes.template operator()<false, false>();
  } else if (ifs.transitionWalk && ifs.restartInterval) {
    // The restricted loop is a separate instantiation, so the unrestricted one is unchanged.
    for (std::int64_t n = 0; n < rounds; ++n)
      for (int l = 0; l < kLanes; ++l) plotted += stepLane<true, true>(local, l, ifs, plot, bad);
    for (int l = 0; l < int(count % kLanes); ++l) plotted += stepLane<true, true>(local, l, ifs, plot, bad);
  } else if (ifs.transitionWalk) {
    for (std::int64_t n = 0; n < rounds; ++n) {
      plotted += stepLane<true, false>(local, 0, ifs, plot, bad);
      plotted += stepLane<true, false>(local, 1, ifs, plot, bad);
      plotted += stepLane<true, false>(local, 2, ifs, plot, bad);
      plotted += stepLane<true, false>(local, 3, ifs, plot, bad);
    }
    for (int l = 0; l < int(count % kLanes); ++l) plotted += stepLane<true, false>(local, l, ifs, plot, bad);
  } else {
    std::int64_t n = 0;
    if constexpr (TakesWholeRounds<Plot>) {
      if (ifs.boundedMaps && !ifs.finalFunction) {
        // The rounds in which some lane still skips as below, then every other round unchecked.
        const auto skipping = [&local] {
          return (local.skipLeft[0] > 0) | (local.skipLeft[1] > 0) | (local.skipLeft[2] > 0) | (local.skipLeft[3] > 0);
        };
        for (; n < rounds && skipping(); ++n)
          for (int l = 0; l < kLanes; ++l) plotted += stepLane<false, false>(local, l, ifs, plot, bad);
        runBoundedRounds(local, ifs, rounds - n, plot);
        n = rounds;
      }
    }
    for (; n < rounds; ++n) {
      plotted += stepLane<false, false>(local, 0, ifs, plot, bad);
      plotted += stepLane<false, false>(local, 1, ifs, plot, bad);
      plotted += stepLane<false, false>(local, 2, ifs, plot, bad);
      plotted += stepLane<false, false>(local, 3, ifs, plot, bad);
    }
    for (int l = 0; l < int(count % kLanes); ++l) plotted += stepLane<false, false>(local, l, ifs, plot, bad);
  }
  finishRun(st, local, plot, count, bad, plotted, counters);
}

/// Packs r g b c in [0, 1] into 4 bytes (r in the low byte).
[[gnu::always_inline]] inline std::uint32_t packColor(v4f c) {
#if defined(__SSE2__)
  const __m128 scaled = _mm_add_ps(_mm_mul_ps(__m128(c), _mm_set1_ps(255.0f)), _mm_set1_ps(0.5f));
  // No max with 0: NaN, negatives and values past the int range convert to INT_MIN or a negative
  // number, which the saturating packs turn into 0, as they would 0 itself.
  const __m128i i32 = _mm_cvttps_epi32(scaled);
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
  v4f size;  // width, height, 1, 1
  float nearPlane;
  std::uint32_t stride;
  /// What the plotters project with (render/camera.h's conventions), per eye (the same twice
  /// without stereo; in stereo, sample k of every eight goes to eye k mod 2): rows[eye][r][c],
  /// the pixel rows (x·w, y·w, w, depth) of a flat camera or the view rows (x, y, z, unused) of
  /// a panoramic one; the eye's pixels [x0, x1) × [y0, y1) of the frame.
  float rows[2][4][4] = {};
  float bounds[2][4] = {};
  enum Kind : std::uint8_t { Flat, Fisheye, Equirectangular } kind = Flat;
  bool stereo = false;      // panoramic: omni-directional stereo
  float centre[2][2] = {};  // panoramic: the eye image's centre, frame pixels
  float pixelsPerRadian = 1.0f, halfFov = 0.0f;
  float radius = 0.0f;      // omni-directional stereo: half the eye separation
  float up[3] = {0, 1, 0};  // the world's vertical axis in view space
  float turn[2][9] = {};    // per eye, row major: the convergence turn
  float sign[2] = {-1, 1};  // the eyes' sides
};

inline constexpr std::uint64_t kEmptyKey = ~std::uint64_t(0);

/// One pixel of a worker's buffers: the z-buffer key and the hit count share a 16-byte cell, so a
/// plotted sample touches one cache line, not two (the buffers are far larger than the caches).
struct alignas(16) PixelCell {
  std::uint64_t key = kEmptyKey;  // depth bits << 32 | packed colour; kEmptyKey when no point
  std::uint32_t density = 0;
  std::uint32_t unused = 0;
};

inline HotCamera makeHotCamera(const OrbitCamera& camera) {
  const OrbitCamera::PixelRows rows = camera.pixelRows();
  HotCamera hot{};
  v4f* columns[4] = {&hot.cx, &hot.cy, &hot.cz, &hot.c1};
  for (int c = 0; c < 4; ++c) *columns[c] = v4f{rows.rowX[c], rows.rowY[c], rows.rowW[c], rows.rowD[c]};
  hot.size = v4f{float(camera.width()), float(camera.height()), 1.0f, 1.0f};
  hot.nearPlane = float(camera.nearPlane());
  hot.stride = std::uint32_t(camera.width());
  for (int eye = 0; eye < 2; ++eye) {
    const int source = camera.eyes() == 2 ? eye : 0;
    const OrbitCamera::PixelRows r = camera.pixelRows(source);
    const float* rowOf[4] = {r.rowX, r.rowY, r.rowW, r.rowD};
    for (int row = 0; row < 4; ++row)
      for (int c = 0; c < 4; ++c) hot.rows[eye][row][c] = rowOf[row][c];
    const EyeRegion region = camera.eyeRegion(source);
    hot.bounds[eye][0] = float(region.x);
    hot.bounds[eye][1] = float(region.x + region.width);
    hot.bounds[eye][2] = float(region.y);
    hot.bounds[eye][3] = float(region.y + region.height);
    hot.centre[eye][0] = float(region.x + 0.5 * region.width);
    hot.centre[eye][1] = float(region.y + 0.5 * region.height);
    const glm::dmat3& turn = camera.eyeTurn(source);
    for (int row = 0; row < 3; ++row)
      for (int c = 0; c < 3; ++c) hot.turn[eye][3 * row + c] = float(turn[c][row]);
  }
  if (camera.panoramic()) {
    hot.kind =
        camera.settings().projection == CameraProjection::Fisheye ? HotCamera::Fisheye : HotCamera::Equirectangular;
    hot.pixelsPerRadian = float(camera.pixelsPerRadian());
    hot.halfFov = float(camera.settings().fov * (M_PI / 360.0));
    hot.stereo = camera.eyes() == 2;
    hot.radius = float(camera.stereoRadius());
    const glm::dvec3 up = camera.viewUp();
    for (int d = 0; d < 3; ++d) hot.up[d] = float(up[d]);
  }
  return hot;
}

/// Eight 4-lane vectors as four 8-lane rows (lane k of row j is element j of vector k): points
/// or colours as x, y, z (, w) rows for the plotters' eight-at-a-time projections.
[[gnu::always_inline]] inline void transposeEight(const v4f* v, v8f& r0, v8f& r1, v8f& r2, v8f& r3) {
  v4f out[4][2];
  for (int h = 0; h < 2; ++h) {
    const v4f a = v[4 * h], b = v[4 * h + 1], c = v[4 * h + 2], d = v[4 * h + 3];
    const v4f ab01 = __builtin_shufflevector(a, b, 0, 4, 1, 5), cd01 = __builtin_shufflevector(c, d, 0, 4, 1, 5);
    const v4f ab23 = __builtin_shufflevector(a, b, 2, 6, 3, 7), cd23 = __builtin_shufflevector(c, d, 2, 6, 3, 7);
    out[0][h] = __builtin_shufflevector(ab01, cd01, 0, 1, 4, 5);
    out[1][h] = __builtin_shufflevector(ab01, cd01, 2, 3, 6, 7);
    out[2][h] = __builtin_shufflevector(ab23, cd23, 0, 1, 4, 5);
    out[3][h] = __builtin_shufflevector(ab23, cd23, 2, 3, 6, 7);
  }
  r0 = __builtin_shufflevector(out[0][0], out[0][1], 0, 1, 2, 3, 4, 5, 6, 7);
  r1 = __builtin_shufflevector(out[1][0], out[1][1], 0, 1, 2, 3, 4, 5, 6, 7);
  r2 = __builtin_shufflevector(out[2][0], out[2][1], 0, 1, 2, 3, 4, 5, 6, 7);
  r3 = __builtin_shufflevector(out[3][0], out[3][1], 0, 1, 2, 3, 4, 5, 6, 7);
}

/// A panoramic camera's per-lane constants at the width V: eight lanes, or sixteen as two
/// groups of eight (lane k still of eye k mod 2).
template <class V>
struct PanoramicLanes {
  V centreX, centreY, pixelsPerRadian, halfFov, twicePixelsPerRadian, halfAngleTanSquared;
  V radiusSquared, radiusTimesSign, up[3], turn[9];
};
/// What the plotters project eight samples at a time with: a HotCamera's numbers per lane (pixel
/// rows, the eye's pixels, the panoramic constants), built once per chunk. Lane k takes eye k mod 2.
struct ProjectionLanes {
  v8f rows[4][4];      // rows[r][c] per lane: the lane's eye's row r, coefficient c
  v8f x0, x1, y0, y1;  // per lane: the eye's pixels
  v8f nearPlane;
  std::uint32_t stride;
  HotCamera::Kind kind;
  bool stereo;
  bool hemisphere;  // a fisheye of at most 180°
  // Panoramic: the centre and scale; for a hemisphere 2·pixelsPerRadian and tan²(halfFov/2);
  // for omni-directional stereo the eyes' circle, the world's up and the convergence turn.
  PanoramicLanes<v8f> lanes;
};
inline ProjectionLanes projectionLanes(const HotCamera& cam) {
  ProjectionLanes p;
  // Lane k takes eye k mod 2 (by reference: a lambda returning an eight-lane vector would cross
  // the ABI that differs without AVX).
  auto lanes = [](v8f& out, float left, float right) {
    for (int k = 0; k < 8; ++k) out[k] = (k & 1) ? right : left;
  };
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) lanes(p.rows[r][c], cam.rows[0][r][c], cam.rows[1][r][c]);
  lanes(p.x0, cam.bounds[0][0], cam.bounds[1][0]);
  lanes(p.x1, cam.bounds[0][1], cam.bounds[1][1]);
  lanes(p.y0, cam.bounds[0][2], cam.bounds[1][2]);
  lanes(p.y1, cam.bounds[0][3], cam.bounds[1][3]);
  p.nearPlane = v8f{} + cam.nearPlane;
  p.stride = cam.stride;
  p.kind = cam.kind;
  p.stereo = cam.stereo;
  lanes(p.lanes.centreX, cam.centre[0][0], cam.centre[1][0]);
  lanes(p.lanes.centreY, cam.centre[0][1], cam.centre[1][1]);
  p.lanes.pixelsPerRadian = v8f{} + cam.pixelsPerRadian;
  p.lanes.halfFov = v8f{} + cam.halfFov;
  p.hemisphere = cam.kind == HotCamera::Fisheye && cam.halfFov <= float(M_PI / 2);
  const float halfAngleTan = std::tan(0.5f * cam.halfFov);
  p.lanes.twicePixelsPerRadian = v8f{} + 2.0f * cam.pixelsPerRadian;
  p.lanes.halfAngleTanSquared = v8f{} + halfAngleTan * halfAngleTan;
  p.lanes.radiusSquared = v8f{} + cam.radius * cam.radius;
  lanes(p.lanes.radiusTimesSign, cam.radius * cam.sign[0], cam.radius * cam.sign[1]);
  for (int d = 0; d < 3; ++d) p.lanes.up[d] = v8f{} + cam.up[d];
  for (int k = 0; k < 9; ++k) lanes(p.lanes.turn[k], cam.turn[0][k], cam.turn[1][k]);
  return p;
}

// The panoramic projections' math (render/panoramic_lanes.inc), compiled for eight lanes
// everywhere (with the kernels' AVX2 and baseline clones) and for AVX-512's sixteen where GCC
// builds the kernels' clones. Sixteen lanes carry two groups of eight in every instruction, so
// the long dependent chain of one group (square roots, a division, the arctangents'
// polynomials) overlaps the other's where eight lanes left the CPU waiting: equirectangular
// 0.80 → 0.95 of perspective's samples per second (docs/CAMERAS.md). Both widths do the same
// float operations per lane, so the pictures are the same bits on every CPU.
#define GRIDIFS_LANES_FUNCTION GRIDIFS_KERNEL_CLONES
namespace eight_lanes {
using Lanes = v8f;
[[gnu::always_inline]] inline void widen(const v8f& x, Lanes& out) { out = x; }
/// Eight points as x, y and z lanes.
[[gnu::always_inline]] inline void loadLanes(const v4f* points, Lanes& x, Lanes& y, Lanes& z) {
  v8f w;
  transposeEight(points, x, y, z, w);
}
#include "render/panoramic_lanes.inc"
}  // namespace eight_lanes
#undef GRIDIFS_LANES_FUNCTION

// A region whose target is AVX-512, not a template instantiated for sixteen lanes: a template's
// body is compiled for the default target first, where a sixteen-lane comparison used as a
// condition is lowered lane by lane, and it stays so once inlined.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GRIDIFS_NO_KERNEL_CLONES)
#define GRIDIFS_SIXTEEN_LANES 1
#pragma GCC push_options
#pragma GCC target("arch=x86-64-v4")
#define GRIDIFS_LANES_FUNCTION [[gnu::noinline]]
namespace sixteen_lanes {
using Lanes = v16f;
/// Eight lanes' constants for two groups of eight (lane k still of eye k mod 2).
[[gnu::always_inline]] inline void widen(const v8f& x, Lanes& out) {
  out = __builtin_shufflevector(x, x, 0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7);
}
/// Sixteen points as x, y and z lanes: two groups of eight side by side.
[[gnu::always_inline]] inline void loadLanes(const v4f* points, Lanes& x, Lanes& y, Lanes& z) {
  v8f xa, ya, za, wa, xb, yb, zb, wb;
  transposeEight(points, xa, ya, za, wa);
  transposeEight(points + 8, xb, yb, zb, wb);
  x = __builtin_shufflevector(xa, xb, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  y = __builtin_shufflevector(ya, yb, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  z = __builtin_shufflevector(za, zb, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
}
#include "render/panoramic_lanes.inc"
}  // namespace sixteen_lanes
#undef GRIDIFS_LANES_FUNCTION
#pragma GCC pop_options
#else
#define GRIDIFS_SIXTEEN_LANES 0
#endif

/// The z-buffer plotter (Gröller & Wegenkittl 1994, §3.1). Keys are (depth bits << 32 | packed colour): depth is
/// positive, so unsigned order is depth order and equal depths fall back to the colour, which makes
/// the per-pixel minimum independent of sample and worker order. Buffer accesses go through
/// std::atomic_ref with relaxed order: plain moves on x86, but snapshot() may read them while
/// the worker writes.
///
/// Samples are collected in chunks and plotted a chunk at a time, away from the chaos game's loop,
/// which only stores the point and its colour. Why: one sample at a time, the projection, the
/// colour packing and the read-modify-write of a cell far out in the buffers (which are far larger
/// than the caches) shared the loop's registers and its few cache misses in flight with the
/// function evaluations. A chunk is projected eight samples at once; every cell it touches is
/// prefetched before the first is written; then the cells are updated in sample order, so every
/// pixel still receives its colour additions in sample order and the sums are bit-identical to
/// plotting at once. The projection is the same float operations, in the same order, as one
/// sample at a time. runChain calls flush() and takes the plotted count with takePlotted().
template <bool kAccumulateColor>
struct ZBufferPlot {
  HotCamera cam;
  PixelCell* cells;
  std::uint64_t* colorSums;  // 4 per pixel, fixed point (render/accumulation.h), only with kAccumulateColor
  /// Optional: 257 entries r g b 0 (the last repeats entry 255). When set, colorSums
  /// receive the palette color at c for every sample, as flam3 does (Draves & Reckase 2003, §5), instead of
  /// the blended RGB; lane 3 still sums c.
  const v4f* palette = nullptr;
  /// False: hit counts (and colour sums) only, the keys stay kEmptyKey (RenderJob::depthKeys).
  bool keys = true;

  ZBufferPlot() = default;
  ZBufferPlot(const HotCamera& camera, PixelCell* cellBuffer, std::uint64_t* sums, const v4f* paletteEntries = nullptr)
      : cam(camera), cells(cellBuffer), colorSums(sums), palette(paletteEntries) {}

  // Every sample of a chunk has its lines prefetched before the first is written: 256 samples
  // of one line each for the z-buffer, and 64 for the flame display, whose colour sums are a second
  // line per sample (with 256, the first prefetched lines were gone again by their turn: 64 takes
  // 4–5 % fewer CPU seconds for a 400×300 flame, the same image).
  static constexpr int kChunk = kAccumulateColor ? 64 : 256;
  static constexpr int kGroup = 8;  // samples projected at once
  static_assert(kChunk % kGroup == 0 && kChunk % kLanes == 0);
  v4f points[kChunk] = {};
  /// A sample's colour as the plotter keeps it: the running colour for the flame display's sums,
  /// packed (packColor) for the z-buffer's key, done by the chaos game's loop, whose idle issue
  /// slots take it for free, instead of eight at a time here.
  using ColourSlot = std::conditional_t<kAccumulateColor, v4f, std::uint32_t>;
  ColourSlot colors[kChunk] = {};
  [[gnu::always_inline]] static void putColour(ColourSlot& slot, v4f col) {
    if constexpr (kAccumulateColor)
      slot = col;
    else
      slot = packColor(col);
  }
  int count = 0;
  std::int64_t plotted = 0;  // samples of drained chunks that landed in the image

  /// Collects a sample; it is counted as plotted by takePlotted() once its chunk is drained.
  [[gnu::always_inline]] int operator()(v4f q, v4f col) {
    points[count] = q;
    putColour(colors[count], col);
    if (++count == kChunk) [[unlikely]]
      drain();
    return 0;
  }

  void flush() {
    if constexpr (!kAccumulateColor) commitStagedRest();
    if (count > 0) drain();
  }

  /// The samples plotted since the last call (after flush(), all of them).
  std::int64_t takePlotted() {
    const std::int64_t n = plotted;
    plotted = 0;
    return n;
  }

  /// For loops whose every sample is plotted (runBoundedRounds): how many whole rounds of kLanes
  /// samples fit into the chunk, and where the first goes. A chunk without room for one round is
  /// projected first (the z-buffer: staged, see takeStagedRounds).
  [[gnu::always_inline]] std::int64_t freeRounds(v4f*& pointSlots, ColourSlot*& colorSlots) {
    if (count > kChunk - kLanes) [[unlikely]] {
      if constexpr (kAccumulateColor) {
        drain();
      } else {
        commitStagedRest();
        stage();
      }
    }
    pointSlots = points + count;
    colorSlots = colors + count;
    return (kChunk - count) / kLanes;
  }
  [[gnu::always_inline]] void takeRounds(int rounds) { count += rounds * kLanes; }

  /// The z-buffer's staged writes, handed to the chaos game's loop. Why: one chain step waits on
  /// the one before (the point's cell, its loads, its lerps), so the chaos game leaves many of the
  /// CPU's issue slots idle, while the writes of a projected chunk are independent of it and of
  /// each other. Interleaved, kLanes writes of the last chunk with each round of the next
  /// (commitRound, or countRound without keys), they fill those slots. Each pixel still receives
  /// its writes in sample order: a staged chunk is written entirely before the next is staged.
  struct StagedRounds {
    const std::uintptr_t* cell;  // the cells of the staged writes from the first handed round on
    const std::uint64_t* key;    // their keys; null when the plotter keeps no keys
    int rounds;                  // rounds of kLanes writes handed over
  };
  /// Hands up to `rounds` rounds of the staged writes over; the caller does every one of them
  /// before it next asks for free rounds.
  [[gnu::always_inline]] StagedRounds takeStagedRounds(int rounds) requires(!kAccumulateColor) {
    const int left = (kChunk - stagedNext) / kLanes;
    const StagedRounds staged{stagedCell + stagedNext, keys ? stagedKey + stagedNext : nullptr,
                              rounds < left ? rounds : left};
    stagedNext += staged.rounds * kLanes;
    return staged;
  }
  [[gnu::always_inline]] static void commitRound(const StagedRounds& staged, int n) {
    for (int k = 0; k < kLanes; ++k)
      commit(*reinterpret_cast<PixelCell*>(staged.cell[kLanes * n + k]), staged.key[kLanes * n + k]);
  }
  [[gnu::always_inline]] static void countRound(const StagedRounds& staged, int n) {
    for (int k = 0; k < kLanes; ++k) countHit(*reinterpret_cast<PixelCell*>(staged.cell[kLanes * n + k]));
  }

  /// Plots the collected chunk (after the staged one, when there is one).
  void drain() {
    if constexpr (kAccumulateColor) {
      drainColourSums();
    } else {
      commitStagedRest();
      stage();
      commitStagedRest();
    }
  }

 private:
  // The staged chunk (z-buffer only): each sample's cell (the scratch cell for one outside the
  // image and past a partial chunk's end) and key, in sample order; entries from stagedNext on
  // are not yet written.
  static_assert(sizeof(std::uintptr_t) == sizeof(std::uint64_t));
  alignas(32) std::uintptr_t stagedCell[kAccumulateColor ? 1 : kChunk];
  alignas(32) std::uint64_t stagedKey[kAccumulateColor ? 1 : kChunk];
  int stagedNext = kChunk;
  PixelCell scratch;

  [[gnu::always_inline]] void commitStaged(int j) {
    if (keys)
      commit(*reinterpret_cast<PixelCell*>(stagedCell[j]), stagedKey[j]);
    else
      countHit(*reinterpret_cast<PixelCell*>(stagedCell[j]));
  }

  void commitStagedRest() {
    for (int j = stagedNext; j < kChunk; ++j) commitStaged(j);
    stagedNext = kChunk;
  }

  /// Eight samples of a flat camera projected: pixel index (0 outside), depth and whether they land (Gröller &
  /// Wegenkittl 1994, §3.1: the camera's pixel rows), the same float operations as one sample at
  /// a time. NaN points fall outside.
  template <class V8u, class V8i>
  [[gnu::always_inline]] static void projectEight(const ProjectionLanes& pr, const v4f* eight, V8u& pixel, v8f& depth,
                                                  V8i& inside) {
    v8f x, y, z, unused;
    transposeEight(eight, x, y, z, unused);
    // r = cx·x + cy·y + cz·z + c1 per row, as one sample at a time (no FMA contraction).
    v8f px = pr.rows[0][0] * x + pr.rows[0][1] * y + pr.rows[0][2] * z + pr.rows[0][3];
    v8f py = pr.rows[1][0] * x + pr.rows[1][1] * y + pr.rows[1][2] * z + pr.rows[1][3];
    v8f pw = pr.rows[2][0] * x + pr.rows[2][1] * y + pr.rows[2][2] * z + pr.rows[2][3];
    depth = pr.rows[3][0] * x + pr.rows[3][1] * y + pr.rows[3][2] * z + pr.rows[3][3];
    const v8f reciprocal = 1.0f / pw;
    const v8f ix = px * reciprocal, iy = py * reciprocal;
    // NaN fails every comparison, so it falls outside.
    inside = (depth > pr.nearPlane) & (ix >= pr.x0) & (ix < pr.x1) & (iy >= pr.y0) & (iy < pr.y1);
    const V8u column = V8u(__builtin_convertvector(inside ? ix : v8f{}, V8i));
    const V8u row = V8u(__builtin_convertvector(inside ? iy : v8f{}, V8i));
    pixel = row * pr.stride + column;
  }
  /// The collected samples rounded up to whole groups: of eight, or sixteen for a panoramic
  /// camera, which may project sixteen at once.
  int paddedCount() const {
    const int group = cam.kind == HotCamera::Flat ? kGroup : 2 * kGroup;
    return (count + group - 1) / group * group;
  }
  /// A chunk's groups of a panoramic camera, projected before any is staged (see stage()).
  template <class V8u, class V8i>
  struct PanoramicGroups {
    V8u pixel[kChunk / kGroup];
    v8f depth[kChunk / kGroup];
    V8i inside[kChunk / kGroup];
    void project(const ProjectionLanes& pr, const v4f* points, int n) {
      auto* const pixels = reinterpret_cast<std::uint32_t*>(pixel);
      auto* const depths = reinterpret_cast<float*>(depth);
      auto* const insides = reinterpret_cast<std::int32_t*>(inside);
#if GRIDIFS_SIXTEEN_LANES
      static const bool sixteenLanes = __builtin_cpu_supports("x86-64-v4");
      if (sixteenLanes) return sixteen_lanes::projectChunk(pr, points, n, pixels, depths, insides);
#endif
      eight_lanes::projectChunk(pr, points, n, pixels, depths, insides);
    }
    [[gnu::always_inline]] void take(int i, V8u& p, v8f& d, V8i& in) const {
      p = pixel[i / kGroup];
      d = depth[i / kGroup];
      in = inside[i / kGroup];
    }
  };
  /// The eight samples' keys: depth bits << 32 | packed colour (packColor, eight at a time).
  template <class V8u>
  [[gnu::always_inline]] static void keysOfEight(const v4f* colours, const v8f& depth, V8u& high, V8u& low) {
    v8f red, green, blue, c;
    transposeEight(colours, red, green, blue, c);
    V8u r8, g8, b8, c8;
    channelByte(red, r8);
    channelByte(green, g8);
    channelByte(blue, b8);
    channelByte(c, c8);
    low = r8 | g8 << 8 | b8 << 16 | c8 << 24;
    high = V8u(depth);
  }

  /// Projects a chunk's n points (a multiple of kGroup) eight at a time and hands each group to
  /// body(i, pixel, depth, inside). A panoramic camera's groups are projected first, all of them,
  /// and handed over after: its projection is a long chain of dependent operations (a square
  /// root, a division, the arctangents' polynomials), and with nothing but projections between
  /// them the CPU overlaps the chains of consecutive groups (equirectangular 0.71 → 0.80 of
  /// perspective's samples per second). A flat camera's short projection gains nothing from it
  /// and stays in one loop.
  template <class V8u, class V8i, class Body>
  [[gnu::always_inline]] static void forEachProjectedGroup(const ProjectionLanes& pr, const v4f* points, int n,
                                                           Body&& body) {
    PanoramicGroups<V8u, V8i> panoramic;
    if (pr.kind != HotCamera::Flat) panoramic.project(pr, points, n);
    for (int i = 0; i < n; i += kGroup) {
      V8u pixel;
      v8f depth;
      V8i inside;
      if (pr.kind == HotCamera::Flat)
        projectEight(pr, points + i, pixel, depth, inside);
      else
        panoramic.take(i, pixel, depth, inside);
      body(i, pixel, depth, inside);
    }
  }

  /// Projects the collected chunk into the staged entries and prefetches their cells (z-buffer).
  /// Out of line (once per chunk), compiled for the CPU like the chaos game's kernel.
  [[gnu::noinline]] GRIDIFS_KERNEL_CLONES void stage() {
    typedef std::int32_t v8i __attribute__((vector_size(32)));
    typedef std::uint32_t v8u __attribute__((vector_size(32)));
    // A partial chunk is padded with NaN points, which fall outside the image.
    const int n = paddedCount();
    for (int i = count; i < n; ++i) {
      points[i] = v4f{} + __builtin_nanf("");
      colors[i] = 0;
    }
    const ProjectionLanes pr = projectionLanes(cam);
    typedef std::uint64_t v4u64 __attribute__((vector_size(32)));
    typedef std::int64_t v4i64 __attribute__((vector_size(32)));
    const v4u64 cellBase = v4u64{} + std::uint64_t(reinterpret_cast<std::uintptr_t>(cells));
    const v4u64 scratchCell = v4u64{} + std::uint64_t(reinterpret_cast<std::uintptr_t>(&scratch));
    v8i landed{};
    const auto stageGroup = [&](int i, const v8u& pixel, const v8f& depth, const v8i& inside)
        __attribute__((always_inline)) {
      // Every sample keeps its place, so there is no branch per sample (which mispredicted
      // wherever a fifth of the samples fall outside, as spherical flames' do) and no list to
      // build: one outside, the NaN padding too, writes the scratch cell.
      for (int h = 0; h < 2; ++h) {
        const v4u64 offset = __builtin_convertvector(
            h ? __builtin_shufflevector(pixel, pixel, 4, 5, 6, 7) : __builtin_shufflevector(pixel, pixel, 0, 1, 2, 3),
            v4u64);
        const v4i64 lands = __builtin_convertvector(h ? __builtin_shufflevector(inside, inside, 4, 5, 6, 7)
                                                      : __builtin_shufflevector(inside, inside, 0, 1, 2, 3),
                                                    v4i64);
        const v4u64 cell = lands != 0 ? cellBase + offset * sizeof(PixelCell) : scratchCell;
        std::memcpy(stagedCell + i + 4 * h, &cell, sizeof cell);
      }
      for (int k = 0; k < kGroup; ++k) __builtin_prefetch(reinterpret_cast<const void*>(stagedCell[i + k]), 1);
      if (keys) {
        v8u low;
        std::memcpy(&low, colors + i, sizeof low);
        const v8u high = v8u(depth);
        const v8u first = __builtin_shufflevector(low, high, 0, 8, 1, 9, 2, 10, 3, 11);
        const v8u second = __builtin_shufflevector(low, high, 4, 12, 5, 13, 6, 14, 7, 15);
        std::memcpy(stagedKey + i, &first, sizeof first);
        std::memcpy(stagedKey + i + 4, &second, sizeof second);
      }
      landed -= inside;  // -1 where a sample lands
    };
    forEachProjectedGroup<v8u, v8i>(pr, points, n, stageGroup);
    for (int j = n; j < kChunk; ++j) {
      stagedCell[j] = reinterpret_cast<std::uintptr_t>(&scratch);
      stagedKey[j] = kEmptyKey;
    }
    std::int64_t landedCount = 0;
    for (int k = 0; k < kGroup; ++k) landedCount += landed[k];
    plotted += landedCount;
    stagedNext = 0;
    count = 0;
  }

  /// Plots the collected chunk of the flame display: hit counts and colour sums (and keys). Out
  /// of line (once per chunk), compiled for the CPU like the chaos game's kernel.
  [[gnu::noinline]] GRIDIFS_KERNEL_CLONES void drainColourSums() {
    typedef std::int32_t v8i __attribute__((vector_size(32)));
    typedef std::uint32_t v8u __attribute__((vector_size(32)));
    const int n = paddedCount();
    for (int i = count; i < n; ++i) {
      points[i] = v4f{} + __builtin_nanf("");
      colors[i] = v4f{};
    }
    alignas(32) std::uint32_t pixels[kChunk];  // 0 for a sample outside
    alignas(32) std::uint64_t keysOf[kChunk];
    std::uint16_t landed[kChunk];
    int landedCount = 0;
    const ProjectionLanes pr = projectionLanes(cam);
    const auto listGroup = [&](int i, const v8u& pixel, const v8f& depth, const v8i& inside)
        __attribute__((always_inline)) {
      std::memcpy(pixels + i, &pixel, sizeof pixel);
      if (keys) {
        v8u high, low;
        keysOfEight(colors + i, depth, high, low);
        for (int k = 0; k < kGroup; ++k) keysOf[i + k] = std::uint64_t(high[k]) << 32 | low[k];
      }
      for (int k = 0; k < kGroup; ++k) {
        // Outside samples prefetch pixel 0 (a line already at hand) and are not listed.
        __builtin_prefetch(cells + pixels[i + k], 1);
        __builtin_prefetch(colorSums + std::size_t(pixels[i + k]) * 4, 1);
        landed[landedCount] = std::uint16_t(i + k);
        landedCount += inside[k] != 0;  // the NaN padding is outside
      }
    };
    forEachProjectedGroup<v8u, v8i>(pr, points, n, listGroup);
    // The buffers' addresses in locals: the compiler cannot tell that the cells' stores leave
    // these members alone, and reloaded them for every sample.
    PixelCell* const cellBase = cells;
    std::uint64_t* const sumBase = colorSums;
    if (keys) {
      for (int j = 0; j < landedCount; ++j) {
        const int i = landed[j];
        commit(cellBase[pixels[i]], keysOf[i]);
        addColor(sumBase + std::size_t(pixels[i]) * 4, colors[i]);
      }
    } else {
      for (int j = 0; j < landedCount; ++j) {
        const int i = landed[j];
        countHit(cellBase[pixels[i]]);
        addColor(sumBase + std::size_t(pixels[i]) * 4, colors[i]);
      }
    }
    plotted += landedCount;
    count = 0;
  }

  [[gnu::always_inline]] static void commit(PixelCell& cell, std::uint64_t key) {
    std::atomic_ref<std::uint64_t> z(cell.key);
    // The nearer key stored every time, not behind a branch on the depth test: the line is
    // written anyway (the hit count), and the branch mispredicted whenever a sample came nearer
    // than all before it.
    const std::uint64_t old = z.load(std::memory_order_relaxed);
    z.store(key < old ? key : old, std::memory_order_relaxed);
    countHit(cell);
  }

  [[gnu::always_inline]] static void countHit(PixelCell& cell) {
#if defined(__x86_64__) && defined(__GNUC__)
    // The saturating increment in place: the carry of n - 0xFFFFFFFF is set exactly when n is
    // below the maximum. Two instructions where the load, compare, add and store were five; the
    // count is still written by one aligned 4-byte store, which a concurrent reader sees whole,
    // as with the relaxed atomic store.
    asm("cmpl $-1, %0\n\tadcl $0, %0" : "+m"(cell.density) : : "cc");
#else
    std::atomic_ref<std::uint32_t> d(cell.density);
    const std::uint32_t n = d.load(std::memory_order_relaxed);
    d.store(n + (n != 0xFFFFFFFFu), std::memory_order_relaxed);  // saturating
#endif
  }

  /// Adds the sample's colour in fixed point, round(v · 2^16) per channel with v clamped to
  /// [0, 1] (as the GPU does): integer sums do not depend on the order of the samples, so the
  /// sums are the same for any thread count and any split of the render into parts.
  [[gnu::always_inline]] void addColor(std::uint64_t* sums, v4f col) const {
    v4f add = col;
    if (palette) {  // flam3's linear palette mode: index c·256, blend entries i and i+1
      float x = col[3] * 256.0f;
      x = x > 0.0f ? (x < 256.0f ? x : 256.0f) : 0.0f;  // NaN → 0
      const int i = int(x) < 255 ? int(x) : 255;
      const float frac = x - float(i);
      add = palette[i] + (palette[i + 1] - palette[i]) * frac;
      add[3] = col[3];
    }
    add = add > 0.0f ? add : v4f{};  // NaN → 0
    add = add < 1.0f ? add : v4f{} + 1.0f;
    const v4i fixed = __builtin_convertvector(add * 65536.0f + 0.5f, v4i);
    // Unrolled: as a loop, the four values went through the stack, and each add waited on them.
#pragma GCC unroll 4
    for (int k = 0; k < 4; ++k) {
#if defined(__x86_64__) && defined(__GNUC__)
      // One add to memory per channel where the load, add and store were three: the sum is still
      // written by one aligned 8-byte store, which a concurrent reader sees whole (countHit).
      asm("addq %1, %0" : "+m"(sums[k]) : "r"(std::uint64_t(std::uint32_t(fixed[k]))) : "cc");
#else
      std::atomic_ref<std::uint64_t> s(sums[k]);
      s.store(s.load(std::memory_order_relaxed) + std::uint32_t(fixed[k]), std::memory_order_relaxed);
#endif
    }
  }

  /// packColor's byte for eight values of one channel: round(v·255) in [0, 255], NaN → 0.
  template <class V8u>
  [[gnu::always_inline]] static void channelByte(const v8f& v, V8u& out) {
    typedef std::int32_t v8i __attribute__((vector_size(32)));
    v8f scaled = v * 255.0f + 0.5f;
    scaled = scaled > 0.0f ? scaled : v8f{};  // NaN → 0, as maxps(scaled, 0)
    scaled = scaled < 255.0f ? scaled : v8f{} + 255.0f;
    out = V8u(__builtin_convertvector(scaled, v8i));
  }
};

}  // namespace gridifs::kernel
