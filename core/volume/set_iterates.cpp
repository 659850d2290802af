#include "volume/set_iterates.h"

#include <algorithm>
#include <iterator>

#include "base/hash.h"
#include "base/parallel.h"
#include "model/stack_evaluator.h"
#include "volume/set_orbit_memo.h"
#include "volume/set_voxelizer.h"

namespace gridifs {
namespace {

/// f(in), with f(∅) = ∅ for every map but a constant one: the sets of H(X) are non-empty, but a
/// point map may send a whole set out of X, and the median of an empty set is not defined.
void applyTo(const SetFunction& f, const VoxelSet& in, VoxelSet& out, SetScratch& scratch, int threads) {
  if (in.empty()) {
    out.lattice = in.lattice;
    out.voxels = f.condensation().voxels;  // C for a constant map; a median's C is not its image of ∅
    if (!f.isConstant()) out.voxels.clear();
    return;
  }
  f.apply(in, out, scratch, threads);
}

}  // namespace

SetSystem buildSetSystem(const Project& project, const VoxelLattice& lattice,
                         const std::filesystem::path& projectFolder) {
  SetSystem system;
  system.lattice = lattice;
  for (std::size_t i = 0; i < project.functions.size(); ++i) {
    const Function& f = project.functions[i];
    if (f.muted || !(f.weight > 0.0)) continue;
    const std::string path = "functions[" + std::to_string(i) + "]";
    switch (f.kind) {
      case FunctionKind::Median:
        system.functions.push_back(
            SetFunction::median(voxelizeSet(f.set, lattice, projectFolder, path + ".set"), f.rotate, f.rotate_axis));
        break;
      case FunctionKind::Condensation:
        system.functions.push_back(SetFunction::constant(voxelizeSet(f.set, lattice, projectFolder, path + ".set")));
        break;
      case FunctionKind::Grid:
        system.functions.push_back(
            SetFunction::pointMap(compileFunction(f, *evaluateFunctionAt(f, path, project.time), i), lattice));
        break;
      case FunctionKind::Matrix:
        throw ModelError(path + ".kind", "a \"matrix\" function cannot map voxel sets");
    }
    system.sources.push_back(i);
    system.weights.push_back(f.weight);
  }
  if (system.functions.empty()) throw ModelError("functions", "no unmuted function has a positive weight");
  return system;
}

VoxelSet startSet(const Project& project, const VoxelLattice& lattice, const std::filesystem::path& projectFolder) {
  if (project.volume && project.volume->start)
    return voxelizeSet(*project.volume->start, lattice, projectFolder, "volume.start");
  VoxelSet all{lattice, std::vector<std::uint32_t>(lattice.voxelCount())};
  for (std::size_t v = 0; v < all.voxels.size(); ++v) all.voxels[v] = std::uint32_t(v);
  return all;
}

VoxelSet unite(const VoxelSet& a, const VoxelSet& b) {
  VoxelSet out{a.lattice, {}};
  out.voxels.reserve(a.size() + b.size());
  std::set_union(a.voxels.begin(), a.voxels.end(), b.voxels.begin(), b.voxels.end(), std::back_inserter(out.voxels));
  return out;
}

VoxelSet iterateSets(const SetSystem& system, const VoxelSet& start, int depth, int threads,
                     const std::function<void(double)>& progress) {
  threads = resolveThreadCount(threads);
  VoxelSet current = start, image;
  SetScratch scratch;
  for (int k = 0; k < depth; ++k) {
    VoxelSet next{system.lattice, {}};
    for (const SetFunction& f : system.functions) {
      applyTo(f, current, image, scratch, threads);
      next = unite(next, image);
    }
    current = std::move(next);
    if (progress) progress(double(k + 1) / depth);
  }
  return current;
}

std::int64_t bookPageCount(std::size_t functions, int depth, std::int64_t limit) {
  std::int64_t pages = 1;
  for (int k = 0; k < depth; ++k) {
    if (pages > limit / std::int64_t(std::max<std::size_t>(functions, 1))) return -1;
    pages *= std::int64_t(functions);
  }
  return pages > limit ? -1 : pages;
}

namespace {

/// The walk over the book's addresses, innermost map first: level k applies σ_{D−k+1}, whose
/// digit weighs N^(k−1). Every distinct set is interned with its images, so equal intermediate
/// pages (the maps are contractions: deep pages converge) cost a look-up.
struct BookWalk {
  const SetSystem& system;
  int depth;
  int threads;
  const std::function<void(std::int64_t, const VoxelSet&)>& page;
  const std::function<void(double)>& progress;
  SetOrbitMemo memo;
  SetScratch scratch;
  std::vector<VoxelSet> owned;  // per level: the set when the memo is full
  double nodes = 0.0, done = 0.0;

