#include "field/field_lattice.h"

namespace gridifs::field_lattice {

// Thirty-two-bit lanes: sixteen hashes per AVX-512 instruction, eight per AVX2 one.
GRIDIFS_FIELD_VECTOR_CLONES
void randomsFromSums(const std::uint32_t* sums, std::size_t count, RandomKey key, double* out) {
  for (std::size_t i = 0; i < count; ++i) out[i] = randomFromSum(sums[i], key);
}

}  // namespace gridifs::field_lattice
