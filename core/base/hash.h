#pragma once
// Integer hashing for reproducible random streams: SplitMix64 (Steele, Lea & Flood 2014), the
// seeding function recommended for the xoshiro and wyrand generators. The chaos game seeds its
// per-worker generators with it and the calculator's rand() hashes node indices with it.
//
// Thread-safety: pure functions.
#include <cstdint>

namespace gridifs {

/// One SplitMix64 step: a bijective mix of 64 bits (equal inputs, equal outputs on every machine).
constexpr std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

}  // namespace gridifs
