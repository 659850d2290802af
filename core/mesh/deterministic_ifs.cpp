#include "mesh/deterministic_ifs.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <limits>

#include "base/parallel.h"
#include "base/text_format.h"
#include "freeform/bezier_lattice.h"
#include "freeform/state_expansion.h"
#include "freeform/transition_matrix.h"
#include "model/stack_evaluator.h"

namespace gridifs {
namespace {

constexpr std::uint64_t kSaturated = std::numeric_limits<std::uint64_t>::max();
std::uint64_t mul(std::uint64_t a, std::uint64_t b) { return a != 0 && b > kSaturated / a ? kSaturated : a * b; }
std::uint64_t add(std::uint64_t a, std::uint64_t b) { return a > kSaturated - b ? kSaturated : a + b; }

// Memory of one element of the output IfsMesh (ArrayKernel): a vertex holds its point, color
// and outgoing halfedge; an edge two halfedges of (face, to-vertex, next, prev); a face its
// halfedge and its address.
constexpr std::uint64_t kBytesPerVertex = sizeof(IfsMesh::Point) + sizeof(IfsMesh::Color) + sizeof(int);
constexpr std::uint64_t kBytesPerEdge = 2 * 4 * sizeof(int);
constexpr std::uint64_t kBytesPerFace = 2 * sizeof(int);

template <class GridOf, class FinalOf>
DeterministicIfs snapshotWith(const Project& project, GridOf gridOf, FinalOf finalOf) {
  if (project.space)
    throw ModelError("space",
                     "the deterministic algorithm does not build free-form (control point) IFSs yet; "
                     "their chaos-game points export with export-points");
  DeterministicIfs ifs;
  for (std::size_t i = 0; i < project.functions.size(); ++i) {
    const Function& f = project.functions[i];
    if (f.muted || !(f.weight > 0.0)) continue;
    if (f.kind == FunctionKind::Median)
      throw ModelError("functions[" + std::to_string(i) + "].kind",
                       "a median function maps voxel sets, not meshes, so the deterministic algorithm cannot "
                       "build it; its density volume exports with the volume verb");
    if (f.kind == FunctionKind::Condensation) {
      ifs.condensations.push_back({nullptr, f.color, i});
      continue;
    }
    auto grid = gridOf(i);
    if (!allFinite(*grid)) throw ModelError("functions[" + std::to_string(i) + "]", "a grid node is not finite");
    ifs.maps.push_back({std::move(grid), f.color, f.color_speed, i});
  }
  std::vector<std::size_t> active;
  for (const auto& map : ifs.maps) active.push_back(map.functionIndex);
  const auto rows = activeTransitionWeights(project, active);
  if (!rows.empty() && !ifs.condensations.empty())
    throw ModelError("functions[" + std::to_string(ifs.condensations.front().functionIndex) + "].kind",
                     "the deterministic algorithm does not build condensation functions together with a "
                     "transition matrix; their chaos-game points export with export-points");
  if (ifs.maps.empty() && !ifs.condensations.empty())
    throw ModelError("functions",
                     "the IFS has only condensation functions, so A_n is their sets alone; add a "
                     "function that maps the sets");
  for (const auto& row : rows) {
    ifs.follows.emplace_back();
    for (double w : row) ifs.follows.back().push_back(w > 0.0 ? 1 : 0);
  }
  if (project.states) {
    if (!ifs.condensations.empty())
      throw ModelError("functions[" + std::to_string(ifs.condensations.front().functionIndex) + "].kind",
                       "the deterministic algorithm does not build condensation functions together with states; "
                       "their chaos-game points export with export-points");
    // The maps become the virtual functions of the states, each a copy of its function's map.
    std::vector<std::size_t> present, position;
    for (const DeterministicMap& m : ifs.maps) present.push_back(m.functionIndex);
    const StateExpansion x = expandStatesOver(project, present, position);
    std::vector<DeterministicMap> maps;
    for (std::size_t k : position) maps.push_back(ifs.maps[k]);
    ifs.maps = std::move(maps);
    ifs.follows = x.follows;
    for (StateStep step : x.step) ifs.last.push_back(step != StateStep::Hidden);
  }
  if (project.final_function && !project.final_function->muted) {
    ifs.finalGrid = finalOf();
    if (project.final_function->interpolation == LatticeInterpolation::Bezier) {
      try {
        ifs.finalGrid = sampleBezierLattice(*ifs.finalGrid);
      } catch (const ModelError& e) {
        throw e.under("final");
      }
    }
    if (!allFinite(*ifs.finalGrid)) throw ModelError("final", "a grid node is not finite");
  }
  return ifs;
}

std::string faceCountText(const DeterministicPlan& plan) {
  if (plan.total.faces != kSaturated) return withThousands(plan.total.faces);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "about %.3g", plan.approximateFaces);
  return buffer;
}

std::string gibText(std::uint64_t bytes) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.1f GiB", double(bytes) / double(std::uint64_t(1) << 30));
  return buffer;
}

