#include "volume/measure_attractor.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <thread>

#include "base/hash.h"
#include "base/parallel.h"
#include "model/stack_evaluator.h"
#include "render/accumulation.h"
#include "render/barycentric_kernel.h"
#include "render/chaos_kernel.h"
#include "render/chaos_renderer.h"
#include "render/sample_chunks.h"
#include "volume/condensation_sampler.h"
#include "volume/density_field.h"
#include "volume/set_function.h"
#include "volume/set_orbit_memo.h"
#include "volume/set_voxelizer.h"

namespace gridifs {
namespace {

bool cancelled(const VolumeJob& job) { return job.cancel && job.cancel->load(std::memory_order_relaxed); }

std::vector<std::size_t> activeFunctions(const Project& project) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < project.functions.size(); ++i)
    if (!project.functions[i].muted && project.functions[i].weight > 0.0) out.push_back(i);
  if (out.empty()) throw ModelError("functions", "no unmuted function has a positive weight");
  return out;
}

/// Sokolov & Gentil, §3.4: the random iteration algorithm over sets.
DensityVolume iterateSets(const Project& project, const VolumeJob& job) {
  const VolumeSettings& settings = job.settings;
  const VoxelLattice lattice{settings.resolution};
  const int threads = resolveThreadCount(job.threads);
  const std::vector<std::size_t> active = activeFunctions(project);
  std::vector<SetFunction> functions;
  std::vector<double> cumulative;
  double total = 0.0;
  for (std::size_t i : active) {
    const Function& f = project.functions[i];
    const std::string path = "functions[" + std::to_string(i) + "]";
    switch (f.kind) {
      case FunctionKind::Median:
        functions.push_back(SetFunction::median(voxelizeSet(f.set, lattice, job.projectFolder, path + ".set"), f.rotate,
                                                f.rotate_axis));
        break;
      case FunctionKind::Condensation:
        functions.push_back(SetFunction::constant(voxelizeSet(f.set, lattice, job.projectFolder, path + ".set")));
        break;
      case FunctionKind::Grid:
        functions.push_back(
            SetFunction::pointMap(compileFunction(f, *evaluateFunctionAt(f, path, project.time), i), lattice));
        break;
      case FunctionKind::Matrix:
        throw ModelError(path + ".kind", "a \"matrix\" function cannot map voxel sets");
    }
    total += f.weight;
    cumulative.push_back(total);
  }
  const bool colored = hasColorVolume(project);
  DensityVolume volume{lattice, std::vector<float>(lattice.voxelCount(), 0.0f), {}, 0.0};
  if (colored) volume.color.assign(lattice.voxelCount() * 3, 0.0f);
  std::uint64_t state = splitmix64(settings.seed ^ 0x9E3779B97F4A7C15ull);
  auto next = [&] { return splitmix64(state++); };
  // "draw a random non-empty binary image I_0": a few random voxels.
  auto randomSet = [&] {
    VoxelSet s{lattice, {}};
    const int count = 1 + int(next() % 64);
    for (int v = 0; v < count; ++v) s.voxels.push_back(std::uint32_t(next() % lattice.voxelCount()));
    normalizeVoxels(s.voxels);
    return s;
  };
  // Every distinct set of the orbit is kept once (up to 256 MiB of voxel indices) with the images
  // already computed from it: a revisited (set, function) pair costs a look-up. Orbits through a
  // constant condensation revisit every set; two median functions rarely do.
  SetOrbitMemo memo(functions.size(), std::size_t(256) << 20);
  VoxelSet owned = randomSet(), image;  // the current set when the memo is full
  int id = memo.intern(owned);
  const VoxelSet* current = id == SetOrbitMemo::kNone ? &owned : &memo.set(id);
  SetScratch scratch;
  Vec3 color{0.5};
  const int skip = std::min(settings.skip, settings.iterations - 1);
  for (int k = 0; k < settings.iterations && !cancelled(job); ++k) {
    const double r = double(next() >> 11) * (total / 9007199254740992.0);
    const std::size_t pick =
        std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), r) - cumulative.begin());
    const std::size_t i = std::min(pick, functions.size() - 1);
    const int known = id == SetOrbitMemo::kNone ? SetOrbitMemo::kNone : memo.image(id, i);
    if (known != SetOrbitMemo::kNone) {
      id = known;
      current = &memo.set(id);
    } else {
      functions[i].apply(*current, image, scratch, threads);
      // A point map may send the whole set out of X; the iteration needs a non-empty set (a
      // fresh random one, which is not an image of the function, so it is not remembered).
      const bool restarted = image.empty();
      if (restarted) image = randomSet();
      const int imageId = memo.intern(image);
      if (imageId != SetOrbitMemo::kNone && id != SetOrbitMemo::kNone && !restarted) memo.rememberImage(id, i, imageId);
      id = imageId;
      if (id == SetOrbitMemo::kNone) {
        std::swap(owned, image);
        current = &owned;
      } else {
        current = &memo.set(id);
      }
    }
    const Function& f = project.functions[active[i]];
    color += (f.color - color) * f.color_speed;  // Draves & Reckase 2003, §5, for the whole set
    if (k >= skip) {
      float* density = volume.density.data();
      float* sums = volume.color.empty() ? nullptr : volume.color.data();
      const Vec3 c = color;
      const std::vector<std::uint32_t>& voxels = current->voxels;
      parallelFor(voxels.size(), threads, 1 << 14, [&](std::size_t begin, std::size_t end) {
        for (std::size_t v = begin; v < end; ++v) {
          const std::uint32_t voxel = voxels[v];
          density[voxel] += 1.0f;
          if (sums)
            for (int d = 0; d < 3; ++d) sums[3 * std::size_t(voxel) + std::size_t(d)] += float(c[d]);
        }
      });
      if (job.partial) job.partial(volume);
    }
    if (job.progress) job.progress(double(k + 1) / settings.iterations);
  }
  normalizeDensity(volume);
  return volume;
}

