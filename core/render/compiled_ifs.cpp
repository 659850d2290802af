#include "render/compiled_ifs.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <string>

#include "base/hash.h"
#include "freeform/bezier_lattice.h"
#include "freeform/state_expansion.h"
#include "freeform/transition_matrix.h"
#include "model/grid_affine_fit.h"
#include "model/stack_evaluator.h"
#include "render/batched_variations.h"

namespace gridifs {
namespace {

float clampToX(float v) {
  // NaN → -1, like Grid::evaluate (points outside X are clamped to X first).
  v = v > -1.0f ? v : -1.0f;
  return v < 1.0f ? v : 1.0f;
}

void compileColor(const Function& function, CompiledFunction& out) {
  for (int d = 0; d < 3; ++d) out.color[d] = float(std::clamp(function.color[d], 0.0, 1.0));
  out.color[3] = float(std::clamp(function.palette_index, 0.0, 1.0));
  out.colorSpeed = float(std::clamp(function.color_speed, 0.0, 1.0));
  out.weight = function.weight;
}

/// Steps between restarts of a chain on a graph that is not strongly connected: long enough that
/// the skipped first steps cost 2%, short enough that a render's millions of restarts sample each
/// part of the attractor in proportion.
constexpr std::uint32_t kRestartInterval = 1024;
/// The same for an IFS matrix with states, whose chains often end in one fixed point after their
/// last transient step: short, so the transient parts are drawn often.
constexpr std::uint32_t kStateRestartInterval = 128;

std::shared_ptr<const CompiledVariations> compileVariations(const Function& function, const Grid& evaluated);

/// The padded barycentric size of the kernel's blocks: 8, 16, 32 or 64 floats.
std::uint32_t barycentricPadFor(std::size_t m) {
  std::uint32_t pad = 8;
  while (pad < m) pad *= 2;
  return pad;
}

}  // namespace

namespace {

/// Sets CompiledFunction::affine and affineColumns from the evaluated grid (see there).
void compileAffineMap(const Grid& evaluated, CompiledFunction& out) {
  const Index3 n = evaluated.resolution();
  if (n[0] < 2 || n[1] < 2 || n[2] < 2) return;
  const Vec3 origin = evaluated.node(0, 0, 0);
  // q(p) = origin + Σ_d (p_d + 1)/2 · edge_d, edge_d from the origin to the far corner along d.
  const Vec3 edge[3] = {evaluated.node(n[0] - 1, 0, 0) - origin, evaluated.node(0, n[1] - 1, 0) - origin,
                        evaluated.node(0, 0, n[2] - 1) - origin};
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const double u[3] = {double(i) / double(n[0] - 1), double(j) / double(n[1] - 1), double(k) / double(n[2] - 1)};
        const Vec3 node = evaluated.node(i, j, k);
        const Vec3 predicted = origin + u[0] * edge[0] + u[1] * edge[1] + u[2] * edge[2];
        for (int d = 0; d < 3; ++d)
          if (!(std::abs(node[d] - predicted[d]) <= 1e-6 * (1.0 + std::abs(node[d])))) return;
      }
  // In X coordinates: q = origin + Σ_d edge_d/2 + Σ_d p_d · edge_d/2.
  for (int d = 0; d < 3; ++d) {
    for (int r = 0; r < 3; ++r) out.affineColumns[d][r] = float(0.5 * edge[d][r]);
    out.affineColumns[3][d] = float(origin[d] + 0.5 * (edge[0][d] + edge[1][d] + edge[2][d]));
  }
  out.affine = true;
}

}  // namespace

