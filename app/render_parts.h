#pragma once
// `--part K/N` for render and volume, and `gridifs merge`: a split render's accumulations
// written to and read from render part files (io/render_part_file.h, docs/FARM.md).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/render_part_file.h"
#include "render/accumulation.h"
#include "render/sample_chunks.h"
#include "volume/measure_attractor.h"

namespace gridifs::cli {

/// Parses "K/N" (0 ≤ K < N ≤ kMaxRenderParts). Throws CliError(2).
RenderPart parsePart(const std::string& text);
inline constexpr std::int64_t kMaxRenderParts = 100000;

/// Writes the accumulations of one frame's time samples (one without motion blur) as a part file.
void writeImagePart(const std::filesystem::path& out, const RenderPartHeader& header,
                    const std::vector<Accumulation>& timeSamples);

/// Reads a part written by writeImagePart into `timeSamples` (one accumulation per time sample).
/// Kept by the caller from part to part, its buffers are reused instead of allocated (and
/// page-faulted in) again for every part. Throws PartFileError.
void readImagePart(RenderPartReader& reader, std::vector<Accumulation>& timeSamples);

/// Adds a part's time samples into `sums`: counts and sums by (saturating) addition, keys by
/// minimum, so the order in which parts are added never changes the result. Throws
/// PartFileError (another motion blur) or std::invalid_argument (another size, key form, lights).
void addImageParts(std::vector<Accumulation>& sums, const std::vector<Accumulation>& part);

void writeVolumePart(const std::filesystem::path& out, const RenderPartHeader& header, const VoxelAccumulation& acc);
void addVolumePart(RenderPartReader& reader, VoxelAccumulation& sum, bool first);

/// Develops and writes a frame from merged accumulations exactly as `gridifs render` does for the
/// same project and options (verb_render.cpp). `project` and `optionsJson` as the parts carry them.
int finishMergedFrame(const Project& project, const std::string& file, const std::string& out,
                      const std::string& optionsJson, const std::vector<Accumulation>& sums,
                      std::optional<int> bitDepth, bool transparent);

/// The digest of a render: the project as rendered and the options that shape the accumulation.
std::string partDigest(const std::string& kind, const std::string& project, const std::string& options,
                       std::int64_t parts, const std::string& device, std::optional<std::int64_t> frame);

}  // namespace gridifs::cli