Vec3 toVec3(const IfsMesh::Point& p) { return {p[0], p[1], p[2]}; }

// Reports progress on the caller's thread at most every 1% and polls the cancel flag.
class ProgressGate {
 public:
  ProgressGate(const DeterministicProgress& progress, const std::atomic<bool>* cancel, std::atomic<bool>& stop)
      : progress_(progress), cancel_(cancel), stop_(stop) {}
  void operator()(double fraction) {
    if (cancel_ && cancel_->load(std::memory_order_relaxed)) stop_ = true;
    if (!progress_ || stop_) return;
    fraction = std::clamp(fraction, 0.0, 1.0);
    if (fraction < last_ + 0.01 && fraction < 1.0) return;
    last_ = fraction;
    if (!progress_(fraction)) stop_ = true;
  }

 private:
  const DeterministicProgress& progress_;
  const std::atomic<bool>* cancel_;
  std::atomic<bool>& stop_;
  double last_ = -1.0;
};

}  // namespace

DeterministicIfs snapshotDeterministicIfs(const Project& project, const EvaluationCache& evaluation) {
  return snapshotWith(
      project, [&](std::size_t i) { return evaluation.function(project, i); },
      [&] { return evaluation.finalFunction(project); });
}

DeterministicIfs snapshotDeterministicIfs(const Project& project) {
  return snapshotWith(
      project,
      [&](std::size_t i) {
        return evaluateFunctionAt(project.functions[i], "functions[" + std::to_string(i) + "]", project.time);
      },
      [&] { return evaluateFunctionAt(*project.final_function, "final", project.time); });
}

