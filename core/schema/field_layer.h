#pragma once
// The value G of a field layer of the volume ("volume.field", model/volume_settings.h): Colonna's
// fractal field F_seed ("Animation of fractal objects", §2), or the interpolation between the
// field and a geometric shape that his figure 3 shows (§1.2: fields "transformed and combined
// with other fields"): G = (1 − blend)·F + blend·S, S = clamp(−d/softness, −1, 1) with d the
// shape's signed distance, so S is 1 deep inside the shape, −1 far outside it and passes through
// 0 on its boundary. The field is sampled at (p + ∫₀ᵗ wind, t), as the field operation samples it.
//
// Thread-safety: pure functions of their arguments.
#include <string>
#include <vector>

#include "model/volume_settings.h"

namespace gridifs {

/// The signed distance from p to a sphere, box or torus (negative inside; exact for the sphere
/// and the torus, the usual box distance). 0 for mesh and VDB sets.
double primitiveSignedDistance(const CondensationSet& set, const Vec3& p);

/// S(p) of the layer's shape; 0 when it has none.
double fieldShapeValue(const VolumeDensityField& layer, const Vec3& p);

/// G at p and time t (double precision, point by point).
double fieldLayerValue(const VolumeDensityField& layer, const Vec3& p, double t);

/// G at every point (the fast whole-step field evaluation of field/field_step.h: the same values
/// up to single-precision rounding). Uses up to `threads` workers (≤ 0: all).
std::vector<double> fieldLayerValues(const VolumeDensityField& layer, const std::vector<Vec3>& points, double t,
                                     int threads = 0);

/// G over the size×size pixel centres of the square [-1, 1]² at height z, row-major with row 0
/// at y = −1 (pixel (i, j) at x = −1 + (2i + 1)/size, y = −1 + (2j + 1)/size).
std::vector<double> fieldLayerPlane(const VolumeDensityField& layer, int size, double z, double t, int threads = 0);

/// Where a layer samples its plane: cloud and terrain layers at their height, density layers at 0.
double fieldLayerPlaneHeight(const VolumeDensityField& layer);

/// Every layer of the settings in order: `field`, then `more_fields`.
std::vector<const VolumeDensityField*> fieldLayers(const VolumeSettings& settings);

/// Checks a layer's numbers (strength in [0, 100], the field's parameters, finite height,
/// thickness, blend in [0, 1], positive softness, a primitive shape). Throws ModelError with a
/// path below `path`.
void checkFieldLayer(const VolumeDensityField& layer, const std::string& path);

inline constexpr double kMaxFieldLayerExtent = 1e3;  // |height|, thickness, softness
inline constexpr std::size_t kMaxFieldLayers = 16;   // layers in "volume.field"

}  // namespace gridifs
