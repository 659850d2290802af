#pragma once
// Condensation sets as voxel sets (Sokolov & Gentil, §4.2: "the models were voxelized"): built-in
// primitives by their voxel centres, meshes through OpenVDB's mesh-to-volume conversion, VDB
// grids by a threshold.
#include <filesystem>
#include <string>

#include "model/condensation_set.h"
#include "volume/voxel_set.h"

namespace gridifs {

/// The voxels of `set` on `lattice`: those whose centres lie inside (boundary included) for a
/// sphere, box, torus, solid mesh or VDB level; those within half a voxel diagonal of the surface
/// for a mesh with `fill: surface`. Mesh and VDB paths are relative to `projectFolder`.
/// Throws ModelError (a path under `jsonPath`, one sentence naming the file where there is one)
/// when the file is missing or unreadable, a solid mesh is not closed, the VDB has no such float
/// grid, or the set has no voxel inside X.
VoxelSet voxelizeSet(const CondensationSet& set, const VoxelLattice& lattice,
                     const std::filesystem::path& projectFolder, const std::string& jsonPath);

}  // namespace gridifs
