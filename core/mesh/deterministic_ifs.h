#pragma once
// The deterministic algorithm (Gröller & Wegenkittl 1994, §3.2): Ã ≈ F^n(A), where F(A) = ∪_i f_i(A) is the
// Hutchinson operator of the IFS. Applied to a base mesh A it gives the union of N^n transformed
// copies of A — a mesh that ray tracers and DCC tools (Blender, MeshLab) can light and shade.
//
// Typical use (GUI: steps 1–2 on the UI thread, 3 on a worker; CLI: all on one thread):
//   1. DeterministicIfs ifs = snapshotDeterministicIfs(document.project(), document.evaluation());
//   2. DeterministicPlan plan = planDeterministic(ifs, spec, options);   // counts, budget warning
//   3. DeterministicMesh out = runDeterministic(ifs, spec, options, progress, &cancelFlag);
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "mesh/base_mesh.h"
#include "mesh/ifs_mesh.h"
#include "model/evaluation_cache.h"
#include "model/project.h"

namespace gridifs {

/// One function of the snapshot: its evaluated (distorted and placed) grid and its color.
struct DeterministicMap {
  std::shared_ptr<const Grid> grid;
  Vec3 color{1.0};
  double colorSpeed = 0.5;
  std::size_t functionIndex = 0;  // index in Project::functions
};

/// A condensation function (Barnsley's constant map onto a set C, Sokolov & Gentil, §3.1): with it
/// the deterministic algorithm is A_n = C ∪ F(A_{n−1}), and C enters as its surface mesh (the
/// boundary of a solid set is its surface, so `fill` does not change it).
struct DeterministicCondensation {
  /// C's surface in X; null until loadCondensationMeshes (volume/condensation_mesh.h) fills it.
  std::shared_ptr<const IfsMesh> mesh;
  Vec3 color{1.0};
  std::size_t functionIndex = 0;  // index in Project::functions
};

/// An immutable snapshot of the IFS: safe to share with a worker thread while the Document
/// keeps changing. `maps` are the unmuted functions with weight > 0 in project order — the
/// functions the chaos game can pick, so the mesh shows the attractor the preview shows.
struct DeterministicIfs {
  std::vector<DeterministicMap> maps;
  /// The unmuted condensation functions with weight > 0, in project order (address digits
  /// maps.size() + j). Median functions have no mesh meaning and are refused by the snapshot.
  std::vector<DeterministicCondensation> condensations;
  std::shared_ptr<const Grid> finalGrid;  // applied once to every vertex at the end; may be null
  /// The transition matrix over `maps`: follows[a][b] when map b may be applied right after map a
  /// (Thollot et al. §3.2: only the allowed words are built). Empty: every word.
  std::vector<std::vector<char>> follows;
  /// With an IFS matrix with states (freeform/state_expansion.h, the maps being its virtual
  /// functions): last[b] when map b may be applied last, i.e. its word starts in an initial state.
  /// Empty: every map.
  std::vector<char> last;
  /// Whether the word applying maps digit[0], digit[1], … in that order is allowed.
  bool allows(std::size_t previous, std::size_t next) const { return follows.empty() || follows[previous][next]; }
  bool mayBeLast(std::size_t map) const { return last.empty() || last[map]; }
};

/// Reads evaluated grids through `evaluation` (the Document's cache): call on the thread that
/// owns it. Throws ModelError (with a JSON path) when a stack fails to evaluate.
DeterministicIfs snapshotDeterministicIfs(const Project& project, const EvaluationCache& evaluation);
/// The same from a bare project (evaluates every stack). Thread-safe for distinct projects.
DeterministicIfs snapshotDeterministicIfs(const Project& project);

inline constexpr int kMaxDeterministicDepth = 256;

struct DeterministicLimits {
  /// Above this estimated memory of the result, plans are flagged overBudget (warn the user).
  std::uint64_t memoryBudgetBytes = std::uint64_t(2) << 30;
  /// Above this many faces, plans are flagged overLimit and building refuses (ModelError).
  std::uint64_t maxFaces = 50'000'000;
};

struct DeterministicOptions {
  int depth = 3;    // n in F^n(A), 0..kMaxDeterministicDepth
  int threads = 0;  // 0: std::thread::hardware_concurrency(); the result never depends on it
  DeterministicLimits limits;
};

/// What a run will produce, known before anything big is allocated.
struct DeterministicPlan {
  std::size_t functionCount = 0;  // N
  int depth = 0;
  std::uint64_t copies = 0;  // allowed words of length depth (N^depth unrestricted), saturated
  MeshCounts base;           // one copy of the (refined) base mesh
  /// With condensation functions: copies of each C, Σ_{k<depth} N^k (f_w(C) for every word w
  /// shorter than the depth), and all of their faces together.
  std::uint64_t condensationCopies = 0;
  MeshCounts condensation;
  /// copies × base + the condensation copies, saturated: |A_n| = |C| + N·|A_{n−1}|, |A_0| = |base|.
  MeshCounts total;
  double approximateFaces = 0.0;  // the same in floating point, for messages about absurd depths
  std::uint64_t estimatedBytes = 0;
  bool overBudget = false;  // estimatedBytes > limits.memoryBudgetBytes: warn
  bool overLimit = false;   // beyond limits.maxFaces or OpenMesh's 32-bit handles: refuse
  /// One sentence: why the plan is over the limit or budget ("" when neither).
  std::string message;
};

/// Counts for N^depth copies of a base with `base` counts and the condensation copies. Throws
/// ModelError when the depth is outside 0..kMaxDeterministicDepth, `ifs` has no maps, or a
/// condensation mesh is not loaded. Pure; thread-safe.
DeterministicPlan planDeterministic(const DeterministicIfs& ifs, const MeshCounts& base,
                                    const DeterministicOptions& options);
/// The same for a base spec: loads the coarse base (reads the file) and predicts its refined
/// counts without building it. Throws ModelError as loadCoarseBase does.
DeterministicPlan planDeterministic(const DeterministicIfs& ifs, const BaseMeshSpec& spec,
                                    const DeterministicOptions& options);

/// F^n(A). Note: IfsMesh (OpenMesh) has no move constructor — std::move copies it — so build a
/// large result where it will live (a local initialised from the call, or the overloads below
/// that fill a caller-owned object, e.g. one made with std::make_shared on a worker thread).
/// Vertex colors (float RGBA in [0, 1], alpha 1) hold each copy's structural color; the face property
/// `address` (see ifs_mesh.h) holds its address code. Copy c occupies vertices [c·V, (c+1)·V)
/// and faces [c·F, (c+1)·F) with the base's topology (copies are not welded together).
/// With condensation functions (T = N + M digits, M condensations) the copies of the base come
/// first, then for each level k = 0 … n−1 and each condensation j the N^k copies f_w(C_j); the
/// address of f_{a1}∘…∘f_{ak}(C_j) is the length-n base-T word a1 … ak (N+j) … (N+j) (the
/// constant map ignores what follows it), so decodeAddress(code, T, n) reads every copy.
struct DeterministicMesh {
  IfsMesh mesh;
  DeterministicPlan plan;
  /// digit → index in Project::functions, to decode addresses (decodeAddress in ifs_mesh.h);
  /// the grid maps' digits first, then the condensations'.
  std::vector<std::size_t> functionIndices;
};

/// Called on the calling thread with the fraction done in [0, 1], a few dozen times per run;
/// returning false cancels.
using DeterministicProgress = std::function<bool(double fraction)>;

/// Thrown when a run is cancelled by its progress callback or cancel flag.
struct DeterministicCancelled : std::runtime_error {
  DeterministicCancelled() : std::runtime_error("mesh export cancelled") {}
};

/// Builds F^n(base) for a refined base (contiguous handles, at least one face; see
/// refineBase). Vertex positions are computed by composing the functions copy by copy with
/// shared prefixes (each level's images are reused by the N copies below it), in parallel over
/// `options.threads`; the output's connectivity is the base's, replicated with offsets into
/// arrays sized once. Colors: a copy f_{a1}∘…∘f_{an}(A) gets c = color(a_n), then for
/// k = n−1 … 1, c = mix(c, color(a_k), colorSpeed(a_k)) — the chaos game's blend in the order
/// the functions are applied; depth 0 gives white. The final function changes positions only.
/// Throws ModelError when the plan is over the limit (plan.message), DeterministicCancelled
/// when cancelled (`cancel` may be null; it is polled by all workers). Thread-safe for
/// distinct outputs; `ifs` and `base` are only read.
DeterministicMesh buildDeterministicMesh(const DeterministicIfs& ifs, const IfsMesh& base,
                                         const DeterministicOptions& options,
                                         const DeterministicProgress& progress = {},
                                         const std::atomic<bool>* cancel = nullptr);

/// The same, building into `out` (its previous content is discarded).
void buildDeterministicMesh(const DeterministicIfs& ifs, const IfsMesh& base, const DeterministicOptions& options,
                            DeterministicMesh& out, const DeterministicProgress& progress = {},
                            const std::atomic<bool>* cancel = nullptr);

/// loadCoarseBase → predictBaseCounts → planDeterministic (refuses over the limit before
/// subdividing) → refineBase → buildDeterministicMesh. Throws as those do.
DeterministicMesh runDeterministic(const DeterministicIfs& ifs, const BaseMeshSpec& spec,
                                   const DeterministicOptions& options, const DeterministicProgress& progress = {},
                                   const std::atomic<bool>* cancel = nullptr);
/// The same, building into `out`.
void runDeterministic(const DeterministicIfs& ifs, const BaseMeshSpec& spec, const DeterministicOptions& options,
                      DeterministicMesh& out, const DeterministicProgress& progress = {},
                      const std::atomic<bool>* cancel = nullptr);

}  // namespace gridifs
