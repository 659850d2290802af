#pragma once
// Line drawings of condensation sets for the modeller's views: primitives as wireframes, meshes
// as their placed edges, VDB sets as the outline of their voxels. Headless: the views turn the
// segments into lines of their own.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "mesh/ifs_mesh.h"
#include "model/condensation_set.h"
#include "volume/voxel_set.h"

namespace gridifs {

/// Line segments as consecutive pairs of end points: segment s runs from points[2s] to points[2s+1].
using LineSegments = std::vector<Vec3>;

/// A primitive's wireframe: a box's 12 edges, a sphere's three great circles (in the xy, yz and zx
/// planes through its centre), a torus's outer, inner, upper and lower rings and eight tube loops
/// around its centre line. Circles have `segmentsPerLoop` segments. Empty for file sets.
LineSegments primitiveOutline(const CondensationSet& set, int segmentsPerLoop = 48);

/// The edges of `mesh` placed by `placement` (placement(q) = T + R·(S·q)); a mesh with more than
/// `maxSegments` edges keeps every k-th edge, so a huge mesh stays a light drawing.
LineSegments meshOutline(const IfsMesh& mesh, const Placement& placement, std::size_t maxSegments);

/// The outline of a voxel set: every edge of the faces between a voxel of the set and one outside
/// it (or the lattice's border), each edge once; at most `maxSegments` (every k-th beyond that).
LineSegments voxelOutline(const VoxelSet& voxels, std::size_t maxSegments);

/// The drawing of any set: a primitive's wireframe; a mesh's placed edges; a VDB set's voxel
/// outline on a `resolution`³ lattice. File sets are voxelized on that lattice first, so a set that
/// cannot be read, is not closed for `fill: solid`, or has no voxel inside X throws the
/// voxelizer's ModelError (a path under `jsonPath`, one sentence naming the file).
LineSegments setOutline(const CondensationSet& set, const std::filesystem::path& projectFolder,
                        const std::string& jsonPath, int resolution = 32, std::size_t maxSegments = 20000);

}  // namespace gridifs
