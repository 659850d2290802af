#pragma once
// Internal to the renderer: the chaos game of a free-form IFS (Thollot, Zair, Tosan & Vandorpe
// 1997, §3.1). Each chain carries m barycentric coordinates λ; a step picks a matrix T like the
// grid kernel picks a function (weights, transition rows), sets λ ← λ·T and plots
// P·λ = Σ_j λ_j p_j. The compiled rows also hold (T·P)_i, so the plotted point comes out of the
// same pass over the rows: q = Σ_i λ_i (T·P)_i. Colour, skip, escape, the final function and the
// plotters are those of chaos_kernel.h.
#include <algorithm>
#include <vector>

#include "render/chaos_kernel.h"

namespace gridifs::kernel {

inline constexpr int kMaxBarycentricPad = 64;

/// Copies a free-form IFS's space into `hot` (nothing for a grid IFS). Throws ModelError when the
/// compiled space does not fit this kernel.
inline void attachBarycentric(HotIfs& hot, const CompiledIfs& compiled) {
  if (compiled.barycentricSize == 0) return;
  if (compiled.barycentricPad % 8 != 0 || compiled.barycentricPad > std::uint32_t(kMaxBarycentricPad) ||
      compiled.barycentricSize > compiled.barycentricPad)
    throw ModelError("space", "the compiled free-form space does not fit the renderer");
  for (const CompiledFunction& f : compiled.functions)
    if (f.matrix.size() != std::size_t(compiled.barycentricSize) * compiled.barycentricStride())
      throw ModelError("functions", "a compiled matrix does not match the control points");
  hot.barycentricSize = compiled.barycentricSize;
  hot.barycentricBlocks = compiled.barycentricPad / 8;
}

/// The kernels' view of a compiled IFS: `hot` receives the functions' loop forms, then the final
/// function's, and the returned HotIfs points into `hot` and `compiled` (both must outlive it).
/// Throws ModelError when the compiled transition rows or free-form space do not fit.
inline HotIfs makeHotIfs(const CompiledIfs& compiled, std::vector<HotFunction>& hot, int skip, float escapeBound) {
  hot.clear();
  for (const CompiledFunction& f : compiled.functions) hot.push_back(makeHot(f));
  if (compiled.finalFunction) hot.push_back(makeHot(*compiled.finalFunction));
  HotIfs ifs;
  ifs.functions = hot.data();
  ifs.alias = compiled.alias.data();
  if (!compiled.transitionWalk.empty()) {
    if (compiled.transitionWalk.size() !=
        (compiled.stateRowsOffset ? 2 : 1) * (compiled.functions.size() + 1) * compiled.functions.size())
      throw ModelError("transitions", "the compiled transition rows do not match the functions");
    ifs.transitionWalk = compiled.transitionWalk.data();
  }
  ifs.count = std::uint32_t(compiled.functions.size());
  ifs.finalFunction = compiled.finalFunction ? &hot.back() : nullptr;
  ifs.skip = skip;
  // flam3 keeps points up to 1e10 before it calls them bad: spherical and its kin bring far points
  // back, so an IFS with variations keeps them too.
  ifs.escapeBound = compiled.hasVariations ? std::max(escapeBound, 1e10f) : escapeBound;
  ifs.variations = compiled.hasVariations;
  ifs.batched = compiled.batchedVariations.get();
  ifs.restartInterval = compiled.restartInterval;
  ifs.stateRowsOffset = compiled.stateRowsOffset;
  for (const CompiledFunction& f : compiled.functions) ifs.condensation |= !f.points.empty();
  ifs.boundedMaps = !compiled.functions.empty() && !compiled.hasVariations && !ifs.condensation;
  for (const CompiledFunction& f : compiled.functions)
    ifs.boundedMaps = ifs.boundedMaps && !f.pairs.empty() && f.nodeMagnitude <= 0.5f * escapeBound;
  attachBarycentric(ifs, compiled);
  return ifs;
}

/// The barycentric coordinates of one worker's kLanes chains (padded entries stay 0).
struct BarycentricState {
  alignas(32) float lambda[kLanes][kMaxBarycentricPad] = {};

