#pragma once
// The shaded display's settings, stored in the project under "render.shading": directional lights,
// a Blinn-Phong specular term, screen-space ambient occlusion, distance fog and depth of field.
// Lights, ambient, specular, occlusion and fog are applied when the z-buffer is developed (no
// re-render); shadows and depth of field are chaos-game effects (core/render/shaded_plot.h).
//
// Thread-safety: plain values; the functions are pure.
#include <optional>
#include <string>
#include <vector>

#include "base/types.h"

namespace gridifs {

namespace limits {
inline constexpr int kMaxLights = 3;
inline constexpr int kMaxAoDirections = 32;
inline constexpr double kMaxAoRadius = 256.0;  // pixels
}  // namespace limits

/// A directional light. `direction` points from the scene towards the light, in world
/// coordinates (+z up); it need not be normalised but must not be zero.
struct ShadingLight {
  Vec3 direction{0.3, -0.5, 1.0};
  Vec3 color{1.0};
  double intensity = 1.0;
  bool shadows = true;
  bool operator==(const ShadingLight&) const = default;
};

/// Horizon-based screen-space ambient occlusion (Bavoil, Sainz & Dimitrov 2008): `directions`
/// screen directions, marched up to `radius` pixels; `strength` 0 turns it off.
struct AmbientOcclusionSettings {
  double radius = 12.0;
  double strength = 0.8;
  int directions = 8;
  bool operator==(const AmbientOcclusionSettings&) const = default;
};

/// Exponential fog by view depth: colour = mix(fog colour, colour, exp(-density · depth)).
struct FogSettings {
  Vec3 color{0.0};
  double density = 0.0;
  bool operator==(const FogSettings&) const = default;
};

/// Depth of field as a chaos-game effect: each projected point moves on a disc of radius
/// aperture · |depth − focus| (world units) in the image plane. `focus` is the view depth in
/// focus; an aperture > 0 needs it.
struct DepthOfFieldSettings {
  double aperture = 0.0;
  std::optional<double> focus;
  bool operator==(const DepthOfFieldSettings&) const = default;
};

struct ShadingSettings {
  std::vector<ShadingLight> lights{ShadingLight{}};
  double ambient = 0.15;
  double specular = 0.3;
  double shininess = 32.0;
  AmbientOcclusionSettings ao;
  FogSettings fog;
  DepthOfFieldSettings dof;
  bool operator==(const ShadingSettings&) const = default;

  /// Whether any light casts shadows (the chaos game then fills a z-buffer per such light).
  bool anyShadows() const;
};

}  // namespace gridifs
