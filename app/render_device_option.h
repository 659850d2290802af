#pragma once
// `--device auto|gpu|cpu` for render, export-points and volume, and the device line of `info`: which
// renderer runs (the GPU compute renderer or the CPU worker pool), with the CPU as the fallback.
#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "io/point_cloud_export.h"
#include "render/chaos_renderer.h"
#include "render/sample_chunks.h"
#include "volume/measure_attractor.h"

namespace gridifs::cli {

/// Adds the --device option to a verb.
void addDeviceOption(CLI::App& app, std::optional<std::string>& device);

/// Checks --device ("auto" when absent). Bad value → CliError(2).
std::string checkedDevice(const std::optional<std::string>& device);

/// Renders `job` to completion on `device` and returns its buffers undeveloped
/// (render/accumulation.h): gpu fails with CliError(1) and one sentence when there is no usable
/// GPU; auto falls back to the CPU (printDeviceNote says so). `progress` as in
/// renderToCompletion (false cancels: RenderCancelled). `used` receives the device's name.
Accumulation accumulateOnDevice(const std::string& device, std::shared_ptr<const CompiledIfs> ifs, const RenderJob& job,
                                const std::function<bool(const RenderStats&)>& progress, std::string& used);

/// The share of the work job.part plays on `used` (the device accumulateOnDevice named), for the
/// part header: on the CPU the part's chunks, on a GPU its chains (the GPU splits its chains,
/// not the CPU's chunks).
ChunkRange playedRange(const std::string& used, const RenderJob& job);

/// The point walk for export-points on `device` (empty: the CPU's generatePoints), with the same
/// failure and fallback rules.
PointGenerator pointGeneratorOn(const std::string& device, std::string& used);

/// The density volume's voxel binning on `device` (empty: the CPU workers), with the same failure
/// and fallback rules. `setIteration`: the project has median functions, whose iteration over
/// voxel sets only the CPU runs.
VoxelBinner voxelBinnerOn(const std::string& device, bool setIteration, std::string& used);

/// Prints, once, why `auto` rendered on the CPU (after the output was written, so that a failing
/// verb still prints one sentence only).
void printDeviceNote();

/// What `--device auto` would use here, in one line (`gridifs info`).
std::string deviceReport(const std::string& device, bool& gpu);

}  // namespace gridifs::cli
