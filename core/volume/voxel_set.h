#pragma once
// A set of voxels of the N³ lattice covering X = [-1, 1]³: the digital images that Sokolov &
// Gentil's random iteration (§3.4) carries from step to step instead of a point.
#include <cstdint>
#include <vector>

#include "base/types.h"

namespace gridifs {

/// Voxel (i, j, k) of an N³ lattice has centre (−1 + (2i+1)/N, …) and linear index i + N·(j + N·k).
struct VoxelLattice {
  int n = 64;

  std::uint32_t index(int i, int j, int k) const {
    return std::uint32_t(i) + std::uint32_t(n) * (std::uint32_t(j) + std::uint32_t(n) * std::uint32_t(k));
  }
  Index3 coordinates(std::uint32_t index) const {
    const std::uint32_t un = std::uint32_t(n);
    return {int(index % un), int((index / un) % un), int(index / (un * un))};
  }
  double voxelSize() const { return 2.0 / n; }
  Vec3 centre(int i, int j, int k) const {
    return {-1.0 + (2.0 * i + 1.0) / n, -1.0 + (2.0 * j + 1.0) / n, -1.0 + (2.0 * k + 1.0) / n};
  }
  Vec3 centre(std::uint32_t index) const {
    const Index3 c = coordinates(index);
    return centre(c[0], c[1], c[2]);
  }
  /// Continuous lattice coordinate of a point of X: voxel centres are at integers.
  double toLattice(double x) const { return (x + 1.0) * 0.5 * n - 0.5; }
  std::size_t voxelCount() const { return std::size_t(n) * std::size_t(n) * std::size_t(n); }
  bool operator==(const VoxelLattice&) const = default;
};

/// A set of voxels as sorted, distinct linear indices.
struct VoxelSet {
  VoxelLattice lattice;
  std::vector<std::uint32_t> voxels;

  bool empty() const { return voxels.empty(); }
  std::size_t size() const { return voxels.size(); }
  bool operator==(const VoxelSet&) const = default;
};

/// Makes `voxels` sorted and distinct.
void normalizeVoxels(std::vector<std::uint32_t>& voxels);

/// The centroid of a non-empty set, in lattice coordinates.
Vec3 latticeCentroid(const VoxelSet& set);

}  // namespace gridifs
