#pragma once
// The functions of an IFS on H(X) as maps of voxel sets (Sokolov & Gentil, §3): the condensation
// function f_C = M(·, C) of §3.2 (optionally rotated, §4.1), Barnsley's constant condensation
// f(B) = C (§3.1), and a point map of X (a grid function) applied to every voxel.
#include <memory>
#include <vector>

#include "render/compiled_ifs.h"
#include "volume/voxel_set.h"

namespace gridifs {

/// Reusable buffers of one set iteration (not thread-safe; one per iteration).
struct SetScratch {
  std::vector<std::uint64_t> marks;  // one bit per lattice voxel, all clear between calls
  std::vector<std::uint32_t> candidates;
};

class SetFunction {
 public:
  /// f_C = M(·, C): the union of the left median D_B(C) and the right median D_C(B) (§3.2);
  /// `rotateDegreesPerUnit` ≠ 0 rotates the median about `axis` (z by default; need not be unit
  /// length, must not be zero), around the point midway between the centroids of B and C, by that
  /// many degrees per unit of distance between them (§4.1).
  static SetFunction median(VoxelSet condensation, double rotateDegreesPerUnit, Vec3 axis = Vec3{0.0, 0.0, 1.0});
  /// f(B) = C for every B.
  static SetFunction constant(VoxelSet condensation);
  /// f(B) = {g(x) : x ∈ B} for a point map g of X: each voxel is supersampled 2×2×2 so that a
  /// map that stretches somewhere leaves no holes; images outside X are dropped.
  static SetFunction pointMap(CompiledFunction map, VoxelLattice lattice);

  SetFunction(SetFunction&&) noexcept;
  SetFunction& operator=(SetFunction&&) noexcept;
  ~SetFunction();

  /// out = f(in) (in must be non-empty, on the same lattice). Runs on up to `threads` threads.
  /// Not thread-safe with respect to other calls of the same function (a median memoises its
  /// nearest-voxel answers).
  void apply(const VoxelSet& in, VoxelSet& out, SetScratch& scratch, int threads) const;

  /// The condensation set (empty for a point map).
  const VoxelSet& condensation() const;
  /// Whether f is Barnsley's constant map (f(B) = C for every B).
  bool isConstant() const;

 private:
  struct Impl;
  explicit SetFunction(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace gridifs