  /// Restarts `lane` of `st` (position, colour, skip) at a random point of the simplex.
  void restartLane(ChainState& st, int lane, int skip, std::uint32_t m) {
    st.restartLane(lane, skip);
    float sum = 0.0f;
    for (std::uint32_t j = 0; j < m; ++j) {
      const float u = float(std::uint32_t(st.rng.next() >> 40) + 1u) * (1.0f / 16777216.0f);
      lambda[lane][j] = u;
      sum += u;
    }
    for (std::uint32_t j = 0; j < m; ++j) lambda[lane][j] /= sum;
    for (int j = int(m); j < kMaxBarycentricPad; ++j) lambda[lane][j] = 0.0f;
  }
  void start(ChainState& st, const HotIfs& ifs) {
    for (int l = 0; l < kLanes; ++l) restartLane(st, l, ifs.skip, ifs.barycentricSize);
  }
  /// Brings Σλ back to 1: float rounding lets the sum drift slowly over millions of steps.
  void renormalise(std::uint32_t m) {
    for (auto& lane : lambda) {
      float sum = 0.0f;
      for (std::uint32_t j = 0; j < m; ++j) sum += lane[j];
      if (sum > 1e-3f && sum < 1e3f)
        for (std::uint32_t j = 0; j < m; ++j) lane[j] /= sum;
    }
  }
};

template <int kBlocks, bool kRestricted, class Plot>
[[gnu::always_inline]] inline int stepBarycentricLane(ChainState& st, BarycentricState& bs, int lane, const HotIfs& ifs,
                                                      Plot& plot, std::int64_t& bad) {
  constexpr int kPad = 8 * kBlocks, kStride = kPad + 8;
  if constexpr (kRestricted)
    if (ifs.restartInterval && ++st.age[lane] > ifs.restartInterval)
      bs.restartLane(st, lane, ifs.skip, ifs.barycentricSize);
  std::uint32_t nextRow = kRestricted ? st.row[lane] : 0;
  const HotFunction& f = ifs.functions[ifs.pick<kRestricted>(nextRow, st.rng.next())];
  float* lambda = bs.lambda[lane];
  v8f next[kBlocks] = {};
  v4f q = {};
  const float* row = f.matrix;
  for (std::uint32_t i = 0; i < ifs.barycentricSize; ++i, row += kStride) {
    const float li = lambda[i];
    // Scalar-to-vector arithmetic broadcasts in registers; an initialiser list would go through
    // four narrow stack stores and one wide load (a store-forwarding stall on every row).
#if defined(__SSE2__)
    const v4f l4 = v4f(_mm_set1_ps(li));
#else
    const v4f l4 = {li, li, li, li};
#endif
    const v8f l8 = __builtin_shufflevector(l4, l4, 0, 1, 2, 3, 0, 1, 2, 3);
    for (int b = 0; b < kBlocks; ++b) {
      v8f r;
      std::memcpy(&r, row + 8 * b, 32);
      next[b] += l8 * r;
    }
    q += l4 * load4(row + kPad);
  }
  const v4f col = st.color[lane] + (f.color - st.color[lane]) * f.speed;  // Draves & Reckase 2003, §5
  if (!inBounds(q, ifs.escapeBound)) [[unlikely]] {
    ++bad;
    bs.restartLane(st, lane, ifs.skip, ifs.barycentricSize);
    return 0;
  }
  if (!kRestricted || !(nextRow & kTransitionPeek)) std::memcpy(lambda, next, sizeof next);  // a peek stays
  return advanceAndPlot<kRestricted>(st, lane, ifs, plot, bad, q, col, nextRow);
}

template <int kBlocks, bool kRestricted, class Plot>
[[gnu::always_inline]] inline std::int64_t runBarycentricLanes(ChainState& st, BarycentricState& bs, const HotIfs& ifs,
                                                               std::int64_t count, Plot& plot, std::int64_t& bad) {
  std::int64_t plotted = 0;
  for (std::int64_t n = 0; n < count / kLanes; ++n)
    for (int l = 0; l < kLanes; ++l) plotted += stepBarycentricLane<kBlocks, kRestricted>(st, bs, l, ifs, plot, bad);
  for (int l = 0; l < int(count % kLanes); ++l)
    plotted += stepBarycentricLane<kBlocks, kRestricted>(st, bs, l, ifs, plot, bad);
  return plotted;
}

template <int kBlocks, class Plot>
[[gnu::always_inline]] inline std::int64_t runBarycentricBlocks(ChainState& st, BarycentricState& bs, const HotIfs& ifs,
                                                                std::int64_t count, Plot& plot, std::int64_t& bad) {
  return ifs.transitionWalk ? runBarycentricLanes<kBlocks, true>(st, bs, ifs, count, plot, bad)
                            : runBarycentricLanes<kBlocks, false>(st, bs, ifs, count, plot, bad);
}

/// runChain for a free-form IFS (ifs.barycentricBlocks > 0); `bs` belongs to `st` (started with
/// BarycentricState::start after ChainState::start).
template <class Plot>
[[gnu::always_inline]] inline void runBarycentricChain(ChainState& st, BarycentricState& bs, const HotIfs& ifs,
                                                       std::int64_t count, Plot& plot, ChainCounters& counters) {
  std::int64_t bad = 0, plotted = 0;
  ChainState local = st;
  bs.renormalise(ifs.barycentricSize);
  switch (ifs.barycentricBlocks) {
    case 1:
      plotted = runBarycentricBlocks<1>(local, bs, ifs, count, plot, bad);
      break;
    case 2:
      plotted = runBarycentricBlocks<2>(local, bs, ifs, count, plot, bad);
      break;
    case 3:
    case 4:
      plotted = runBarycentricBlocks<4>(local, bs, ifs, count, plot, bad);
      break;
    default:
      plotted = runBarycentricBlocks<8>(local, bs, ifs, count, plot, bad);
      break;
  }
  finishRun(st, local, plot, count, bad, plotted, counters);
}

}  // namespace gridifs::kernel