/// P = hits per voxel, plotted by the chaos kernel. Like the z-buffer plotter, each hit is
/// deferred by kDefer samples after a prefetch of its voxel: the volume is far larger than the
/// caches, so the miss overlaps the next samples' arithmetic instead of stalling the chain.
struct VoxelBins {
  std::uint32_t* counts;
  std::uint64_t* colors;  // 3 per voxel, fixed point (render/accumulation.h), or null
  float half;             // N / 2
  float n;
  std::size_t stride;

  static constexpr unsigned kDefer = 8;
  struct Pending {
    std::size_t voxel = ~std::size_t(0);
    kernel::v4f color{};
  };
  Pending pending[kDefer] = {};
  unsigned next = 0;

  void commit(const Pending& p) {
    std::atomic_ref<std::uint32_t>(counts[p.voxel]).fetch_add(1, std::memory_order_relaxed);
    if (colors) {
      // Integer sums, as the renderer's colour sums: exact in any order, so the volume is the same
      // for any thread count and any split into parts.
      kernel::v4f c = p.color > 0.0f ? p.color : kernel::v4f{};  // NaN → 0
      c = c < 1.0f ? c : kernel::v4f{} + 1.0f;
      const kernel::v4i fixed = __builtin_convertvector(c * 65536.0f + 0.5f, kernel::v4i);
      for (int d = 0; d < 3; ++d)
        std::atomic_ref<std::uint64_t>(colors[3 * p.voxel + std::size_t(d)])
            .fetch_add(std::uint32_t(fixed[d]), std::memory_order_relaxed);
    }
  }

  void flush() {
    for (unsigned k = 0; k < kDefer; ++k) {
      Pending& p = pending[(next + k) % kDefer];
      if (p.voxel != ~std::size_t(0)) commit(p);
      p.voxel = ~std::size_t(0);
    }
  }

  [[gnu::always_inline]] int operator()(kernel::v4f q, kernel::v4f col) {
    const kernel::v4f s = (q + 1.0f) * half;
    if (!(s[0] >= 0.0f && s[0] < n && s[1] >= 0.0f && s[1] < n && s[2] >= 0.0f && s[2] < n)) return 0;  // NaN fails
    const std::size_t v = std::size_t(std::uint32_t(s[0])) +
                          stride * (std::size_t(std::uint32_t(s[1])) + stride * std::size_t(std::uint32_t(s[2])));
    __builtin_prefetch(counts + v, 1);
    if (colors) __builtin_prefetch(colors + 3 * v, 1);
    Pending& slot = pending[next++ % kDefer];
    if (slot.voxel != ~std::size_t(0)) commit(slot);
    slot.voxel = v;
    slot.color = col;
    return 1;
  }
};

GRIDIFS_KERNEL_CLONES void runBins(kernel::ChainState& chain, const kernel::HotIfs& ifs, std::int64_t count,
                                   VoxelBins& bins, kernel::ChainCounters& counters) {
  kernel::runChain(chain, ifs, count, bins, counters);
}

/// The same for a free-form IFS: Thollot et al. 1997, §3.1, λ ← λ·T, binned at P·λ.
GRIDIFS_KERNEL_CLONES void runBarycentricBins(kernel::ChainState& chain, kernel::BarycentricState& bary,
                                              const kernel::HotIfs& ifs, std::int64_t count, VoxelBins& bins,
                                              kernel::ChainCounters& counters) {
  kernel::runBarycentricChain(chain, bary, ifs, count, bins, counters);
}

DensityVolume finishBinning(const VoxelLattice& lattice, const std::vector<std::uint32_t>& counts,
                            std::vector<float> colors) {
  DensityVolume volume{lattice, std::vector<float>(counts.begin(), counts.end()), std::move(colors), 0.0};
  normalizeDensity(volume);
  return volume;
}

}  // namespace

void VoxelAccumulation::add(const VoxelAccumulation& other) {
  if (other.resolution != resolution || other.counts.size() != counts.size() ||
      other.colorSums.size() != colorSums.size())
    throw std::invalid_argument("the voxel accumulations have different resolutions or colours");
  for (std::size_t i = 0; i < counts.size(); ++i) counts[i] += other.counts[i];
  for (std::size_t i = 0; i < colorSums.size(); ++i) colorSums[i] += other.colorSums[i];
  samples += other.samples;
}

