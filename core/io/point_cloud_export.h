#pragma once
// Chaos-game points as a binary PLY: the points the renderer would
// plot, x y z float and red green blue uchar, little-endian. Shared by the CLI verb and the GUI.
#include <filesystem>
#include <functional>
#include <string>

#include "render/chaos_renderer.h"

namespace gridifs {

struct PointCloudResult {
  std::uint64_t written = 0;  // points in the file
  RenderStats stats;
  bool cancelled = false;  // progress returned false: nothing was written
};

/// Streams the points of `job` into `out` through a temporary file in the same folder that is
/// renamed over `out` only when everything was written, so nothing is ever half-written.
/// `progress` is called after every batch on the calling thread; returning false cancels.
/// Throws IoError naming `out` when writing fails, and ModelError (no path) when at least half
/// of the samples were non-finite or escaped (the IFS has no usable attractor; nothing written).
/// `generator` walks the chaos game (default: generatePoints on the CPU; the GPU's
/// generatePointsGpu has the same signature).
/// The PLY's comment: what the points are of (`source`, the project's file name), with the job's
/// samples, seed and worker streams (the points depend on all three).
std::string pointCloudDescription(const std::string& source, const RenderJob& job);

using PointGenerator = std::function<RenderStats(const CompiledIfs&, const RenderJob&,
                                                 const std::function<bool(const PointBatch&, const RenderStats&)>&)>;
PointCloudResult writePointCloud(const CompiledIfs& ifs, const RenderJob& job, const std::filesystem::path& out,
                                 const std::string& description,
                                 const std::function<bool(const RenderStats&)>& progress = {},
                                 const PointGenerator& generator = {});

/// The PLY header; `count` is rewritten in place at the end, so the header's length does not
/// depend on it (a comment line absorbs the digits). Exposed for tests.
std::string pointCloudHeader(std::uint64_t count, const std::string& description);

}  // namespace gridifs
