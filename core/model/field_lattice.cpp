#include "model/field_lattice.h"

namespace gridifs::field_lattice {

// SplitMix64 needs 64-bit multiplies, one vector instruction in AVX-512DQ. The integer hash and
// the conversion of a 53-bit integer to double are exact: equal values everywhere.
GRIDIFS_FIELD_VECTOR_CLONES
void randomsFromSums(const std::uint64_t* sums, std::size_t count, std::uint64_t key, double* out) {
  for (std::size_t i = 0; i < count; ++i) {
    const auto bits = static_cast<std::int64_t>(splitmix64(sums[i] + key) >> 11);
    out[i] = static_cast<double>(bits) * 0x1.0p-52 - 1.0;
  }
}

}  // namespace gridifs::field_lattice
