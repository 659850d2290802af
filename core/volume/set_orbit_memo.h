#pragma once
// The orbit of the random iteration over sets (Sokolov & Gentil, §3.4) is a walk on a finite
// collection of digital images: the functions are contractions, so after a few steps the current
// set depends only on the last few choices and the iteration keeps revisiting the same sets.
// This memo interns every distinct set once and remembers f_i(X) for every (X, i) it has seen,
// so a revisited step costs a table look-up instead of a median image; the iteration it feeds is
// exactly the one computed without it.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <unordered_map>
#include <vector>

#include "volume/voxel_set.h"

namespace gridifs {

class SetOrbitMemo {
 public:
  static constexpr int kNone = -1;

  /// Keeps at most `byteBudget` bytes of voxel indices; past it, new sets are not interned.
  SetOrbitMemo(std::size_t functionCount, std::size_t byteBudget);

  /// The id of a set equal to `set`, interning a copy when it is new (kNone when the budget is spent).
  int intern(const VoxelSet& set);
  /// The interned set `id` (stable address while the memo lives).
  const VoxelSet& set(int id) const { return sets_[std::size_t(id)]; }
  /// The id of f_function(set id), or kNone when not yet known.
  int image(int id, std::size_t function) const { return images_[std::size_t(id) * functionCount_ + function]; }
  void rememberImage(int id, std::size_t function, int imageId);

  std::size_t setCount() const { return sets_.size(); }

 private:
  std::size_t functionCount_;
  std::size_t byteBudget_;
  std::size_t bytes_ = 0;
  std::deque<VoxelSet> sets_;
  std::vector<int> images_;  // functionCount_ per set
  std::unordered_multimap<std::uint64_t, int> byHash_;
};

/// A 64-bit hash of a set's voxels (equal sets, equal hashes).
std::uint64_t hashVoxelSet(const VoxelSet& set);

}  // namespace gridifs
