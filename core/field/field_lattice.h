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

// Loops over many vertices or nodes are also compiled for AVX2 and AVX-512, and the loader
// picks what the processor runs. No multiply and add is fused behind the code's back
// (fp-contract=off), so every processor rounds alike; where a kernel fuses one it says so with
// std::fma, which rounds once on every processor (in hardware or in the C library).
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

// The random value RDN of a vertex is half of a 32-bit integer hash of the sum of one share per
// dimension and a (seed pair, level) key: the shares are computed once per index along each
// dimension, the sum once per vertex for the three axes, and the hash of 32-bit lanes is the
// cheap part of a vector loop (sixteen lanes per AVX-512 instruction). One hash serves two
// seeds, 2m (its upper 16 bits) and 2m + 1 (its lower 16 bits), so the three axes' seeds S, S+1,
// S+2 take two hashes per vertex instead of three; 16 bits are ample for a noise field's values.
//
// Odd 32-bit multipliers of each dimension's share.
constexpr std::array<std::uint32_t, kDims> kIndexMix{0x9E3779B9u, 0x85EBCA77u, 0xC2B2AE3Du, 0x27D4EB2Fu};

inline std::int64_t wrapIndex(std::int64_t i, std::int64_t cells) {
  if (cells <= 0) return i;
  i %= cells;
  return i < 0 ? i + cells : i;
}

/// A vertex index's share of the hash input along dimension d (wrapped where periodic). It is
/// not linear in the index: with shares index·m_d the sum of four shares modulo 2^32 would take
/// equal values along a lattice of vertices a few hundred cells apart, and the meshes would
/// repeat; the xor-shift of the product breaks that lattice. Indices 2^32 cells apart share.
inline std::uint32_t indexContribution(std::int64_t index, std::int64_t cells, int d) {
  std::uint32_t x = static_cast<std::uint32_t>(wrapIndex(index, cells)) * kIndexMix[d];
  x ^= x >> 15;
  return x * 0x2C1B3C6Du;
}

/// The 32-bit hash key of a 64-bit (seed pair, level) mix.
inline std::uint32_t foldKey(std::uint64_t key) { return static_cast<std::uint32_t>(key ^ (key >> 32)); }

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

/// The 32-bit integer hash of RDN: the first round of Wellons' "lowbias32" (hash-prospector), a
/// bijective xor-shift-multiply-xor-shift mix; exact integer arithmetic, equal on every machine.
/// One round suffices because its input is already mixed: each dimension's share is a product
/// passed through an xor-shift and a second product (indexContribution), so neighbouring
/// vertices differ by unrelated 32-bit steps (the statistics are tested: uniform values,
/// uncorrelated neighbours, axes, seed pairs and far vertices, also in their magnitudes).
inline std::uint32_t mix32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7FEB352Du;
  x ^= x >> 15;
  return x;
}

/// Which RDN a hash gives: the key of the seed pair (seed >> 1) and level, and the shift that
/// moves the seed's half of the hash into the upper 16 bits (0 for even seeds, 16 for odd).
struct RandomKey {
  std::uint32_t key = 0;
  std::uint32_t shift = 0;
};

/// The scale of RDN's integer: RDN = int32(half << 16) · 2^-31 = int16(half) · 2^-15, in [-1, 1)
/// and exact in double.
constexpr double kRandomScale = 0x1.0p-31;

/// A hash's half for one seed, as the upper 16 bits of a 32-bit integer (lower bits zero).
inline std::int32_t randomHalf(std::uint32_t hash, std::uint32_t shift) {
  return static_cast<std::int32_t>((hash << shift) & 0xFFFF0000u);
}

/// RDN from a vertex's summed index shares and its key, in [-1, 1).
inline double randomFromSum(std::uint32_t indexSum, RandomKey key) {
  return static_cast<double>(randomHalf(mix32(indexSum + key.key), key.shift)) * kRandomScale;
}

/// out[i] = randomFromSum(sums[i], key) for i < count: the same values, many at a time (the
/// integer hash and the conversion of a 32-bit integer to double are exact, so every
/// instruction set gives equal results).
void randomsFromSums(const std::uint32_t* sums, std::size_t count, RandomKey key, double* out);

}  // namespace gridifs::field_lattice
