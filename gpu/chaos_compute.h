#pragma once
// The GL side of the GPU chaos game (shaders/chaos_game.comp.glsl): the compiled IFS, the chains
// and the image buffers in shader storage buffers, one dispatch per slice of iterations, and the
// read-back of the buffers. Internal to GpuChaosRenderer and generatePointsGpu; every call must
// run on the thread whose context is current.
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gpu/headless_gl_context.h"
#include "render/chaos_renderer.h"

namespace gridifs::gpu {

/// What a dispatch writes: a projected image (z-buffer, density, flame colour sums), every plotted
/// point (export-points), hits per voxel of a lattice over X (the density volume), or (tests) the
/// images f(p) of given points under given functions (evaluateMaps).
enum class ChaosOutput { Image, Points, Voxels, Maps };

/// The buffers as read back: the raw keys, densities and fixed-point colour sums (Voxels: density
/// and colorSums per voxel, 6 words a voxel).
struct ChaosReadback {
  std::uint64_t generation = 0;
  int width = 0, height = 0;
  bool atomic64 = false;
  float depthMin = 0.0f, depthScale = 0.0f;  // 32-bit keys: depth = depthMin + q / depthScale
  std::vector<std::uint64_t> keys64;
  std::vector<std::uint32_t> keys32;
  std::vector<std::uint32_t> density;
  std::vector<std::uint32_t> colorSums;  // 8 words per pixel (lo, hi per channel)
  std::int64_t samples = 0, bad = 0, plotted = 0;
};

/// How many chains a job runs (a function of the job only, so the image does not depend on the
/// GPU): enough that every chain iterates at least 64·(skip + 1) times, at most 2^18.
std::uint32_t chainCount(const RenderJob& job, bool software);

/// The chains one setup plays: [begin, end) of a job's `total` chains. Chain i (a global index)
/// always has the same seed and budget, whichever range it is played in, so the accumulations
/// of ranges that cover the chains once sum to the whole job's.
struct ChainRange {
  std::uint32_t total = 0, begin = 0, end = 0;
  static ChainRange all(std::uint32_t total) { return ChainRange{total, 0, total}; }
  std::uint32_t size() const { return end > begin ? end - begin : 0; }
};

/// The chains of render part job.part (all of them without one): the GPU's chains stand in for
/// the CPU's chunks, so part K of N plays partChunks(chainCount(job), K, N) — contiguous shares
/// that cover every chain once and differ by at most one chain.
ChainRange chainsOf(const RenderJob& job, bool software);

/// The samples the chains of `chains` play in all (0 without a budget).
std::int64_t chainBudget(const RenderJob& job, ChainRange chains);

class ChaosCompute {
 public:
  /// Compiles the program variant (those for IFSs with flame variations, one per set of
  /// variations used, when setup or evaluateMaps first needs them). Throws GpuUnavailable when the
  /// driver rejects it.
  /// accumulateColor: colour sums (Image: the flame display's; Voxels: rgb per voxel).
  ChaosCompute(const GpuInfo& info, ChaosOutput output, bool accumulateColor, bool allowAtomic64);
  ~ChaosCompute();
  ChaosCompute(const ChaosCompute&) = delete;
  ChaosCompute& operator=(const ChaosCompute&) = delete;

  /// Uploads the IFS, allocates and clears the buffers and seeds the chains in `chains` (each
  /// seeded and budgeted by its index among chains.total). Throws GpuUnavailable when the image
  /// (Voxels: the voxelResolution³ lattice) or the chains do not fit the device's memory.
  void setup(const CompiledIfs& ifs, const RenderJob& job, ChainRange chains, int voxelResolution = 0);
  /// Iterates every chain `iterations` more times (fewer where its budget ends). Does not wait.
  void dispatch(std::uint32_t iterations);
  /// Waits for the dispatched work.
  void finish();
  /// Reads the image buffers and tallies (after finish()).
  void readback(ChaosReadback& out) const;
  /// EMIT_POINTS only: the slots of the last dispatch, xyz valid | rgb 0 for each, iteration-major.
  void readPoints(std::vector<float>& slots, std::uint32_t iterations) const;
  /// Samples done so far (by the range's chains), from the dispatched iteration counts.
  std::int64_t samplesDone() const;
  /// Whether every chain of the range has spent its budget (at once for an empty range).
  bool finished() const;
  /// Maps only (tests): f_{functions[i]}(points[i]) for every i, through the shader's own map
  /// (the grid lookup, extrapolated where the function has variations, then its variation stage),
  /// random variations drawing from stream i under `seed`. Waits for the result.
  std::vector<std::array<float, 3>> evaluateMaps(const CompiledIfs& ifs, const std::vector<std::uint32_t>& functions,
                                                 const std::vector<std::array<float, 3>>& points, std::uint64_t seed);
  /// The chains this setup plays (the range's size).
  std::uint32_t chains() const { return chains_; }
  bool atomic64() const { return atomic64_; }

 private:
  void allocate(unsigned buffer, std::size_t bytes, const std::string& what);
  /// usedVariations: empty for the plain program, else usedVariations(ifs) (gpu/variation_stage.h).
  unsigned buildProgram(const std::string& usedVariations) const;
  /// The program for `ifs`: the plain one, or the one specialised to its variations (built and
  /// kept on first use).
  unsigned programFor(const CompiledIfs& ifs);
  /// Functions, node pairs, the alias table and (with variations) the variation stages.
  void uploadIfs(const CompiledIfs& ifs);
  /// depthMin_ and depthScale_ for the 32-bit keys.
  void depthRange(const CompiledIfs& ifs, const RenderJob& job, const OrbitCamera& camera);
  /// The panoramic projection's and the stereo eyes' uniforms (render/camera.h).
  void setProjectionUniforms(const OrbitCamera& camera);

  GpuInfo info_;
  ChaosOutput output_ = ChaosOutput::Image;
  bool color_ = false, points_ = false, atomic64_ = false;
  int voxels_ = 0;
  unsigned program_ = 0;  // the program of the current setup: plainProgram_ or a variation program
  unsigned plainProgram_ = 0;
  std::map<std::string, unsigned> variationPrograms_;  // by usedVariations(ifs)
  /// One storage buffer per binding of chaos_game.comp.glsl (chaos_compute.cpp's Binding).
  static constexpr int kBufferCount = 11;
  unsigned buffers_[kBufferCount] = {};
  RenderJob job_;
  std::uint32_t chains_ = 0, count_ = 0;
  // Every chain's budget is budgetBase_ (+1 for the first budgetExtra_ of the job's chains);
  // extraHere_ of them lie in this range.
  std::uint64_t budgetBase_ = 0, budgetExtra_ = 0, extraHere_ = 0, issued_ = 0;
  std::size_t pixels_ = 0, pointSlots_ = 0;
  float depthMin_ = 0.0f, depthScale_ = 0.0f;
};

}  // namespace gridifs::gpu
