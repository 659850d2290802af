#pragma once
// Internal to volume/: OpenVDB's work for the volume features, done by the OpenVDB plugin
// (vdb_io/, loaded on first use; see vdb_io_abi.h for why), in GridIFS's own types.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "volume/voxel_set.h"

namespace gridifs::vdb_io {

/// Loads the plugin now (it is loaded once, on first use); throws IoError when it cannot be.
void requirePlugin();

/// Writes an OpenVDB file at `file` (the caller makes it atomic): the density of the N³ lattice
/// as a fog volume and, when `color` is not empty, its colour (3 per voxel). Throws IoError with
/// the library's message, or when the plugin cannot be loaded.
void writeVolume(const std::filesystem::path& file, const VoxelLattice& lattice, const std::vector<float>& density,
                 const std::vector<float>& color);

/// A triangle and quad mesh (vertex positions x y z, faces as vertex indices).
struct FaceLists {
  std::vector<float> points;
  std::vector<std::uint32_t> triangles, quads;  // 3 and 4 indices per face
};

/// The lattice voxels of a mesh: inside it (solid, for a closed mesh), or within `halfDiagonal`
/// of its surface, in no order, possibly repeated. Throws ModelError under `jsonPath` when OpenVDB fails.
std::vector<std::uint32_t> meshVoxels(const FaceLists& mesh, const VoxelLattice& lattice, bool solid,
                                      float halfDiagonal, const std::string& jsonPath);

/// The lattice voxels where float grid `grid` of the VDB file, sampled at the voxel centre, is at
/// least `threshold`, in no order, possibly repeated. Throws ModelError under `jsonPath` (".vdb" or ".grid")
/// naming the file when it is missing or unreadable or has no float grid of that name.
std::vector<std::uint32_t> gridVoxels(const std::filesystem::path& file, const std::string& grid,
                                      const VoxelLattice& lattice, float threshold, const std::string& jsonPath);

/// The iso-surface at `threshold` of float grid `grid` (faces wound as for a level set: inside
/// below the iso-value). Throws as gridVoxels does.
FaceLists gridIsoSurface(const std::filesystem::path& file, const std::string& grid, float threshold,
                         const std::string& jsonPath);

}  // namespace gridifs::vdb_io
