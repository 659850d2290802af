#pragma once
// The flame variations four chains at a time. The chaos game runs four independent chains in turn
// (render/chaos_kernel.h); each picks its own function, and the functions of a flame mostly share
// a few variations. Evaluating one variation for all four chains in float SIMD lanes
// (variations/lane_math.h) costs about what one chain's double evaluation does, so the variation stage
// of a whole round costs a term per variation of the IFS instead of a term per variation of each
// chain's function. Draves & Reckase's formulas as flame_variation_bodies.inc writes them, in
// float: every lane stays within a few float ulps of the kernel's double body.
#include <cstdint>
#include <vector>

#include "variations/flame_variations.h"
#include "variations/lane_math.h"

namespace gridifs {

/// One term for four chains: lane l holds chain l's point, its function's weight for the term
/// (0 where the function lacks it) and parameters (another function's where it lacks the term).
/// Only the lanes in `active` draw random numbers, in lane order, from the one stream.
struct VariationLanes {
  lane_math::v4f x, y, z;
  lane_math::v4f weight;
  int active = 0;  // bit l: chain l's function has the term
  const double* params[4] = {};
  std::uint64_t* random = nullptr;

  /// √(x² + y²) and flam3's angle atan2(x, y), worked out once per point: the terms of a round
  /// share them (heart and julia, polar and handkerchief, …).
  [[gnu::always_inline]] lane_math::v4f radius() {
    if (!hasRadius_) {
      radius_ = lane_math::sqrt(x * x + y * y);
      hasRadius_ = true;
    }
    return radius_;
  }
  [[gnu::always_inline]] lane_math::v4f angle() {
    if (!hasAngle_) {
      angle_ = lane_math::atan2(x, y);
      hasAngle_ = true;
    }
    return angle_;
  }

 private:
  lane_math::v4f radius_{}, angle_{};
  bool hasRadius_ = false, hasAngle_ = false;
};

/// w·V(p) per lane (x, y and z; z only for the variations that write it, VariationLanes'
/// caller carries w·z for the others). Inactive lanes hold anything, NaN included.
using LaneBodyFn = void (*)(VariationLanes& in, lane_math::v4f& x, lane_math::v4f& y, lane_math::v4f& z);

/// The four-lane form of variation `name` (a FlameVariation::name), or null when it has none; those
/// run lane by lane through their kernel body.
LaneBodyFn laneVariationBody(const char* name);
/// Its number for BatchedVariations::Slot::lanes, or -1.
int laneVariationBodyIndex(const char* name);

/// The variation stages of an IFS's functions, for four chains at once: each variation of the whole
/// IFS is evaluated once per round, in float SIMD lanes, weighted by each chain's function (0
/// where it lacks the variation). Built by render/batched_variations.h's batchVariations();
/// immutable after, thread-safe to read.
struct BatchedVariations {
  using v4f = lane_math::v4f;
  /// One variation of the IFS (a function with the same variation twice has two slots).
  struct Slot {
    int lanes = -1;                 // its four-lane form (laneVariationBodyIndex), or -1: lane by lane through `scalar`
    KernelBodyFn scalar = nullptr;  // its kernel body
    bool writesZ = false;           // otherwise the term carries w·z
    bool params = false;            // the variation has parameters
  };
  std::vector<Slot> slots;
  /// Per function f and slot s, at [f · slots.size() + s]: the term's weight (0 when f lacks it)
  /// and parameters (when f lacks it, those of the first function that has it, so that every lane
  /// evaluates something well defined).
  std::vector<float> weights;
  std::vector<const double*> params;
  /// Per function: bit s set when it has slot s; its affine fit (the dependent variations read
  /// it); its post map as columns x, y, z, 1 (4 floats each, lane 3 zero) when it has one; whether
  /// a flatten term clears z.
  std::vector<std::uint32_t> slotMask;
  std::vector<const FlameAffine*> coefs;
  std::vector<float> postColumns;
  std::vector<std::uint8_t> hasPost, flatten;
  bool anyPost = false, anyFlatten = false;
  /// Per function: it has no variation stage (a grid function among flame ones, as a flame's
  /// symmetry xforms import): its lane keeps the grid image the kernel gave it.
  std::vector<std::uint8_t> keepsGridImage;
  bool anyKeepsGridImage = false;

  /// The variation stage of four chains: q[l] is chain l's grid image g(p) under function fn[l]
  /// and becomes post(Σ w_i V_i(q)) (lane 3 zero), or stays when fn[l] has no stage. Random variations draw from
  /// `random`, slot by slot, the chains in order.
  void apply(const std::uint32_t (&fn)[4], v4f (&q)[4], std::uint64_t& random) const;
};

}  // namespace gridifs