CompiledFunction compileFunction(const Function& function, const Grid& evaluated, std::size_t sourceIndex) {
  if (!allFinite(evaluated)) throw ModelError("", "the evaluated grid has non-finite nodes");
  const Index3 n = evaluated.resolution();
  CompiledFunction out;
  out.resolution = n;
  out.pairStrideJ = std::uint32_t(n[0] - 1);
  out.pairStrideK = std::uint32_t(n[0] - 1) * std::uint32_t(n[1]);
  out.pairs.resize(std::size_t(n[0] - 1) * n[1] * n[2]);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i + 1 < n[0]; ++i) {
        NodePair& pair =
            out.pairs[std::size_t(i) + out.pairStrideJ * std::size_t(j) + out.pairStrideK * std::size_t(k)];
        const Vec3 a = evaluated.node(i, j, k), b = evaluated.node(i + 1, j, k);
        for (int d = 0; d < 3; ++d) {
          pair.a[d] = float(a[d]);
          pair.b[d] = float(b[d]);
          // A double beyond float's range is infinite here, and fails every bound.
          out.nodeMagnitude = std::max({out.nodeMagnitude, std::fabs(pair.a[d]), std::fabs(pair.b[d])});
        }
        pair.a[3] = pair.b[3] = 0.0f;
      }
  for (int d = 0; d < 3; ++d) {
    out.toLattice[d] = 0.5f * float(n[d] - 1);
    out.maxCell[d] = float(n[d] - 2);
  }
  compileColor(function, out);
  out.sourceIndex = sourceIndex;
  if (function.hasVariationStage()) {
    out.variations = compileVariations(function, evaluated);
    compileAffineMap(evaluated, out);
  }
  return out;
}

namespace {

std::shared_ptr<const CompiledVariations> compileVariations(const Function& function, const Grid& evaluated) {
  auto out = std::make_shared<CompiledVariations>();
  std::vector<std::pair<const FlameVariation*, double>> chosen;
  for (const auto& [name, weight] : function.variations) {
    const int id = flameVariationIndex(name);
    if (id < 0) throw ModelError("variations." + name, "\"" + name + "\" is not a flame variation");
    if (weight == 0.0) continue;
    const FlameVariation& v = flameVariations()[std::size_t(id)];
    out->variationIds.push_back(id);
    out->paramOffsets.push_back(std::uint32_t(out->params.size()));
    for (const auto& [attribute, fallback] : v.params) {
      const auto it = function.variation_params.find(attribute);
      out->params.push_back(it == function.variation_params.end() ? fallback : it->second);
    }
    chosen.emplace_back(&v, weight);
    out->random |= v.random;
  }
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    out->terms.push_back({chosen[i].first, chosen[i].second, out->params.data() + out->paramOffsets[i]});
    out->kernelTerms.push_back(makeKernelVariationTerm(out->terms.back()));
    out->anyPre |= chosen[i].first->pre;
  }
  const bool direct = out->kernelTerms.size() <= std::size_t(CompiledVariations::kDirectTerms) &&
                      std::none_of(out->kernelTerms.begin(), out->kernelTerms.end(),
                                   [](const KernelVariationTerm& t) { return t.pre || t.flatten; });
  if (direct)
    for (const KernelVariationTerm& t : out->kernelTerms)
      out->directBodies[out->directCount++] = kernelVariationBody(t.body);
  double fitError = 0.0;  // a distorted grid's dependent variations read its closest affine map
  out->coefs = fitAffine(evaluated, fitError);
  if (function.post) {
    const auto m = function.post->affine();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) {
        out->post[r][c] = m[std::size_t(r)][std::size_t(c)];
        out->hasPost |= out->post[r][c] != (r == c ? 1.0 : 0.0);
      }
  }
  return out;
}

}  // namespace

CompiledFunction compileMatrixFunction(const Function& function, const FreeFormSpace& space, std::uint32_t pad,
                                       std::size_t sourceIndex) {
  const std::size_t m = space.control_points.size();
  if (function.matrix.size() != m || m > pad)
    throw ModelError("matrix", "the matrix does not match the control points");
  CompiledFunction out;
  const std::size_t stride = std::size_t(pad) + 8;
  out.matrix.assign(m * stride, 0.0f);
  for (std::size_t i = 0; i < m; ++i) {
    if (function.matrix[i].size() != m) throw ModelError("matrix", "the matrix does not match the control points");
    Vec3 tp{0.0};
    for (std::size_t j = 0; j < m; ++j) {
      const double t = function.matrix[i][j];
      if (!std::isfinite(t)) throw ModelError("matrix", "the matrix has non-finite entries");
      out.matrix[i * stride + j] = float(t);
      tp += t * space.control_points[j];
    }
    for (int d = 0; d < 3; ++d) out.matrix[i * stride + pad + std::size_t(d)] = float(tp[d]);
  }
  compileColor(function, out);
  out.sourceIndex = sourceIndex;
  return out;
}