DeterministicPlan planDeterministic(const DeterministicIfs& ifs, const MeshCounts& base,
                                    const DeterministicOptions& options) {
  if (options.depth < 0 || options.depth > kMaxDeterministicDepth)
    throw ModelError("depth", "the depth must be between 0 and " + std::to_string(kMaxDeterministicDepth) + ", not " +
                                  std::to_string(options.depth));
  if (ifs.maps.empty())
    throw ModelError("functions", "the IFS has no unmuted function with a positive weight, so F^n(A) is empty");
  DeterministicPlan plan;
  plan.functionCount = ifs.maps.size();
  plan.depth = options.depth;
  plan.base = base;
  plan.copies = 1;
  if (ifs.follows.empty()) {
    for (int k = 0; k < options.depth; ++k) plan.copies = mul(plan.copies, plan.functionCount);
  } else if (options.depth > 0) {
    // words[b]: allowed words of the current length ending with map b.
    std::vector<std::uint64_t> words(plan.functionCount, 1), next(plan.functionCount);
    for (int k = 1; k < options.depth; ++k) {
      for (std::size_t b = 0; b < plan.functionCount; ++b) {
        next[b] = 0;
        for (std::size_t a = 0; a < plan.functionCount; ++a)
          if (ifs.follows[a][b]) next[b] = add(next[b], words[a]);
      }
      words.swap(next);
    }
    plan.copies = 0;
    for (std::size_t b = 0; b < words.size(); ++b)
      if (ifs.mayBeLast(b)) plan.copies = add(plan.copies, words[b]);
  }
  plan.total = {mul(plan.copies, base.vertices), mul(plan.copies, base.edges), mul(plan.copies, base.faces),
                mul(plan.copies, base.corners)};
  plan.approximateFaces =
      ifs.follows.empty() || plan.copies != kSaturated
          ? (ifs.follows.empty() ? std::pow(double(plan.functionCount), double(options.depth)) : double(plan.copies)) *
                double(base.faces)
          : std::pow(double(plan.functionCount), double(options.depth)) * double(base.faces);
  if (!ifs.condensations.empty()) {
    // A_n = C ∪ F(A_{n−1}) unrolled: F^n(A_0) ∪ ⋃_{k<n} F^k(C), N^k copies of C at level k.
    MeshCounts sets;
    for (std::size_t j = 0; j < ifs.condensations.size(); ++j) {
      const DeterministicCondensation& c = ifs.condensations[j];
      if (!c.mesh)
        throw ModelError("functions[" + std::to_string(c.functionIndex) + "].set",
                         "the condensation set's mesh was not loaded");
      const MeshCounts m = countMesh(*c.mesh);
      sets = {add(sets.vertices, m.vertices), add(sets.edges, m.edges), add(sets.faces, m.faces),
              add(sets.corners, m.corners)};
    }
    std::uint64_t power = 1;
    double approximateCopies = 0.0;
    for (int k = 0; k < options.depth; ++k) {
      plan.condensationCopies = add(plan.condensationCopies, power);
      approximateCopies += std::pow(double(plan.functionCount), double(k));
      power = mul(power, plan.functionCount);
    }
    const std::uint64_t copies = plan.condensationCopies;
    plan.condensation = {mul(copies, sets.vertices), mul(copies, sets.edges), mul(copies, sets.faces),
                         mul(copies, sets.corners)};
    plan.total = {add(plan.total.vertices, plan.condensation.vertices), add(plan.total.edges, plan.condensation.edges),
                  add(plan.total.faces, plan.condensation.faces), add(plan.total.corners, plan.condensation.corners)};
    plan.approximateFaces += approximateCopies * double(sets.faces);
  }
  plan.estimatedBytes = add(add(mul(plan.total.vertices, kBytesPerVertex), mul(plan.total.edges, kBytesPerEdge)),
                            mul(plan.total.faces, kBytesPerFace));
  const std::string what = "F^" + std::to_string(options.depth) + "(A) with " + std::to_string(plan.functionCount) +
                           " function" + (plan.functionCount == 1 ? "" : "s") + " would have " + faceCountText(plan) +
                           " faces";
  // OpenMesh addresses elements with int handles; halfedges are the largest count.
  const std::uint64_t handleLimit = std::uint64_t(INT_MAX);
  if (plan.total.faces > options.limits.maxFaces || plan.total.vertices > handleLimit ||
      mul(2, plan.total.edges) > handleLimit) {
    plan.overLimit = true;
    plan.message = what + ", more than the limit of " + withThousands(options.limits.maxFaces) +
                   "; lower the depth or the subdivision";
  } else if (plan.estimatedBytes > options.limits.memoryBudgetBytes) {
    plan.overBudget = true;
    plan.message = what + " and need about " + gibText(plan.estimatedBytes) + " of memory (budget " +
                   gibText(options.limits.memoryBudgetBytes) + ")";
  }
  return plan;
}

DeterministicPlan planDeterministic(const DeterministicIfs& ifs, const BaseMeshSpec& spec,
                                    const DeterministicOptions& options) {
  const IfsMesh coarse = loadCoarseBase(spec);
  return planDeterministic(ifs, predictBaseCounts(coarse, spec), options);
}

DeterministicMesh buildDeterministicMesh(const DeterministicIfs& ifs, const IfsMesh& base,
                                         const DeterministicOptions& options, const DeterministicProgress& progress,
                                         const std::atomic<bool>* cancel) {
  DeterministicMesh result;
  buildDeterministicMesh(ifs, base, options, result, progress, cancel);
  return result;  // NRVO: no copy of the mesh
}

