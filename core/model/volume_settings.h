#pragma once
// "volume": how the measure attractor is computed as a density volume (Sokolov & Gentil, §3.4).
#include <cstdint>

namespace gridifs {

struct VolumeSettings {
  int resolution = 128;  // N: the volume is N³ voxels covering X
  int iterations = 300;  // set iterations (projects with median functions)
  int skip = 20;         // set iterations before P accumulates
  std::uint64_t seed = 1;
  std::int64_t samples = 20'000'000;  // chaos-game points (projects without median functions)
  bool operator==(const VolumeSettings&) const = default;
};

inline constexpr int kMinVolumeResolution = 16;
inline constexpr int kMaxVolumeResolution = 512;

}  // namespace gridifs
