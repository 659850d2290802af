#pragma once
// Reading and writing meshes through OpenMesh (base meshes and the deterministic algorithm):
// OBJ, PLY, STL and OFF, with vertex colors where the format has them, written atomically.
#include <filesystem>
#include <optional>
#include <string>

#include "mesh/ifs_mesh.h"

namespace gridifs {

enum class MeshFormat { Ply, Obj, Stl, Off };

/// The format named by a path's extension (case-insensitive: .ply .obj .stl .off), if any.
std::optional<MeshFormat> meshFormatFromPath(const std::filesystem::path& path);
const char* meshFormatName(MeshFormat format);  // "PLY", "OBJ", ...
/// PLY and OFF carry per-vertex RGB; OpenMesh's OBJ writer and STL have no vertex colors.
bool formatHasVertexColors(MeshFormat format);
/// STL stores triangles only (OpenMesh's STL writer skips other faces).
bool formatNeedsTriangles(MeshFormat format);

/// Files larger than this are refused as base meshes (a hostile file must not exhaust memory).
inline constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t(1) << 30;

/// Reads a mesh with OpenMesh. Faces OpenMesh could only add by duplicating their vertices
/// (non-manifold input) keep face status `fixed_nonmanifold` (the mesh has face status).
/// Throws ModelError (message names the file) when the file is missing, too large, of an
/// unknown format or unreadable. Thread-safe with respect to other mesh_io calls (OpenMesh's
/// message streams are muted under a lock); OpenMesh's messages are never printed.
IfsMesh readMeshFile(const std::filesystem::path& file);

struct MeshWriteOptions {
  bool binary = true;        // PLY and STL: binary (OBJ and OFF are always ASCII)
  bool vertexColors = true;  // ignored for formats without vertex colors
};

/// Checks, before any work, that `file` can be written as a mesh: a known extension, an
/// existing folder in which a file can be created, and not a folder itself. Throws ModelError
/// with one sentence naming the file. Creates and removes a probe file next to `file`.
void checkMeshOutputPath(const std::filesystem::path& file);

/// Writes `mesh` to `file` in the format of its extension: a temporary file in the same folder
/// is written, flushed, synced and renamed over `file`, so `file` is either the old content
/// or the complete new mesh. Throws IoError (naming the file) on any failure, ModelError for an
/// unknown extension. The per-face `address` property goes into PLY files only. Thread-safe for
/// distinct files (OpenMesh's message streams are muted under the same lock as reading).
void writeMeshFile(const IfsMesh& mesh, const std::filesystem::path& file, const MeshWriteOptions& options = {});

}  // namespace gridifs