namespace {

/// One block of the output: the `copies` words of length `depth` applied to `base`, at element
/// offsets (vertices, edges, faces) of the output. The base part of F^n(A), or F^k(C_j).
struct MeshPart {
  const IfsMesh* base = nullptr;
  int depth = 0;
  std::size_t copies = 0;
  std::size_t vertexOffset = 0, edgeOffset = 0, faceOffset = 0;
  /// Condensation parts: the digit of C_j in the output's addresses and C_j's colour, the first
  /// one of the chaos game's blend (the point jumps into C, then the maps are applied).
  bool condensation = false;
  std::size_t condensationDigit = 0;
  Vec3 color{1.0};
};

/// The output address of a part's copy with local code `code` (base N, `part.depth` digits, the
/// first-applied least significant): the base-T word of length n described in the header.
std::uint64_t outputAddress(const MeshPart& part, std::uint64_t code, std::uint64_t N, std::uint64_t T, int n) {
  if (T == N && !part.condensation) return code;
  std::uint64_t out = 0, scale = 1;
  for (int j = 0; j < part.depth; ++j) {  // re-encode the k digits in base T
    out = add(out, mul(code % N, scale));
    code /= N;
    scale = mul(scale, T);
  }
  if (!part.condensation) return out;
  // Digits a1 … ak are the most significant: shift them above the n − k condensation digits.
  std::uint64_t tail = 0, shift = 1;
  for (int j = part.depth; j < n; ++j) {
    tail = add(tail, mul(part.condensationDigit, shift));
    shift = mul(shift, T);
  }
  return add(mul(out, shift), tail);
}

}  // namespace

