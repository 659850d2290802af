#pragma once
// The renderer's immutable snapshot of an evaluated IFS (compiled grids as flat float
// arrays). Built once per edit on the UI thread, then shared read-only by all chaos-game workers.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "model/evaluation_cache.h"
#include "model/project.h"
#include "variations/flame_variations.h"

namespace gridifs {

struct BatchedVariations;

/// Two x-neighbouring distorted nodes (i, j, k) and (i+1, j, k), each as x y z 0: one 32-byte
/// aligned load gives both ends of a cell edge, so a trilinear lookup is 4 loads (Gröller & Wegenkittl 1994, §1.3).
struct alignas(32) NodePair {
  float a[4];
  float b[4];
};

/// A function's variation stage (model/function_variations.h): f(p) = post(Σ w_i V_i(g(p))) with g
/// the grid map extrapolated beyond X. Immutable; `terms` point into `params`.
struct CompiledVariations {
  std::vector<VariationTerm> terms;
  std::vector<double> params;               // every term's parameters, in table order, one term after another
  std::vector<int> variationIds;            // each term's index in flameVariations() (the GPU's numbering)
  std::vector<std::uint32_t> paramOffsets;  // where each term's parameters start in `params`
  FlameAffine coefs;                        // the affine fit of g that the dependent variations read
  double post[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
  bool random = false;  // some term draws random numbers
  /// `terms` as the chaos kernel runs them (evaluateKernelVariations), and whether one is a
  /// pre-variation and whether `post` is not the identity (the kernel skips it then).
  std::vector<KernelVariationTerm> kernelTerms;
  bool anyPre = false;
  bool hasPost = false;
  /// A stage of at most kDirectTerms terms without pre-variations and flatten (most flame
  /// xforms): each term's body, called directly in the kernel instead of through the loop and the
  /// switch of evaluateKernelVariations (the same sum, in the same order, with the same draws).
  static constexpr int kDirectTerms = 4;
  KernelBodyFn directBodies[kDirectTerms] = {};
  int directCount = 0;
  CompiledVariations() = default;
  CompiledVariations(const CompiledVariations&) = delete;  // terms point into params
  CompiledVariations& operator=(const CompiledVariations&) = delete;

  /// The variation stage applied to the grid's image q = g(p); draws from `random` when a term is random.
  std::array<double, 3> apply(std::array<double, 3> q, std::uint64_t& random) const;
  /// The same as the chaos kernel evaluates it (evaluateKernelVariations: the same draws, sin, cos
  /// and atan2 within 1e-9 relative), in float as the kernel keeps its points.
  [[gnu::always_inline]] std::array<float, 3> applyKernel(float x, float y, float z, std::uint64_t& random) const {
    FlamePoint s;
    if (directCount > 0) {
      // evaluateKernelVariations's sum, from 0 (so -0 becomes +0 as there), term by term.
      VariationInput in{x, y, z, &coefs, nullptr, &random};
      for (int i = 0; i < directCount; ++i) {
        const KernelVariationTerm& t = kernelTerms[std::size_t(i)];
        in.param = t.params;
        const FlamePoint q = directBodies[i](in, t.weight);
        s.x += q.x;
        s.y += q.y;
        s.z += t.writesZ ? q.z : t.weight * in.z;
      }
    } else {
      s = evaluateKernelVariations(kernelTerms.data(), kernelTerms.size(), anyPre, {x, y, z}, coefs, &random);
    }
    if (!hasPost) return {float(s.x), float(s.y), float(s.z)};
    std::array<float, 3> out{};
    for (int r = 0; r < 3; ++r) out[r] = float(post[r][0] * s.x + post[r][1] * s.y + post[r][2] * s.z + post[r][3]);
    return out;
  }
};

/// One function of the snapshot. Immutable after compileIfs; thread-safe to read.
struct CompiledFunction {
  Index3 resolution{2, 2, 2};
  /// pairs[(i) + pairStrideJ·j + pairStrideK·k] for i in [0, Ni-2], j in [0, Nj-1], k in [0, Nk-1].
  std::vector<NodePair> pairs;
  std::uint32_t pairStrideJ = 1, pairStrideK = 1;
  /// Lattice coordinate s_d = (p_d + 1) · toLattice[d]; the cell is min(floor(s_d), maxCell[d]).
  float toLattice[4] = {0.5f, 0.5f, 0.5f, 0.0f};
  float maxCell[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  /// r g b and the palette index c_i (Draves & Reckase 2003, §5), mixed into the running color with colorSpeed.
  float color[4] = {1.0f, 1.0f, 1.0f, 0.0f};
  float colorSpeed = 0.5f;
  double weight = 1.0;
  /// The largest |coordinate| of the grid's nodes as stored (float): the grid map of a clamped
  /// point blends nodes with weights in [0, 1], so its image stays within this.
  float nodeMagnitude = 0.0f;
  /// Whether the grid's map is affine (every node within 1e-6·(1 + |node|) of the map through the
  /// origin corner and its three neighbouring corners, as every imported flame xform's is): then a
  /// function with variations evaluates its extrapolated grid map as that affine map, q = c1 +
  /// cx·x + cy·y + cz·z (columns, lane 3 zero), instead of a cell's lookup and seven lerps.
  bool affine = false;
  float affineColumns[4][4] = {};
  /// Index in Project::functions (or SIZE_MAX for the final function).
  std::size_t sourceIndex = 0;
  /// A matrix function of a free-form IFS (Thollot et al. 1997, §3.1; `pairs` is then empty): m
  /// rows of CompiledIfs::barycentricStride() floats, row i = T_i0 … T_i(pad−1) (zero past m),
  /// then (T·P)_i as x y z 0 (P the control points) and 4 zeros, so one pass over the rows gives
  /// both λ·T and the plotted point P·(λ·T).
  std::vector<float> matrix;
  /// A constant condensation function (Sokolov & Gentil, §3.1; `pairs` is then empty): uniform
  /// random samples of its set as x y z 0, of which the chaos game picks one at random.
  std::vector<float> points;

  /// The variation stage, or null when f = g.
  std::shared_ptr<const CompiledVariations> variations;

  /// Reference (scalar) evaluation, identical in result to the renderer's inner loop:
  /// clamp p to X (NaN → -1), locate the cell, interpolate trilinearly in float.
  std::array<float, 3> evaluate(std::array<float, 3> p) const;
  /// The grid map extrapolated beyond X from its border cells (functions with variations), in the
  /// kernel's float operations.
  std::array<float, 3> evaluateExtrapolated(std::array<float, 3> p) const;
  /// The whole map f, as the kernel runs it: with variations, the extrapolated grid map then the
  /// variation stage (drawing from `random`); without, evaluate().
  std::array<float, 3> evaluateMap(std::array<float, 3> p, std::uint64_t& random) const;
};

/// Walker's alias method: one 64-bit random number picks a function by weight in O(1).
struct AliasEntry {
  std::uint32_t threshold;  // keep the column when the low 32 random bits are < threshold
  std::uint32_t alias;      // otherwise take this function
};

/// One entry of the chaos kernel's transition walk: an alias entry of transitionAlias plus the
/// offsets (in entries) of the rows that pick the function after each of its two outcomes, so a
/// Markov step picks the function and its next row with one load and no multiply.
struct TransitionStep {
  std::uint32_t threshold;  // as AliasEntry
  std::uint32_t alias;
  std::uint32_t keepRow;   // the row after this entry's own column
  std::uint32_t aliasRow;  // the row after `alias`
};

/// Flags on TransitionStep::keepRow and aliasRow for an IFS matrix with states
/// (freeform/state_expansion.h): the function moves the point without plotting it (its word does not
/// start in an initial state), or plots its image of the point and leaves the chain as it was (its
/// word can go no further). The row offset is the rest of the bits.
/// While a chain skips its first points it stays inside one strongly connected part with a cycle
/// (rows flagged kTransitionSkipPhase, the first n + 1 rows), so that the point it starts plotting
/// from lies on a tail every infinite word can end with; then it moves to the rows after
/// CompiledIfs::stateRowsOffset.
inline constexpr std::uint32_t kTransitionHidden = 1u << 31;
inline constexpr std::uint32_t kTransitionPeek = 1u << 30;
inline constexpr std::uint32_t kTransitionSkipPhase = 1u << 29;
inline constexpr std::uint32_t kTransitionFlags = kTransitionHidden | kTransitionPeek | kTransitionSkipPhase;
inline constexpr std::uint32_t kTransitionRowMask = kTransitionSkipPhase - 1;

/// The whole snapshot. Immutable; share it as shared_ptr<const CompiledIfs> across threads.
struct CompiledIfs {
  std::vector<CompiledFunction> functions;  // unmuted functions with weight > 0, in project order
  std::optional<CompiledFunction> finalFunction;
  std::vector<AliasEntry> alias;      // one entry per function
  std::vector<double> probabilities;  // normalised weights (for tests and the UI)
  /// The transition matrix as (n + 1) alias tables of n entries each (n = functions.size()):
  /// row r < n picks the function after function r, row n the first function of a chain (the
  /// usual weights). Empty when the project has no matrix (the unrestricted chaos game).
  std::vector<AliasEntry> transitionAlias;
  /// transitionAlias as the kernel walks it: row 0 picks a chain's first function, row i + 1 the
  /// function after function i (offset (i + 1)·n); empty without a matrix. With states, `functions`
  /// are the virtual functions of freeform/state_expansion.h and the row offsets carry their flags.
  std::vector<TransitionStep> transitionWalk;
  /// With transitions whose graph is not strongly connected, a chain never leaves the closed part
  /// it falls into (a union's half, a concatenation's second IFS) and never revisits transient
  /// parts. Restarting each chain after this many steps samples every part as the first-function
  /// weights say, whatever the number of chains; 0 (strongly connected, or no matrix): never.
  std::uint32_t restartInterval = 0;
  /// With states: transitionWalk holds 2(n + 1) rows, the skip phase's then the plotting ones, and
  /// this is the offset between a function's two rows; 0 without states.
  std::uint32_t stateRowsOffset = 0;
  /// Free-form IFS: m barycentric coordinates (0 for a grid IFS), padded to a multiple of 8.
  std::uint32_t barycentricSize = 0, barycentricPad = 0;
  std::uint32_t barycentricStride() const { return barycentricPad + 8; }
  /// Whether some function (or the final one) has a variation stage.
  bool hasVariations = false;
  /// The functions' variation stages for four chains at once (render/batched_variations.h), when
  /// every function has one the batch can run; else null and each chain runs its own.
  std::shared_ptr<const BatchedVariations> batchedVariations;

