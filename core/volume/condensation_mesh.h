#pragma once
// Condensation sets as surface meshes, for the deterministic algorithm with condensation
// (A_n = C ∪ F(A_{n−1}), Sokolov & Gentil, §3.1): a primitive tessellated, a mesh set's own mesh
// in its placement, a VDB set's iso-surface at its threshold (OpenVDB's volumeToMesh). The
// surface of a solid set is its boundary, so `fill` does not change the mesh.
#include <filesystem>
#include <string>

#include "mesh/deterministic_ifs.h"
#include "model/condensation_set.h"

namespace gridifs {

/// Tessellation of the primitives: a UV sphere of 32 segments × 16 rings (512 faces), a box of
/// 12 triangles, a torus of 48 × 16 quads (768 faces).
inline constexpr int kSphereSegments = 32, kSphereRings = 16;
inline constexpr int kTorusMajorSegments = 48, kTorusMinorSegments = 16;

/// The surface of `set` in X, outward oriented. Mesh and VDB paths are relative to
/// `projectFolder`. Throws ModelError under `jsonPath` (one sentence naming the file) when the
/// file is missing or unreadable, the mesh has no faces or a non-finite vertex, the VDB has no
/// such float grid, or its iso-surface is empty.
IfsMesh condensationSetMesh(const CondensationSet& set, const std::filesystem::path& projectFolder,
                            const std::string& jsonPath);

/// Fills the mesh of every condensation of `ifs` from the functions of `project`.
void loadCondensationMeshes(DeterministicIfs& ifs, const Project& project, const std::filesystem::path& projectFolder);

}  // namespace gridifs
