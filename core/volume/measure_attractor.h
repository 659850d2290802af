#pragma once
// The measure attractor of an IFS as a density volume (Sokolov & Gentil, §3.4). With median
// functions: the random iteration over voxel sets (start from a random non-empty set, apply a
// function chosen by weight, after `skip` iterations add every voxel of the current set to P).
// Otherwise: the chaos game's points binned into voxels (P = hits per voxel). Density = P / max P.
#include <atomic>
#include <filesystem>
#include <functional>

#include "model/project.h"
#include "render/compiled_ifs.h"
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
};

/// Whether `project` has a median function (and so runs the iteration over voxel sets).
bool usesSetIteration(const Project& project);

/// Whether the volume gets a colour grid: the active functions do not all share one colour.
bool hasColorVolume(const Project& project);

/// Computes the density volume of `project`. Throws ModelError (a JSON path) when a set cannot be
/// voxelized or the IFS cannot be compiled.
DensityVolume computeDensityVolume(const Project& project, const VolumeJob& job);

}  // namespace gridifs