  /// Maps a 64-bit random number to a function index by weight: the high 32 bits pick the
  /// column, the low 32 bits decide between it and its alias.
  std::uint32_t choose(std::uint64_t random) const {
    const std::uint32_t column =
        std::uint32_t((std::uint64_t(std::uint32_t(random >> 32)) * std::uint64_t(alias.size())) >> 32);
    const AliasEntry& e = alias[column];
    return std::uint32_t(random) < e.threshold ? column : e.alias;
  }
};

/// Packs an evaluated grid (distorted and placed) for the renderer. Throws ModelError when a
/// node is not finite.
CompiledFunction compileFunction(const Function& function, const Grid& evaluated, std::size_t sourceIndex);

/// Packs a matrix function of a free-form project (see CompiledFunction::matrix); `pad` is the
/// padded size (a multiple of 8, at least m). Throws ModelError when an entry is not finite.
CompiledFunction compileMatrixFunction(const Function& function, const FreeFormSpace& space, std::uint32_t pad,
                                       std::size_t sourceIndex);

/// What a function does to X, for the IFS view: its map f (with its variations and post map) at
/// `samples` points along each of lines × lines lattice lines per axis of X. Random variations
/// draw from a fixed stream, so the cloud they make is the same every time. Non-finite and far
/// (beyond 1e6) images are left out. Throws ModelError as compileFunction.
std::vector<Vec3> functionImageSamples(const Function& function, const Grid& evaluated, int lines = 9,
                                       int samples = 48);

/// Builds the alias table for `weights` (all ≥ 0, at least one > 0). Exposed for tests.
std::vector<AliasEntry> buildAliasTable(const std::vector<double>& weights);

/// Samples of the set of condensation function `functionIndex` (Project::functions), uniform over
/// its volume or surface. compileIfs samples primitive sets itself; a sampler is needed for sets
/// read from files (volume/condensation_sampler.h makes one).
using CondensationSampler = std::function<std::vector<Vec3>(std::size_t functionIndex)>;

/// Compiles `project` reading evaluated grids through `evaluation` (the Document's cache). Call on
/// the thread that owns the cache. Throws ModelError (with a JSON path) when a stack fails to evaluate or when no
/// unmuted function has a positive weight.
std::shared_ptr<const CompiledIfs> compileIfs(const Project& project, const EvaluationCache& evaluation,
                                              const CondensationSampler& sampler = {});

/// The same from a bare project (evaluates every stack; no cache). Thread-safe for distinct
/// projects. Throws ModelError as above.
std::shared_ptr<const CompiledIfs> compileIfs(const Project& project, const CondensationSampler& sampler = {});

}  // namespace gridifs