void buildDeterministicMesh(const DeterministicIfs& ifs, const IfsMesh& base, const DeterministicOptions& options,
                            DeterministicMesh& result, const DeterministicProgress& progress,
                            const std::atomic<bool>* cancel) {
  result.mesh = IfsMesh();  // cheap: copies an empty mesh (drops any old `address` property)
  result.functionIndices.clear();
  result.plan = planDeterministic(ifs, countMesh(base), options);
  if (result.plan.overLimit) throw ModelError("depth", result.plan.message);
  if (base.n_faces() == 0) throw ModelError("base", "the base mesh has no faces");
  for (const auto& map : ifs.maps) result.functionIndices.push_back(map.functionIndex);
  for (const auto& c : ifs.condensations) result.functionIndices.push_back(c.functionIndex);

  const std::size_t N = ifs.maps.size();
  const std::size_t T = N + ifs.condensations.size();  // address digits
  const int n = options.depth;
  // With a transition matrix only the allowed words are built; codes[c] is copy c's address code
  // (ascending), so copies stay sorted by address as in the unrestricted case.
  // viable[r][d]: after map d, r more maps can be applied ending with one that may be last
  // (always, without states: every row of a transition matrix allows some map).
  std::vector<std::vector<char>> viable(std::size_t(std::max(n, 0)) + 1, std::vector<char>(N, 1));
  if (!ifs.last.empty()) {
    for (std::size_t d = 0; d < N; ++d) viable[0][d] = ifs.mayBeLast(d);
    for (std::size_t r = 1; r < viable.size(); ++r)
      for (std::size_t d = 0; d < N; ++d) {
        char any = 0;
        for (std::size_t e = 0; e < N && !any; ++e) any = ifs.allows(d, e) && viable[r - 1][e];
        viable[r][d] = any;
      }
  }
  std::vector<std::uint64_t> codes;
  if (!ifs.follows.empty()) {
    std::uint64_t span = 1;
    for (int k = 0; k < n; ++k) span = mul(span, N);
    if (span >= (std::uint64_t(1) << 62))
      throw ModelError("depth", "the depth is too large for address codes with a transition matrix");
    codes.reserve(std::size_t(result.plan.copies));
    std::function<void(int, std::size_t, std::uint64_t, std::uint64_t)> walk =
        [&](int j, std::size_t previous, std::uint64_t code, std::uint64_t scale) {
          if (j > n) {
            codes.push_back(code);
            return;
          }
          for (std::size_t d = 0; d < N; ++d)
            if ((j == 1 || ifs.allows(previous, d)) && viable[std::size_t(n - j)][d])
              walk(j + 1, d, code + d * scale, scale * N);
        };
    walk(1, 0, 0, 1);
    std::sort(codes.begin(), codes.end());
  }
  auto slotOf = [&](std::uint64_t code) {
    return codes.empty() ? std::size_t(code)
                         : std::size_t(std::lower_bound(codes.begin(), codes.end(), code) - codes.begin());
  };
  const int threads = resolveThreadCount(options.threads);

  // The parts: F^n(base), then F^k(C_j) for k = 0 … n−1 and each j.
  std::vector<MeshPart> parts;
  parts.push_back({&base, n, std::size_t(result.plan.copies), 0, 0, 0, false, 0, Vec3(1.0)});
  std::size_t vertices = parts[0].copies * base.n_vertices(), edges = parts[0].copies * base.n_edges(),
              faces = parts[0].copies * base.n_faces();
  std::size_t power = 1;  // N^k
  for (int k = 0; k < n; ++k, power *= N) {
    for (std::size_t j = 0; j < ifs.condensations.size(); ++j) {
      const IfsMesh& c = *ifs.condensations[j].mesh;
      parts.push_back({&c, k, power, vertices, edges, faces, true, N + j, ifs.condensations[j].color});
      vertices += power * c.n_vertices();
      edges += power * c.n_edges();
      faces += power * c.n_faces();
    }
  }

  IfsMesh& out = result.mesh;
  OpenMesh::FPropHandleT<int> address;
  out.add_property(address, kAddressPropertyName);
  out.property(address).set_persistent(true);
  // One allocation per array: every element (and property) of all copies exists from here on.
  out.resize(vertices, edges, faces);

  std::atomic<bool> stop{false};
  ProgressGate report(progress, cancel, stop);
  // Workers poll both the internal stop (progress said no, or a worker failed) and the cancel flag.
  auto halted = [&] {
    if (cancel && cancel->load(std::memory_order_relaxed)) stop.store(true, std::memory_order_relaxed);
    return stop.load(std::memory_order_relaxed);
  };
  // Weights of the two passes in the progress bar, from their measured share of the time.
  constexpr double kPositionsShare = 0.75;
  const double totalWork = double(vertices);
  double workBefore = 0.0;  // output vertices of the parts already built (the progress measure)

  for (const MeshPart& part : parts) {
    const IfsMesh& partBase = *part.base;
    const int depth = part.depth;
    const std::size_t V = partBase.n_vertices(), E = partBase.n_edges(), F = partBase.n_faces(), H = 2 * E;
    const std::size_t copies = part.copies;
    const double partWork = double(copies) * double(V);
    // Only the base part can have a transition matrix (the snapshot refuses condensations with one).
    auto partSlot = [&](std::uint64_t code) { return part.condensation ? std::size_t(code) : slotOf(code); };

    // Pass 1: positions. A task is a block of base vertices × a prefix of the first-applied
    // functions; inside it, an odometer walks the remaining digits, recomputing only the levels
    // whose digit changed (shared prefixes: about N/(N−1) evaluations per output vertex).
    {
      constexpr std::size_t kBlock = 2048;
      const std::size_t blocks = (V + kBlock - 1) / kBlock;
      int fixedLevels = 0;  // digits fixed per task (the first-applied ones)
      std::size_t prefixes = 1;
      while (fixedLevels < depth && blocks * prefixes < 64) {
        ++fixedLevels;
        prefixes *= N;
      }
      std::vector<IfsMesh::Point> basePoints(partBase.points(), partBase.points() + V);
      std::atomic<std::uint64_t> done{0};
      parallelForEach(
          blocks * prefixes, threads,
          [&](std::size_t t) {
            if (halted()) return;
            const std::size_t block = t % blocks, prefix = t / blocks;
            const std::size_t v0 = block * kBlock, count = std::min(kBlock, V - v0);
            // levels[j] holds the block after the first j functions (j = 0: the base).
            std::vector<std::vector<Vec3>> levels(std::size_t(std::max(depth, 1)), std::vector<Vec3>(count));
            for (std::size_t v = 0; v < count; ++v) levels[0][v] = toVec3(basePoints[v0 + v]);
            std::vector<std::size_t> digit(std::size_t(depth) + 1, 0);  // digit[j]: function applied at step j
            std::size_t rest = prefix;
            for (int j = 1; j <= fixedLevels; ++j) {
              digit[std::size_t(j)] = rest % N;
              rest /= N;
              if (j > 1 && !ifs.allows(digit[std::size_t(j - 1)], digit[std::size_t(j)])) return;  // forbidden
              if (!viable[std::size_t(depth - j)][digit[std::size_t(j)]]) return;  // no allowed word goes on
            }
            // The smallest digit ≥ from that may be applied at step j after step j − 1 (N: none).
            auto firstAllowed = [&](int j, std::size_t from) {
              for (std::size_t d = from; d < N; ++d)
                if ((j == 1 || ifs.allows(digit[std::size_t(j - 1)], d)) && viable[std::size_t(depth - j)][d]) return d;
              return N;
            };
            for (int j = fixedLevels + 1; j <= depth; ++j) digit[std::size_t(j)] = firstAllowed(j, 0);
            auto applyLevel = [&](int j) {  // levels[j] = f_digit[j](levels[j-1]), 1 ≤ j < depth
              const Grid& g = *ifs.maps[digit[std::size_t(j)]].grid;
              const auto& in = levels[std::size_t(j - 1)];
              auto& o = levels[std::size_t(j)];
              for (std::size_t v = 0; v < count; ++v) o[v] = g.evaluate(in[v]);
            };
            for (int j = 1; j < std::min(fixedLevels + 1, depth); ++j) applyLevel(j);
            int changed = fixedLevels + 1;
            while (true) {
              if (halted()) return;
              for (int j = changed; j < depth; ++j) applyLevel(j);
              std::size_t code = 0;
              for (int j = depth; j >= 1; --j) code = code * N + digit[std::size_t(j)];
              IfsMesh::Point* dst =
                  &out.point(IfsMesh::VertexHandle(int(part.vertexOffset + partSlot(code) * V + v0)));  // contiguous
              const auto& in = levels[std::size_t(std::max(depth - 1, 0))];
              const Grid* last = depth > 0 ? ifs.maps[digit[std::size_t(depth)]].grid.get() : nullptr;
              const Grid* final = ifs.finalGrid.get();
              for (std::size_t v = 0; v < count; ++v) {
                Vec3 p = last ? last->evaluate(in[v]) : in[v];
                if (final) p = final->evaluate(p);
                dst[v] = IfsMesh::Point(float(p.x), float(p.y), float(p.z));
              }
              done.fetch_add(count, std::memory_order_relaxed);
              // Odometer over the free digits fixedLevels+1 … depth, the last-applied one fastest,
              // stepping only through allowed words (every row of the matrix allows some digit).
              int j = depth;
              while (j > fixedLevels) {
                const std::size_t d = firstAllowed(j, digit[std::size_t(j)] + 1);
                if (d < N) {
                  digit[std::size_t(j)] = d;
                  break;
                }
                --j;
              }
              if (j <= fixedLevels) return;
              for (int k = j + 1; k <= depth; ++k) digit[std::size_t(k)] = firstAllowed(k, 0);
              changed = j;
            }
          },
          [&] { report((workBefore + kPositionsShare * double(done.load())) / totalWork); });
    }
    if (stop) throw DeterministicCancelled();

    // Pass 2: connectivity, colors and addresses. Copy c is the base with handles offset by
    // (c·V, c·H, c·F) after the part's offsets; colors depend on the address only.
    {
      std::vector<int> toVertex(H), nextHalfedge(H), faceOf(H), vertexHalfedge(V), faceHalfedge(F);
      for (std::size_t h = 0; h < H; ++h) {
        const IfsMesh::HalfedgeHandle hh{int(h)};
        toVertex[h] = partBase.to_vertex_handle(hh).idx();
        nextHalfedge[h] = partBase.next_halfedge_handle(hh).idx();
        faceOf[h] = partBase.face_handle(hh).idx();
      }
      for (std::size_t v = 0; v < V; ++v)
        vertexHalfedge[v] = partBase.halfedge_handle(IfsMesh::VertexHandle{int(v)}).idx();
      for (std::size_t f = 0; f < F; ++f) faceHalfedge[f] = partBase.halfedge_handle(IfsMesh::FaceHandle{int(f)}).idx();
      auto shifted = [](int handle, std::size_t offset) { return handle < 0 ? -1 : int(std::size_t(handle) + offset); };

      const std::size_t perCopy = V + H + F;
      const std::size_t copiesPerTask = std::max<std::size_t>(1, (std::size_t(1) << 16) / perCopy);
      const std::size_t taskCount = (copies + copiesPerTask - 1) / copiesPerTask;
      std::atomic<std::uint64_t> done{0};
      parallelForEach(
          taskCount, threads,
          [&](std::size_t t) {
            const std::size_t c0 = t * copiesPerTask, c1 = std::min(copies, c0 + copiesPerTask);
            for (std::size_t c = c0; c < c1; ++c) {
              if (halted()) return;
              const std::size_t vOff = part.vertexOffset + c * V, hOff = 2 * part.edgeOffset + c * H,
                                fOff = part.faceOffset + c * F;
              for (std::size_t h = 0; h < H; ++h) {
                const IfsMesh::HalfedgeHandle hh{int(hOff + h)};
                out.set_vertex_handle(hh, IfsMesh::VertexHandle(shifted(toVertex[h], vOff)));
                out.set_next_halfedge_handle(hh, IfsMesh::HalfedgeHandle(shifted(nextHalfedge[h], hOff)));
                out.set_face_handle(hh, IfsMesh::FaceHandle(shifted(faceOf[h], fOff)));
              }
              // The chaos game's structural color: blend in the order the functions are applied,
              // starting from C's color for a condensation copy.
              Vec3 color = part.condensation ? part.color : Vec3(1.0);
              const std::uint64_t code = part.condensation || codes.empty() ? c : codes[c];
              std::uint64_t rest = code;
              for (int j = 1; j <= depth; ++j) {
                const DeterministicMap& map = ifs.maps[rest % N];
                rest /= N;
                color = j == 1 && !part.condensation ? map.color : color + (map.color - color) * map.colorSpeed;
              }
              const IfsMesh::Color rgb(float(std::clamp(color.x, 0.0, 1.0)), float(std::clamp(color.y, 0.0, 1.0)),
                                       float(std::clamp(color.z, 0.0, 1.0)), 1.0f);
              for (std::size_t v = 0; v < V; ++v) {
                const IfsMesh::VertexHandle vh{int(vOff + v)};
                out.set_halfedge_handle(vh, IfsMesh::HalfedgeHandle(shifted(vertexHalfedge[v], hOff)));
                out.set_color(vh, rgb);
              }
              const std::uint64_t a = outputAddress(part, code, N, T, n);
              for (std::size_t f = 0; f < F; ++f) {
                const IfsMesh::FaceHandle fh{int(fOff + f)};
                out.set_halfedge_handle(fh, IfsMesh::HalfedgeHandle(shifted(faceHalfedge[f], hOff)));
                out.property(address, fh) = a <= std::uint64_t(INT_MAX) ? int(a) : -1;
              }
            }
            done.fetch_add(c1 - c0, std::memory_order_relaxed);
          },
          [&] {
            report(
                (workBefore + kPositionsShare * partWork + (1.0 - kPositionsShare) * double(done.load()) * double(V)) /
                totalWork);
          });
    }
    if (stop) throw DeterministicCancelled();
    workBefore += partWork;
  }
  report(1.0);
}

DeterministicMesh runDeterministic(const DeterministicIfs& ifs, const BaseMeshSpec& spec,
                                   const DeterministicOptions& options, const DeterministicProgress& progress,
                                   const std::atomic<bool>* cancel) {
  IfsMesh coarse = loadCoarseBase(spec);
  const DeterministicPlan plan = planDeterministic(ifs, predictBaseCounts(coarse, spec), options);
  if (plan.overLimit) throw ModelError("depth", plan.message);
  const IfsMesh base = refineBase(std::move(coarse), spec);
  return buildDeterministicMesh(ifs, base, options, progress, cancel);
}

void runDeterministic(const DeterministicIfs& ifs, const BaseMeshSpec& spec, const DeterministicOptions& options,
                      DeterministicMesh& out, const DeterministicProgress& progress, const std::atomic<bool>* cancel) {
  IfsMesh coarse = loadCoarseBase(spec);
  const DeterministicPlan plan = planDeterministic(ifs, predictBaseCounts(coarse, spec), options);
  if (plan.overLimit) throw ModelError("depth", plan.message);
  const IfsMesh base = refineBase(std::move(coarse), spec);
  buildDeterministicMesh(ifs, base, options, out, progress, cancel);
}

}  // namespace gridifs
