#pragma once
// "volume": how the measure attractor is computed as a density volume (Sokolov & Gentil, §3.4).
#include <cstdint>
#include <optional>

#include "anim/fractal_field.h"
#include "model/condensation_set.h"

namespace gridifs {

/// "volume.field": a fractal field that modulates the density, as Colonna's cloud fields give
/// clouds their density ("Animation of fractal objects", §3.2). The visits P of the voxel at p are
/// weighted by max(0, 1 + strength · F_seed(p + wind·t, t)) before the division by max P, so holes
/// open where the field is low and the pattern drifts with the wind; a period in t loops it. The
/// field's parameters are the field operation's, without its amplitude: `strength` plays its part.
struct VolumeDensityField {
  double strength = 1.0;
  FractalFieldParams field;
  bool operator==(const VolumeDensityField&) const = default;
};

inline constexpr double kMaxDensityFieldStrength = 100.0;

struct VolumeSettings {
  int resolution = 128;  // N: the volume is N³ voxels covering X
  int iterations = 300;  // set iterations (projects with median functions)
  int skip = 20;         // set iterations before P accumulates
  std::uint64_t seed = 1;
  std::int64_t samples = 20'000'000;  // chaos-game points (projects without median functions)
  std::optional<VolumeDensityField> field;  // none: the measure attractor's density as it is
  /// "start": the set S the deterministic algorithm over sets starts from (Sokolov & Gentil, §3.3:
  /// "an arbitrary non-empty compact subset"); none: the whole of X.
  std::optional<CondensationSet> start;
  bool operator==(const VolumeSettings&) const = default;
};

inline constexpr int kMinVolumeResolution = 16;
inline constexpr int kMaxVolumeResolution = 512;

}  // namespace gridifs