namespace {

/// The lattice cell and the position in it. `extrapolate`: p is not clamped to X, the cell is
/// clamped to the lattice and the position may lie outside [0, 1] (the border cell continued).
void locateCell(const CompiledFunction& fn, std::array<float, 3> p, bool extrapolate, int cell[3], float f[3]) {
  for (int d = 0; d < 3; ++d) {
    const float s = ((extrapolate ? p[d] : clampToX(p[d])) + 1.0f) * fn.toLattice[d];
    float c = std::min(float(int(s)), fn.maxCell[d]);
    if (extrapolate) c = c > 0.0f ? c : 0.0f;  // NaN → 0, as the kernel's maxps
    cell[d] = int(c);
    f[d] = s - c;
  }
}

/// The trilinear interpolation in cell `cell` at position `f`, in the kernel's float operations:
/// along y, then z, then x (the node pairs hold both x ends of an edge).
std::array<float, 3> interpolateCell(const CompiledFunction& fn, const int cell[3], const float f[3]) {
  const std::size_t idx =
      std::size_t(cell[0]) + fn.pairStrideJ * std::size_t(cell[1]) + fn.pairStrideK * std::size_t(cell[2]);
  const NodePair& p00 = fn.pairs[idx];
  const NodePair& p10 = fn.pairs[idx + fn.pairStrideJ];
  const NodePair& p01 = fn.pairs[idx + fn.pairStrideK];
  const NodePair& p11 = fn.pairs[idx + fn.pairStrideJ + fn.pairStrideK];
  std::array<float, 3> out{};
  for (int d = 0; d < 3; ++d) {
    const float a0 = p00.a[d] + (p10.a[d] - p00.a[d]) * f[1];
    const float b0 = p00.b[d] + (p10.b[d] - p00.b[d]) * f[1];
    const float a1 = p01.a[d] + (p11.a[d] - p01.a[d]) * f[1];
    const float b1 = p01.b[d] + (p11.b[d] - p01.b[d]) * f[1];
    const float a = a0 + (a1 - a0) * f[2];
    const float b = b0 + (b1 - b0) * f[2];
    out[d] = a + (b - a) * f[0];
  }
  return out;
}

}  // namespace

std::array<float, 3> CompiledFunction::evaluateExtrapolated(std::array<float, 3> p) const {
  if (affine) {
    // The kernel's float operations (chaos_kernel.h applyExtrapolated), lane by lane.
    std::array<float, 3> out{};
    for (int d = 0; d < 3; ++d)
      out[d] =
          affineColumns[0][d] * p[0] + affineColumns[1][d] * p[1] + affineColumns[2][d] * p[2] + affineColumns[3][d];
    return out;
  }
  float f[3];
  int cell[3];
  locateCell(*this, p, true, cell, f);
  return interpolateCell(*this, cell, f);
}

std::array<double, 3> CompiledVariations::apply(std::array<double, 3> q, std::uint64_t& random) const {
  const FlamePoint sum = evaluateVariations(terms.data(), terms.size(), {q[0], q[1], q[2]}, coefs, &random);
  std::array<double, 3> out{};
  for (int r = 0; r < 3; ++r) out[r] = post[r][0] * sum.x + post[r][1] * sum.y + post[r][2] * sum.z + post[r][3];
  return out;
}

std::array<float, 3> CompiledFunction::evaluateMap(std::array<float, 3> p, std::uint64_t& random) const {
  if (!variations) return evaluate(p);
  const std::array<float, 3> q = evaluateExtrapolated(p);
  return variations->applyKernel(q[0], q[1], q[2], random);
}

