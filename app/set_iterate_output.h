#pragma once
// `gridifs volume FILE --depth D [--pages]` and `gridifs export-mesh` of a project with median
// functions: the deterministic algorithm over sets (Sokolov & Gentil, §3.3) and its book of
// drawings, written as VDB density volumes, images or iso-surface meshes.
#include <optional>
#include <string>

namespace gridifs::cli {

/// The most pages a book may have (N^D): a sheet of files, not a disk full of them.
inline constexpr std::int64_t kMaxBookPages = 4096;
/// The deepest set iterate A_D.
inline constexpr int kMaxSetDepth = 64;

struct SetIterateRequest {
  std::string file, out;  // out: .vdb, .png/.exr/.tif, or .obj/.ply/.stl/.off; a printf pattern with pages
  int depth = 0;
  bool pages = false;  // every page of the book instead of A_D
  std::optional<int> resolution, threads;
  std::optional<double> time;
  bool quiet = false;
  bool ascii = false;  // PLY and STL meshes in ASCII
};

/// Runs the request. Bad input (an unknown extension, a pattern without one number, an absurd
/// depth or resolution, too many pages, a set that cannot be voxelized) throws CliError(2) before
/// anything is written; a failure while writing throws CliError(1).
int runSetIterates(const SetIterateRequest& request);

}  // namespace gridifs::cli
