#pragma once
// The deterministic algorithm over sets (Sokolov & Gentil, §3.3): the functions of an IFS act on
// voxel sets, A_k = ⋃ f_i(A_{k−1}) (a condensation function contributes its constant set C), and
// the "book of drawings": the pages f_σ1 ∘ … ∘ f_σD (S) for every address σ, which for two median
// functions, sorted by address, morph one condensation set into the other (their figure 8).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "model/project.h"
#include "volume/density_volume.h"
#include "volume/set_function.h"

namespace gridifs {

/// The active functions of a project (unmuted, positive weight) as maps of voxel sets.
struct SetSystem {
  VoxelLattice lattice;
  std::vector<SetFunction> functions;
  std::vector<std::size_t> sources;  // Project::functions index of each
  std::vector<double> weights;
};

/// Builds the set maps of `project` on `lattice`: median, constant condensation, or a grid
/// function's point map at `project.time`. Paths of file sets are relative to `projectFolder`.
/// Throws ModelError (a JSON path) when no function is active, a set cannot be voxelized, a grid
/// cannot be evaluated, or a function is a matrix function.
SetSystem buildSetSystem(const Project& project, const VoxelLattice& lattice,
                         const std::filesystem::path& projectFolder);

/// The start set S of the deterministic algorithm: `volume.start` voxelized, or all of X.
/// Throws ModelError under "volume.start" as voxelizeSet.
VoxelSet startSet(const Project& project, const VoxelLattice& lattice, const std::filesystem::path& projectFolder);

/// A ∪ B of two sets on one lattice.
VoxelSet unite(const VoxelSet& a, const VoxelSet& b);

/// A_depth = ⋃_i f_i(A_{depth−1}), A_0 = `start`. `threads` ≤ 0: every hardware thread.
/// `progress(done)` (0..1) is called on the calling thread after each step when set.
VoxelSet iterateSets(const SetSystem& system, const VoxelSet& start, int depth, int threads,
                     const std::function<void(double)>& progress = {});

/// The number of pages of a book of `depth` for `functions` maps (functions^depth), or -1 when it
/// is above `limit`.
std::int64_t bookPageCount(std::size_t functions, int depth, std::int64_t limit);

/// Calls `page(number, set)` for every page f_σ1 ∘ … ∘ f_σD (start), where number = Σ σ_k N^(D−k)
/// (the address σ1 σ2 … σD read in base N = functions.size(), σ1 the most significant digit, σ
/// counting the active functions from 0). Pages come in no particular order; equal intermediate
/// sets are computed once. `progress` as in iterateSets.
void forEachBookPage(const SetSystem& system, const VoxelSet& start, int depth, int threads,
                     const std::function<void(std::int64_t number, const VoxelSet& set)>& page,
                     const std::function<void(double)>& progress = {});

/// A set as a density volume: 1 on its voxels, 0 elsewhere.
DensityVolume setDensityVolume(const VoxelSet& set);

/// `count` points uniformly distributed in the voxels of `volume`, each voxel chosen with a
/// probability proportional to its density; the same for the same seed. Empty when the volume is.
std::vector<Vec3> sampleDensityVolume(const DensityVolume& volume, std::size_t count, std::uint64_t seed);

}  // namespace gridifs
