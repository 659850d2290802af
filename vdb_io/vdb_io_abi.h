#pragma once
// The C interface between GridIFS and its OpenVDB plugin (libgridifs_vdb_io.so), the only code
// linked to OpenVDB. Why a plugin: OpenVDB's ~69,000 symbol relocations, with its long template
// names hashed one by one, cost every process about 30 ms of dynamic loading at start; only the
// volume features need it, so it is loaded with dlopen when first used (core/volume/vdb_io.cpp).
// Plain C types only; a stale plugin from an older build is refused by its version.
//
// The lattice is GridIFS's N³ voxel lattice of X = [-1, 1]³: voxel (i, j, k) has its centre at
// (−1 + (2i+1)/N, …), and grid index (i, j, k) is voxel (i, j, k) (a linear transform of voxel size
// 2/N translated by −1 + 1/N). Functions return GRIDIFS_VDB_OK or a GridifsVdbStatus with a message
// (no trailing newline) in `error`.
#include <stddef.h>
#include <stdint.h>

#define GRIDIFS_VDB_IO_ABI_VERSION 1

#ifdef __cplusplus
extern "C" {
#endif

enum GridifsVdbStatus {
  GRIDIFS_VDB_OK = 0,
  GRIDIFS_VDB_FAILED = 1,          // the library reported an error (the message says which)
  GRIDIFS_VDB_UNREADABLE = 2,      // the file could not be read as a VDB file
  GRIDIFS_VDB_NO_SUCH_GRID = 3,    // the file has no grid of that name
  GRIDIFS_VDB_NOT_FLOAT_GRID = 4,  // the grid holds something other than floats
};

/// Receives lattice voxels, `count` of them as (i, j, k) triples, a block at a time.
typedef void (*GridifsVdbVoxels)(void* context, const int32_t* ijk, size_t count);

/// The plugin's GRIDIFS_VDB_IO_ABI_VERSION.
int gridifs_vdb_io_abi_version(void);

/// Writes `path`: a float grid "density" of class fog volume (background 0, only voxels with
/// density > 0 active) and, when `color` is not null, a Vec3s grid "color" at the same voxels.
/// density: N³ values at index i + N·(j + N·k); color: 3 per voxel, same order.
int gridifs_vdb_io_write_volume(const char* path, int n, const float* density, const float* color, char* error,
                                size_t errorSize);

/// The lattice voxels of a mesh (points: x y z per vertex; triangles and quads: vertex indices).
/// solid: the voxels inside the closed mesh's level set; else the voxels whose centre is within
/// `halfDiagonal` of the surface (an unsigned distance field). Voxels may repeat.
int gridifs_vdb_io_mesh_voxels(int n, const float* points, size_t pointCount, const uint32_t* triangles,
                               size_t triangleCount, const uint32_t* quads, size_t quadCount, int solid,
                               float halfDiagonal, GridifsVdbVoxels emit, void* context, char* error, size_t errorSize);

/// The lattice voxels near the active values of float grid `grid` of `path` where the grid,
/// sampled trilinearly at the voxel's centre, is at least `threshold`. Voxels may repeat.
int gridifs_vdb_io_grid_voxels(const char* path, const char* grid, int n, float threshold, GridifsVdbVoxels emit,
                               void* context, char* error, size_t errorSize);

/// Receives a mesh: points (x y z each), triangles and quads (vertex indices).
typedef void (*GridifsVdbMesh)(void* context, const float* points, size_t pointCount, const uint32_t* triangles,
                               size_t triangleCount, const uint32_t* quads, size_t quadCount);

/// The iso-surface at `threshold` of float grid `grid` of `path` (OpenVDB's volumeToMesh, faces
/// wound as for a level set: inside below the iso-value).
int gridifs_vdb_io_grid_mesh(const char* path, const char* grid, float threshold, GridifsVdbMesh emit, void* context,
                             char* error, size_t errorSize);

#ifdef __cplusplus
}
#endif
