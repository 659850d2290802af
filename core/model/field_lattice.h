#pragma once
// The lattice arithmetic of Colonna's fractal field meshes ("Animation of fractal objects", §2 and
// the second appendix), shared by the point-by-point evaluation (FractalField::value and
// displacement) and the per-time-step evaluation of many nodes (fieldStepDisplace), so that both
// hash the same vertices to the same random values and interpolate them the same way.
//
// Thread-safety: pure functions.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "base/hash.h"

// Loops over many vertices or nodes are also compiled for AVX2 and AVX-512, and the loader
// picks what the processor runs. Without fused multiply-adds, so every processor rounds alike.
// Sanitized builds (GRIDIFS_NO_KERNEL_CLONES) compile one version: the clones' IFUNC resolver runs
// during relocation, before a sanitizer runtime is up.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(GRIDIFS_NO_KERNEL_CLONES)
#define GRIDIFS_FIELD_VECTOR_CLONES \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"), optimize("fp-contract=off")))
#else
#define GRIDIFS_FIELD_VECTOR_CLONES
#endif

namespace gridifs::field_lattice {

constexpr int kDims = 4;

// Odd 64-bit multipliers that spread a vertex's four indices over the hash input.
constexpr std::array<std::uint64_t, kDims> kIndexMix{0x9E3779B97F4A7C15ull, 0xC2B2AE3D27D4EB4Full,
                                                     0x165667B19E3779F9ull, 0xD6E8FEB86659FD93ull};

inline std::int64_t wrapIndex(std::int64_t i, std::int64_t cells) {
  if (cells <= 0) return i;
  i %= cells;
  return i < 0 ? i + cells : i;
}

/// A vertex index's share of the hash input along dimension d (wrapped where periodic).
inline std::uint64_t indexContribution(std::int64_t index, std::int64_t cells, int d) {
  return static_cast<std::uint64_t>(wrapIndex(index, cells)) * kIndexMix[d];
}

/// The cell of one mesh dimension that holds coordinate s: its lower vertex and the position in it.
struct AxisCell {
  std::int64_t base = 0;
  double u = 0.0;
};

inline AxisCell axisCell(double s, double offset, double cell) {
  double x = (s + offset) / cell;
  // A coordinate that is not finite, or beyond 2^62 cells, has no meaningful cell; cell 0 keeps
  // the integer index arithmetic defined (the node itself stays infinite or undefined).
  if (!(std::abs(x) < 0x1p62)) x = 0.0;
  const double lower = std::floor(x);
  return {static_cast<std::int64_t>(lower), x - lower};
}

// Colonna, second appendix: the cubic through f0, f1 with end slopes d0, d1 (per cell).
inline double hermite(double f0, double f1, double d0, double d1, double u) {
  const double a3 = (d0 + d1) - 2.0 * (f1 - f0);
  const double a2 = 3.0 * (f1 - f0) - (2.0 * d0 + d1);
  return ((a3 * u + a2) * u + d0) * u + f0;
}

/// RDN from a vertex's summed index contributions and a (seed, axis, level) key, in [-1, 1).
inline double randomFromSum(std::uint64_t indexSum, std::uint64_t key) {
  return static_cast<double>(splitmix64(indexSum + key) >> 11) * 0x1.0p-52 - 1.0;
}

/// out[i] = randomFromSum(sums[i], key) for i < count: the same values, many at a time (the
/// integer hash is exact, so every instruction set gives equal results).
void randomsFromSums(const std::uint64_t* sums, std::size_t count, std::uint64_t key, double* out);

}  // namespace gridifs::field_lattice