  void visit(int level, const VoxelSet& set, int id, std::int64_t partial, std::int64_t weight) {
    const std::size_t n = system.functions.size();
    for (std::size_t i = 0; i < n; ++i) {
      const std::int64_t number = partial + std::int64_t(i) * weight;
      int imageId = id == SetOrbitMemo::kNone ? SetOrbitMemo::kNone : memo.image(id, i);
      const VoxelSet* image = nullptr;
      if (imageId != SetOrbitMemo::kNone) {
        image = &memo.set(imageId);
      } else {
        VoxelSet& out = owned[std::size_t(level)];
        applyTo(system.functions[i], set, out, scratch, threads);
        imageId = memo.intern(out);
        if (imageId != SetOrbitMemo::kNone && id != SetOrbitMemo::kNone) memo.rememberImage(id, i, imageId);
        image = imageId == SetOrbitMemo::kNone ? &out : &memo.set(imageId);
      }
      done += 1.0;
      if (progress) progress(done / nodes);
      if (level + 1 == depth)
        page(number, *image);
      else
        visit(level + 1, *image, imageId, number, weight * std::int64_t(n));
    }
  }
};

}  // namespace

void forEachBookPage(const SetSystem& system, const VoxelSet& start, int depth, int threads,
                     const std::function<void(std::int64_t number, const VoxelSet& set)>& page,
                     const std::function<void(double)>& progress) {
  if (depth <= 0) {
    page(0, start);
    return;
  }
  // 512 MiB of voxel indices: a 128³ book of depth 6 keeps all its distinct sets.
  BookWalk walk{system, depth,    resolveThreadCount(threads),
                page,   progress, SetOrbitMemo(system.functions.size(), std::size_t(512) << 20),
                {},     {},       0.0,
                0.0};
  walk.owned.resize(std::size_t(depth));
  double level = 1.0;
  for (int k = 0; k < depth; ++k) walk.nodes += (level *= double(system.functions.size()));
  const int startId = walk.memo.intern(start);
  walk.visit(0, startId == SetOrbitMemo::kNone ? start : walk.memo.set(startId), startId, 0, 1);
}

DensityVolume setDensityVolume(const VoxelSet& set) {
  DensityVolume volume{set.lattice, std::vector<float>(set.lattice.voxelCount(), 0.0f), {}, double(set.size())};
  for (std::uint32_t v : set.voxels) volume.density[v] = 1.0f;
  return volume;
}

std::vector<Vec3> sampleDensityVolume(const DensityVolume& volume, std::size_t count, std::uint64_t seed) {
  std::vector<std::uint32_t> voxels;
  std::vector<double> cumulative;
  double total = 0.0;
  for (std::size_t v = 0; v < volume.density.size(); ++v) {
    if (!(volume.density[v] > 0.0f)) continue;
    total += volume.density[v];
    voxels.push_back(std::uint32_t(v));
    cumulative.push_back(total);
  }
  std::vector<Vec3> out;
  if (voxels.empty()) return out;
  out.reserve(count);
  std::uint64_t state = splitmix64(seed ^ 0xD1B54A32D192ED03ull);
  auto unit = [&] { return double(splitmix64(state++) >> 11) * (1.0 / 9007199254740992.0); };
  const double half = 0.5 * volume.lattice.voxelSize();
  for (std::size_t s = 0; s < count; ++s) {
    const double r = unit() * total;
    const std::size_t pick = std::min(
        std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), r) - cumulative.begin()), voxels.size() - 1);
    const Vec3 c = volume.lattice.centre(voxels[pick]);
    out.push_back(c + half * Vec3{2.0 * unit() - 1.0, 2.0 * unit() - 1.0, 2.0 * unit() - 1.0});
  }
  return out;
}

}  // namespace gridifs