VoxelAccumulation accumulateVoxels(const Project& project, const VolumeJob& job) {
  const VolumeSettings& settings = job.settings;
  const VoxelLattice lattice{settings.resolution};
  const auto compiled = compileIfs(project, makeCondensationSampler(project, job.projectFolder));
  std::vector<kernel::HotFunction> hot;
  const kernel::HotIfs ifs = kernel::makeHotIfs(*compiled, hot, settings.skip, limits::kEscapeBound);

  VoxelAccumulation acc;
  acc.resolution = settings.resolution;
  acc.counts.assign(lattice.voxelCount(), 0);
  if (hasColorVolume(project)) acc.colorSums.assign(lattice.voxelCount() * 3, 0);
  // The budget in chunks with their own streams (render/sample_chunks.h), taken by the workers in
  // turn: the counts and the fixed-point colour sums do not depend on who played which chunk.
  const ChunkRange chunks = chunksOf(settings.samples, job.part ? &*job.part : nullptr);
  const std::int64_t budget = rangeSamples(settings.samples, chunks);
  const int threads = resolveThreadCount(job.threads);
  std::atomic<std::int64_t> done{0}, nextChunk{chunks.begin};
  std::vector<std::thread> workers;
  for (int w = 0; w < threads; ++w) {
    workers.emplace_back([&] {
      kernel::DenormalsAreZero daz;
      kernel::ChainCounters counters;
      std::unique_ptr<kernel::BarycentricState> bary;  // free-form IFSs only
      if (ifs.barycentricBlocks) bary = std::make_unique<kernel::BarycentricState>();
      VoxelBins bins{acc.counts.data(), acc.colorSums.empty() ? nullptr : acc.colorSums.data(), 0.5f * float(lattice.n),
                     float(lattice.n), std::size_t(lattice.n)};
      for (std::int64_t c = nextChunk++; c < chunks.end && !cancelled(job); c = nextChunk++) {
        kernel::ChainState chain = kernel::ChainState::start(settings.seed, std::uint64_t(c), ifs.skip);
        const std::int64_t n = chunkSize(settings.samples, c);
        if (bary) {
          bary->start(chain, ifs);
          runBarycentricBins(chain, *bary, ifs, n, bins, counters);
        } else {
          runBins(chain, ifs, n, bins, counters);
        }
        bins.flush();
        done.fetch_add(n, std::memory_order_relaxed);
      }
    });
  }
  if (job.progress) {
    while (done.load(std::memory_order_relaxed) < budget && !cancelled(job)) {
      job.progress(double(done.load(std::memory_order_relaxed)) / double(std::max<std::int64_t>(1, budget)));
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }
  for (std::thread& t : workers) t.join();
  if (job.progress) job.progress(1.0);
  acc.samples = done.load();
  return acc;
}

DensityVolume developVoxels(const Project& project, const VolumeJob& job, const VoxelAccumulation& acc) {
  std::vector<float> colors(acc.colorSums.size());
  for (std::size_t i = 0; i < colors.size(); ++i)
    colors[i] = float(double(acc.colorSums[i]) * (1.0 / kColorFixedScale));
  DensityVolume volume = finishBinning(VoxelLattice{acc.resolution}, acc.counts, std::move(colors));
  if (!cancelled(job)) applyFieldLayers(volume, job.settings, project.time, job.threads);
  return volume;
}

namespace {

DensityVolume binPoints(const Project& project, const VolumeJob& job) {
  if (job.binner) {
    const auto compiled = compileIfs(project, makeCondensationSampler(project, job.projectFolder));
    const VoxelLattice lattice{job.settings.resolution};
    std::vector<std::uint32_t> counts(lattice.voxelCount(), 0);
    std::vector<float> colors;
    if (hasColorVolume(project)) colors.assign(lattice.voxelCount() * 3, 0.0f);
    if (job.binner(*compiled, job, counts, colors)) return finishBinning(lattice, counts, std::move(colors));
  }
  VolumeJob cpu = job;
  cpu.settings.field.reset();  // computeDensityVolume applies the field layers once, after either path
  cpu.settings.more_fields.clear();
  return developVoxels(project, cpu, accumulateVoxels(project, job));
}

}  // namespace

bool usesSetIteration(const Project& project) {
  for (const Function& f : project.functions)
    if (f.kind == FunctionKind::Median && !f.muted && f.weight > 0.0) return true;
  return false;
}

bool hasColorVolume(const Project& project) {
  const Function* first = nullptr;
  for (const Function& f : project.functions) {
    if (f.muted || !(f.weight > 0.0)) continue;
    if (!first)
      first = &f;
    else if (f.color != first->color)
      return true;
  }
  return false;
}

DensityVolume computeDensityVolume(const Project& project, const VolumeJob& job) {
  DensityVolume volume = usesSetIteration(project) ? iterateSets(project, job) : binPoints(project, job);
  if (!cancelled(job)) applyFieldLayers(volume, job.settings, project.time, job.threads);
  return volume;
}

}  // namespace gridifs
