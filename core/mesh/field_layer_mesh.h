#pragma once
// The field layers of a volume as sheets (Colonna, "Animation of fractal objects", §1.2 and fig. 6:
// the field "visualized as a three-dimensional surface"): each layer a size×size grid over the
// square [-1, 1]² raised to z = h + strength·G(x, y, h, t), h its plane's height (0 for a density
// layer; schema/field_layer.h), joined by quads, terrain coloured dark to light by height, clouds white.
#include <vector>

#include "mesh/ifs_mesh.h"
#include "model/volume_settings.h"

namespace gridifs {

/// One mesh holding a sheet per layer. Expects size in [kMinHeightfieldSize, kMaxHeightfieldSize]
/// (mesh/field_heightfield.h).
IfsMesh fieldLayerSheets(const std::vector<const VolumeDensityField*>& layers, double t, int size);

}  // namespace gridifs
