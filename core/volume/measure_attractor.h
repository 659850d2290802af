#pragma once
// The measure attractor of an IFS as a density volume (Sokolov & Gentil, §3.4). With median
// functions: the random iteration over voxel sets (start from a random non-empty set, apply a
// function chosen by weight, after `skip` iterations add every voxel of the current set to P).
// Otherwise: the chaos game's points binned into voxels (P = hits per voxel). Density = P / max P.
#include <atomic>
#include <filesystem>
#include <functional>

#include "model/project.h"
#include "volume/density_volume.h"

namespace gridifs {

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
};

/// Whether `project` has a median function (and so runs the iteration over voxel sets).
bool usesSetIteration(const Project& project);

/// Whether the volume gets a colour grid: the active functions do not all share one colour.
bool hasColorVolume(const Project& project);

/// Computes the density volume of `project`. Throws ModelError (a JSON path) when a set cannot be
/// voxelized or the IFS cannot be compiled.
DensityVolume computeDensityVolume(const Project& project, const VolumeJob& job);

}  // namespace gridifs