std::array<float, 3> CompiledFunction::evaluate(std::array<float, 3> p) const {
  // Must perform exactly the float operations of the renderer's kernel (chaos_kernel.h).
  float f[3];
  int cell[3];
  locateCell(*this, p, false, cell, f);
  return interpolateCell(*this, cell, f);
}

std::vector<Vec3> functionImageSamples(const Function& function, const Grid& evaluated, int lines, int samples) {
  const CompiledFunction compiled = compileFunction(function, evaluated, 0);
  std::uint64_t random = 0x243F6A8885A308D3ull;
  std::vector<Vec3> out;
  out.reserve(std::size_t(3 * lines * lines * samples));
  auto at = [](int i, int n) { return n <= 1 ? 0.0f : -1.0f + 2.0f * float(i) / float(n - 1); };
  for (int axis = 0; axis < 3; ++axis)
    for (int a = 0; a < lines; ++a)
      for (int b = 0; b < lines; ++b)
        for (int s = 0; s < samples; ++s) {
          std::array<float, 3> u{};
          u[std::size_t(axis)] = at(s, samples);
          u[std::size_t((axis + 1) % 3)] = at(a, lines);
          u[std::size_t((axis + 2) % 3)] = at(b, lines);
          const std::array<float, 3> q = compiled.evaluateMap(u, random);
          const Vec3 p(q[0], q[1], q[2]);
          if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && glm::length(p) < 1e6) out.push_back(p);
        }
  return out;
}

std::vector<AliasEntry> buildAliasTable(const std::vector<double>& weights) {
  // Vose's stable variant of Walker's alias method; thresholds in units of 2^-32.
  const std::size_t n = weights.size();
  std::vector<AliasEntry> table(n);
  double total = 0.0;
  for (double w : weights) total += std::max(0.0, w);
  if (n == 0 || !(total > 0.0)) throw ModelError("functions", "no unmuted function has a positive weight");
  std::vector<double> scaled(n);
  std::vector<std::uint32_t> small, large;
  for (std::size_t i = 0; i < n; ++i) {
    scaled[i] = std::max(0.0, weights[i]) * double(n) / total;
    (scaled[i] < 1.0 ? small : large).push_back(std::uint32_t(i));
  }
  while (!small.empty() && !large.empty()) {
    const std::uint32_t s = small.back(), l = large.back();
    small.pop_back();
    table[s] = {std::uint32_t(std::min(4294967295.0, std::floor(scaled[s] * 4294967296.0))), l};
    scaled[l] = (scaled[l] + scaled[s]) - 1.0;
    if (scaled[l] < 1.0) {
      large.pop_back();
      small.push_back(l);
    }
  }
  // Leftovers are 1 up to rounding: always keep their own column.
  for (std::uint32_t i : large) table[i] = {0xFFFFFFFFu, i};
  for (std::uint32_t i : small) table[i] = {0xFFFFFFFFu, i};
  return table;
}

