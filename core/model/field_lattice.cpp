#include "model/field_lattice.h"

namespace gridifs::field_lattice {

// SplitMix64 needs 64-bit multiplies; AVX-512DQ (x86-64-v4) has them as one vector instruction, so the
// batch is compiled for it too and the loader picks the best the processor runs. The integer
// hash and the conversion of a 53-bit integer to double are exact: equal values everywhere.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#endif
void randomsFromSums(const std::uint64_t* sums, std::size_t count, std::uint64_t key, double* out) {
  for (std::size_t i = 0; i < count; ++i) {
    const auto bits = static_cast<std::int64_t>(splitmix64(sums[i] + key) >> 11);
    out[i] = static_cast<double>(bits) * 0x1.0p-52 - 1.0;
  }
}

}  // namespace gridifs::field_lattice
