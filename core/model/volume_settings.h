#pragma once
// "volume": how the measure attractor is computed as a density volume (Sokolov & Gentil, §3.4).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "field/fractal_field.h"
#include "model/condensation_set.h"

namespace gridifs {

/// "volume.field": a fractal field that modulates the density, as Colonna's cloud fields give
/// clouds their density ("Animation of fractal objects", §3.2). The visits P of the voxel at p are
/// weighted by max(0, 1 + strength · F_seed(p + wind·t, t)) before the division by max P, so holes
/// open where the field is low and the pattern drifts with the wind; a period in t loops it. The
/// field's parameters are the field operation's, without its amplitude: `strength` plays its part.
///
/// A field is one layer of a scene (Colonna's fig. 6: a fractal mountain under layers of cloud);
/// its `role` says what it adds. G below is the layer's field value: F_seed, or with a `shape`
/// Colonna's interpolation between the field and a geometric shape (§1.2, fig. 3),
/// G = (1 − blend)·F + blend·S with S = clamp(−d/softness, −1, 1), d the shape's signed distance
/// (schema/field_layer.h).
enum class FieldRole {
  Density,  // weights the visits: max(0, 1 + strength·G(p)) (the single field's meaning)
  Cloud,    // a cloud of its own: c = clamp(strength·G(x, y, height), 0, 1) fills the voxels within
            // c·thickness/2 of the plane z = height with density c
  Terrain,  // a mountain: the voxels below z = height + strength·G(x, y, height) are solid
};

const char* toString(FieldRole role);
/// Parses "density", "cloud" or "terrain"; returns false for anything else.
bool parseFieldRole(const std::string& text, FieldRole& out);

struct VolumeDensityField {
  double strength = 1.0;
  FractalFieldParams field;
  FieldRole role = FieldRole::Density;
  double height = 0.0;                   // cloud, terrain: the layer's plane z = height
  double thickness = 0.2;                // cloud: the full thickness where the cloud is densest
  std::optional<CondensationSet> shape;  // a sphere, box or torus the field is blended with
  double blend = 0.5;                    // 0: the field alone, 1: the shape alone
  double softness = 0.25;                // distance over which S goes from 1 (inside) to -1
  bool operator==(const VolumeDensityField&) const = default;
};

inline constexpr double kMaxDensityFieldStrength = 100.0;

struct VolumeSettings {
  int resolution = 128;  // N: the volume is N³ voxels covering X
  int iterations = 300;  // set iterations (projects with median functions)
  int skip = 20;         // set iterations before P accumulates
  std::uint64_t seed = 1;
  std::int64_t samples = 20'000'000;        // chaos-game points (projects without median functions)
  std::optional<VolumeDensityField> field;  // none: the measure attractor's density as it is
  /// "start": the set S the deterministic algorithm over sets starts from (Sokolov & Gentil, §3.3:
  /// "an arbitrary non-empty compact subset"); none: the whole of X.
  std::optional<CondensationSet> start;
  /// The second and later layers when "field" is a list (the first is `field`, which keyframe
  /// tracks reach as volume.field.*); applied in order after it.
  std::vector<VolumeDensityField> more_fields;
  bool operator==(const VolumeSettings&) const = default;
};

inline constexpr int kMinVolumeResolution = 16;
inline constexpr int kMaxVolumeResolution = 512;

}  // namespace gridifs
