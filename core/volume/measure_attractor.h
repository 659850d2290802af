#pragma once
// The measure attractor of an IFS as a density volume (Sokolov & Gentil, §3.4). With median
// functions: the random iteration over voxel sets (start from a random non-empty set, apply a
// function chosen by weight, after `skip` iterations add every voxel of the current set to P).
// Otherwise: the chaos game's points binned into voxels (P = hits per voxel). Density = P / max P.
#include <atomic>
#include <filesystem>
#include <functional>
#include <optional>

#include "model/project.h"
#include "render/compiled_ifs.h"
#include "render/sample_chunks.h"
#include "volume/density_volume.h"

namespace gridifs {

struct VolumeJob;

/// Counts the chaos game's points per voxel somewhere other than the CPU workers (the GPU
/// renderer's voxel binning): hits per voxel of settings.resolution³ into `counts` (x fastest)
/// and, when `colors` is not empty on entry, the points' rgb sums (3 per voxel) into it. Returns
/// false to leave the binning to the CPU workers.
using VoxelBinner = std::function<bool(const CompiledIfs& ifs, const VolumeJob& job, std::vector<std::uint32_t>& counts,
                                       std::vector<float>& colors)>;

struct VolumeJob {
  VolumeSettings settings;
  int threads = 0;                      // ≤ 0: every hardware thread
  std::filesystem::path projectFolder;  // mesh and VDB set paths are relative to it
  /// Called on the calling thread with the fraction done, now and then.
  std::function<void(double)> progress;
  /// Set from another thread to stop early; the volume then holds what was done so far.
  const std::atomic<bool>* cancel = nullptr;
  /// Called on the calling thread after each accumulated set iteration with the partial volume
  /// (unnormalised visit counts in `density`), for a progressive display. May be empty.
  std::function<void(const DensityVolume&)> partial;
  /// Bins the chaos game's points (an IFS without median functions) elsewhere when set.
  VoxelBinner binner;
  /// Only this part's chunks of the sample budget (gridifs volume --part K/N); absent: all.
  std::optional<RenderPart> part;
};

/// The chaos game's points binned into voxels, before normalisation: hits per voxel and the
/// fixed-point rgb sums (render/accumulation.h), both exact integer sums, so the accumulations of
/// a volume's parts add up to the whole volume's.
struct VoxelAccumulation {
  int resolution = 0;
  std::vector<std::uint32_t> counts;     // resolution³, x fastest
  std::vector<std::uint64_t> colorSums;  // 3 per voxel when hasColorVolume, else empty
  std::int64_t samples = 0;
  /// Adds `other` in. Throws std::invalid_argument when the two do not match.
  void add(const VoxelAccumulation& other);
};

/// Bins the chaos game's points of job.part (every chunk when absent) on the CPU workers.
/// For projects without median functions. Throws ModelError as computeDensityVolume.
VoxelAccumulation accumulateVoxels(const Project& project, const VolumeJob& job);

/// The density volume of an accumulation: counts normalised (density = P / max P), mean colours,
/// and the project's field modulation when job.settings has one.
DensityVolume developVoxels(const Project& project, const VolumeJob& job, const VoxelAccumulation& acc);

/// Whether `project` has a median function (and so runs the iteration over voxel sets).
bool usesSetIteration(const Project& project);

/// Whether the volume gets a colour grid: the active functions do not all share one colour.
bool hasColorVolume(const Project& project);

/// Computes the density volume of `project`. Throws ModelError (a JSON path) when a set cannot be
/// voxelized or the IFS cannot be compiled.
DensityVolume computeDensityVolume(const Project& project, const VolumeJob& job);

}  // namespace gridifs
