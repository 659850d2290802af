#pragma once
// A function's distorted lattice and its trilinear evaluation (Gröller & Wegenkittl 1994, §1.3).
#include <vector>

#include "base/types.h"

namespace gridifs {

/// Ni × Nj × Nk nodes in double precision; node (i, j, k) is stored at
/// i + Ni*(j + Nj*k). Undistorted node positions tile the bi-unit cube X = [-1, 1]^3.
class Grid {
 public:
  Grid() = default;
  /// An undistorted grid. Throws ModelError when a dimension is outside [2, 128].
  explicit Grid(const Index3& resolution);

  const Index3& resolution() const { return resolution_; }
  std::size_t nodeCount() const { return nodes_.size(); }
  std::size_t index(int i, int j, int k) const {
    return std::size_t(i) + std::size_t(resolution_[0]) * (std::size_t(j) + std::size_t(resolution_[1]) * k);
  }
  const Vec3& node(int i, int j, int k) const { return nodes_[index(i, j, k)]; }
  Vec3& node(int i, int j, int k) { return nodes_[index(i, j, k)]; }
  const std::vector<Vec3>& nodes() const { return nodes_; }
  std::vector<Vec3>& nodes() { return nodes_; }

  /// Undistorted position u = (-1 + 2i/(Ni-1), ...).
  Vec3 undistorted(int i, int j, int k) const;

  /// f(p): clamp p to X, find its cell in the undistorted lattice and trilinearly
  /// interpolate the cell's 8 distorted nodes. Thread-safe (const).
  Vec3 evaluate(Vec3 p) const;

  bool operator==(const Grid&) const = default;

 private:
  Index3 resolution_{2, 2, 2};
  std::vector<Vec3> nodes_;
};

/// Whether every node is finite.
bool allFinite(const Grid& grid);

}  // namespace gridifs
