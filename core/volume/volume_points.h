#pragma once
// A density volume as points for the chaos-game renderer: what `render` and `export-points` draw
// of an IFS with median functions, whose maps act on sets, not points (Sokolov & Gentil, §3.2).
// The volume becomes one condensation function (Barnsley's constant map, §3.1) whose points are
// drawn from the voxels in proportion to their density, so the z-buffer shows the volume's
// visible voxels and the flame display its density (the paper's "X-ray image", §3.4).
#include <cstddef>
#include <memory>

#include "model/project.h"
#include "render/compiled_ifs.h"
#include "volume/density_volume.h"

namespace gridifs {

/// Points in the table of the compiled function: a render of any length replots them.
inline constexpr std::size_t kVolumePointTable = std::size_t(1) << 22;

/// The IFS of one constant map onto `volume`'s points (`points` of them, seeded by
/// project.render.seed), coloured with the weight-averaged colour of the project's active
/// functions. Throws ModelError("functions", …) when the volume is empty.
std::shared_ptr<const CompiledIfs> compileVolumePoints(const Project& project, const DensityVolume& volume,
                                                       std::size_t points = kVolumePointTable);

}  // namespace gridifs
