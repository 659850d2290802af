#pragma once
// Fractal field layers over a density volume (Colonna, "Animation of fractal objects", §3.2:
// clouds whose density is a fractal field, drifting with the wind; fig. 6: a fractal mountain
// under layers of cloud). A `density` layer weights the density at voxel centre p by
// max(0, 1 + strength · G(p, t)) and divides the volume by its new largest value, so it stays in
// [0, 1] with max 1; unvisited voxels stay empty (it shapes the measure attractor's cloud, it does
// not add density outside it). `cloud` and `terrain` layers add density of their own where the
// attractor has none (model/volume_settings.h says where), each voxel keeping the larger value.
// G is the layer's field value (schema/field_layer.h).
#include "model/volume_settings.h"
#include "volume/density_volume.h"

namespace gridifs {

/// The weight a density layer gives the voxel centre p at time t (≥ 0).
double densityFieldWeight(const VolumeDensityField& field, const Vec3& p, double t);

/// Weights every visited voxel of `volume` (normalised, max 1) by the field at time t and
/// normalises again. Uses up to `threads` workers (≤ 0: all); no value depends on the count.
void modulateDensity(DensityVolume& volume, const VolumeDensityField& field, double t, int threads);

/// The density a cloud or terrain layer gives the voxel centre p at time t, in [0, 1] (0 for a
/// density layer, which adds none).
double fieldLayerDensity(const VolumeDensityField& layer, const Vec3& p, double t);

/// Applies every layer of `settings` in order (`field`, then `more_fields`): density layers
/// modulate, cloud and terrain layers add their density (the colour volume, when there is one,
/// gets white clouds and grey rock there). Nothing happens without layers. Threads as above.
void applyFieldLayers(DensityVolume& volume, const VolumeSettings& settings, double t, int threads);

}  // namespace gridifs