namespace {

/// Samples in the condensation table: enough that the chaos game's picks look continuous.
constexpr std::size_t kCondensationSamples = 1 << 16;

CompiledFunction compileCondensationFunction(const Function& f, const CondensationSampler& sampler, std::size_t index) {
  std::vector<Vec3> samples;
  if (f.set.shape == SetShape::Mesh || f.set.shape == SetShape::Vdb || f.set.shape == SetShape::Image) {
    if (!sampler) throw ModelError("set", "a set read from a file needs its project folder to be sampled");
    samples = sampler(index);
  } else {
    samples = samplePrimitive(f.set, kCondensationSamples, splitmix64(index + 1));
  }
  if (samples.empty()) throw ModelError("set", "the set is empty");
  CompiledFunction c;
  c.sourceIndex = index;
  c.weight = f.weight;
  for (int d = 0; d < 3; ++d) c.color[d] = float(f.color[d]);
  c.color[3] = float(f.palette_index);
  c.colorSpeed = float(f.color_speed);
  c.points.reserve(samples.size() * 4);
  for (const Vec3& p : samples) c.points.insert(c.points.end(), {float(p.x), float(p.y), float(p.z), 0.0f});
  return c;
}

/// The kernel's transition walk from one row of relative weights per function (`rows`, the
/// first-function row being ifs.alias).
void buildTransitionWalk(CompiledIfs& ifs, const std::vector<std::vector<double>>& rows) {
  for (const auto& row : rows) {
    const auto table = buildAliasTable(row);
    ifs.transitionAlias.insert(ifs.transitionAlias.end(), table.begin(), table.end());
  }
  ifs.transitionAlias.insert(ifs.transitionAlias.end(), ifs.alias.begin(), ifs.alias.end());
  const std::size_t n = ifs.functions.size();
  auto rowAfter = [n](std::uint32_t function) { return std::uint32_t((std::size_t(function) + 1) * n); };
  for (std::size_t row = 0; row <= n; ++row) {
    const std::size_t source = row == 0 ? n : row - 1;  // the first-function row is last in transitionAlias
    for (std::size_t c = 0; c < n; ++c) {
      const AliasEntry& e = ifs.transitionAlias[source * n + c];
      ifs.transitionWalk.push_back({e.threshold, e.alias, rowAfter(std::uint32_t(c)), rowAfter(e.alias)});
    }
  }
}

/// An IFS matrix with states: the compiled functions become its virtual functions
/// (freeform/state_expansion.h), each a copy of its function, and `weights` theirs. The walk has the
/// skip phase's rows 0 … n (inside strongly connected parts) then the plotting rows n + 1 … 2n + 1.
void compileStates(const Project& project, CompiledIfs& ifs, std::vector<double>& weights) {
  std::vector<std::size_t> present, position;
  for (const CompiledFunction& f : ifs.functions) present.push_back(f.sourceIndex);
  const StateExpansion x = expandStatesOver(project, present, position);
  std::vector<CompiledFunction> virtualFunctions;
  weights.clear();
  for (std::size_t v = 0; v < position.size(); ++v) {
    virtualFunctions.push_back(ifs.functions[position[v]]);
    weights.push_back(project.functions[x.function[v]].weight);
  }
  ifs.functions = std::move(virtualFunctions);
  ifs.alias = buildAliasTable(weights);
  const std::size_t n = x.function.size();
  auto rowOf = [&](std::size_t v, bool skipPhase) {
    std::vector<double> row(n, 0.0);
    bool any = false;
    for (std::size_t w = 0; w < n; ++w)
      if (x.follows[v][w] && (!skipPhase || x.internal[w])) row[w] = weights[w], any = true;
    return any ? row : weights;  // a peek's row is never read
  };
  std::vector<double> firstSkip(n, 0.0);
  for (std::size_t w = 0; w < n; ++w) firstSkip[w] = x.internal[w] ? weights[w] : 0.0;
  std::vector<std::vector<double>> rows{firstSkip};
  for (std::size_t v = 0; v < n; ++v) rows.push_back(rowOf(v, true));
  rows.push_back(weights);
  for (std::size_t v = 0; v < n; ++v) rows.push_back(rowOf(v, false));
  ifs.stateRowsOffset = std::uint32_t((n + 1) * n);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const auto table = buildAliasTable(rows[r]);
    ifs.transitionAlias.insert(ifs.transitionAlias.end(), table.begin(), table.end());
    const bool skipPhase = r <= n;
    const std::uint32_t base = skipPhase ? 0 : ifs.stateRowsOffset;
    auto rowAfter = [&](std::uint32_t c) {
      const std::uint32_t offset = std::uint32_t((std::size_t(c) + 1) * n) + base;
      if (skipPhase) return offset | kTransitionSkipPhase;
      if (x.step[c] == StateStep::Peek) return std::uint32_t(r * n) | kTransitionPeek;
      return x.step[c] == StateStep::Hidden ? offset | kTransitionHidden : offset;
    };
    for (std::size_t c = 0; c < n; ++c)
      ifs.transitionWalk.push_back(
          {table[c].threshold, table[c].alias, rowAfter(std::uint32_t(c)), rowAfter(table[c].alias)});
  }
  // Chains pass through the transient parts once: restart them often, each from a tail inside a
  // strongly connected part (the skip phase), so every part is drawn.
  ifs.restartInterval = kStateRestartInterval;
}

