#pragma once
// Samples of condensation sets read from files, for the chaos game (Barnsley's condensation map:
// a uniformly random point of the set).
#include <filesystem>

#include "render/compiled_ifs.h"

namespace gridifs {

/// A sampler for compileIfs: a set is voxelized at `resolution`³ and sampled uniformly inside its
/// voxels (the set's volume for `fill: solid`, a shell one voxel thick for `surface`).
CondensationSampler makeCondensationSampler(const Project& project, const std::filesystem::path& projectFolder,
                                            int resolution = 256);

}  // namespace gridifs
