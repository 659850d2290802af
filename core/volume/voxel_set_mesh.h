#pragma once
// The surface of a voxel set (the iso-surface at 1/2 of its density volume, 1 inside and 0
// outside) as an OpenMesh mesh: what export-mesh and `volume -o OUT.obj` write of the
// deterministic algorithm over sets (Sokolov & Gentil, §3.3), and the mesh of a drawing set.
#include "mesh/ifs_mesh.h"
#include "volume/voxel_set.h"

namespace gridifs {

/// Voxels per axis at which a drawing set is meshed for the deterministic algorithm on meshes.
inline constexpr int kImageMeshResolution = 256;

/// OpenVDB's volumeToMesh of the set's density at 1/2, faces wound outward. Empty for an empty
/// set. Throws IoError when the OpenVDB plugin cannot be loaded or its temporary file written.
IfsMesh voxelSetMesh(const VoxelSet& set);

}  // namespace gridifs
