#pragma once
// Internal to volume/: OpenVDB set-up shared by the voxelizer and the file writer.
#include <openvdb/openvdb.h>

#include <filesystem>
#include <string>

#include "volume/voxel_set.h"

namespace gridifs {

/// Calls openvdb::initialize() once per process. Thread-safe.
void initializeOpenVdb();

/// The lattice's index-to-world transform (voxel size 2/N, voxel 0's centre at −1 + 1/N).
openvdb::math::Transform::Ptr latticeTransform(const VoxelLattice& lattice);

/// The float grid `name` of the VDB file. Throws ModelError under `jsonPath` naming the file when
/// it is missing or unreadable or has no float grid of that name.
openvdb::FloatGrid::Ptr readFloatGrid(const std::filesystem::path& file, const std::string& name,
                                      const std::string& jsonPath);

}  // namespace gridifs