std::shared_ptr<const CompiledIfs> compileWith(const Project& project,
                                               const std::function<std::shared_ptr<const Grid>(std::size_t)>& gridOf,
                                               const std::function<std::shared_ptr<const Grid>()>& finalGrid,
                                               const CondensationSampler& sampler) {
  auto ifs = std::make_shared<CompiledIfs>();
  if (project.space) {
    ifs->barycentricSize = std::uint32_t(project.space->control_points.size());
    ifs->barycentricPad = barycentricPadFor(ifs->barycentricSize);
  }
  std::vector<double> weights;
  for (std::size_t i = 0; i < project.functions.size(); ++i) {
    const Function& f = project.functions[i];
    if (f.muted || !(f.weight > 0.0)) continue;
    const std::string path = "functions[" + std::to_string(i) + "]";
    try {
      if (f.kind == FunctionKind::Median)
        throw ModelError("kind",
                         "a median function maps sets, not points: compute its density volume (gridifs volume)");
      if (f.kind == FunctionKind::Condensation) {
        ifs->functions.push_back(compileCondensationFunction(f, sampler, i));
        weights.push_back(f.weight);
        continue;
      }
      if (f.kind == FunctionKind::Matrix) {
        if (!project.space) throw ModelError("kind", "a \"matrix\" function needs control points");
        ifs->functions.push_back(compileMatrixFunction(f, *project.space, ifs->barycentricPad, i));
        weights.push_back(f.weight);
        continue;
      }
      ifs->functions.push_back(compileFunction(f, *gridOf(i), i));
    } catch (const ModelError& e) {
      throw e.under(path);
    }
    weights.push_back(f.weight);
  }
  if (project.states) {
    compileStates(project, *ifs, weights);
  } else {
    ifs->alias = buildAliasTable(weights);
    std::vector<std::size_t> active;
    for (const CompiledFunction& f : ifs->functions) active.push_back(f.sourceIndex);
    const auto rows = activeTransitionWeights(project, active);
    if (!rows.empty()) {
      buildTransitionWalk(*ifs, rows);
      if (transitionComponents(project).size() > 1) ifs->restartInterval = kRestartInterval;
    }
  }
  double total = 0.0;
  for (double w : weights) total += w;
  for (double w : weights) ifs->probabilities.push_back(w / total);
  if (project.final_function && !project.final_function->muted) {
    try {
      auto grid = finalGrid();
      // The kernel interpolates trilinearly: a Bézier lattice goes in sampled (bezier_lattice.h).
      if (project.final_function->interpolation == LatticeInterpolation::Bezier) grid = sampleBezierLattice(*grid);
      ifs->finalFunction = compileFunction(*project.final_function, *grid, std::size_t(-1));
    } catch (const ModelError& e) {
      throw e.under("final");
    }
  }
  for (const CompiledFunction& f : ifs->functions) ifs->hasVariations |= f.variations != nullptr;
  if (ifs->finalFunction) ifs->hasVariations |= ifs->finalFunction->variations != nullptr;
  if (ifs->hasVariations) ifs->batchedVariations = batchVariations(*ifs);
  return ifs;
}

}  // namespace

std::shared_ptr<const CompiledIfs> compileIfs(const Project& project, const EvaluationCache& evaluation,
                                              const CondensationSampler& sampler) {
  return compileWith(
      project, [&](std::size_t i) { return evaluation.function(project, i); },
      [&] { return evaluation.finalFunction(project); }, sampler);
}

std::shared_ptr<const CompiledIfs> compileIfs(const Project& project, const CondensationSampler& sampler) {
  return compileWith(
      project,
      [&](std::size_t i) {
        return evaluateFunctionAt(project.functions[i], "functions[" + std::to_string(i) + "]", project.time);
      },
      [&] { return evaluateFunctionAt(*project.final_function, "final", project.time); }, sampler);
}

}  // namespace gridifs
