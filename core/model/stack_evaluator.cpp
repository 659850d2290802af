#include "model/stack_evaluator.h"

#include <algorithm>
#include <cmath>

#include "model/calculator.h"

namespace gridifs {
namespace {

double profileValue(Profile profile, double k, double omega, double t) {
  switch (profile) {
    case Profile::Linear:
      return k * t;
    case Profile::Sine:
      return k * std::sin(omega * t);
    case Profile::PingPong:
      return k * triangleWave(omega * t);
  }
  return 0.0;
}

/// sin(x)/x, smooth through 0 (keeps bend well-defined as k → 0).
double sinc(double x) {
  if (std::abs(x) < 1e-4) return 1.0 - x * x / 6.0;
  return std::sin(x) / x;
}

struct OpContext {
  std::vector<Vec3>& nodes;
  const std::vector<unsigned char>& mask;
  const Vec3 center;
  const double time;  // the project's current time (field ops, the calculator's t)
};

template <class F>
void forSelected(OpContext& ctx, F&& f) {
  for (std::size_t n = 0; n < ctx.nodes.size(); ++n)
    if (ctx.mask[n]) ctx.nodes[n] = f(ctx.nodes[n]);
}

void apply(const TranslateOp& op, OpContext& ctx, const Index3&) {
  forSelected(ctx, [&](const Vec3& p) { return p + op.offset; });
}

void apply(const RotateOp& op, OpContext& ctx, const Index3&) {
  const EulerRotation rotation(op.angles);  // trigonometry once per op, not per node
  forSelected(ctx, [&](const Vec3& p) { return ctx.center + rotation.apply(p - ctx.center); });
}

void apply(const ScaleOp& op, OpContext& ctx, const Index3&) {
  forSelected(ctx, [&](const Vec3& p) { return ctx.center + (p - ctx.center) * op.factors; });
}

// Gröller & Wegenkittl 1994, §2.2 taper: (a, b) *= f(t), f = 1 + profile(t).
void apply(const TaperOp& op, OpContext& ctx, const Index3&) {
  const int along = static_cast<int>(op.axis);
  const std::array<int, 2> ab = perpendicularAxes(op.axis);
  const int a = ab[0], b = ab[1];  // not a structured binding: clang 14 cannot capture those
  forSelected(ctx, [&](const Vec3& p) {
    Vec3 q = p - ctx.center;
    const double f = 1.0 + profileValue(op.profile, op.k, op.omega, q[along]);
    q[a] *= f;
    q[b] *= f;
    return ctx.center + q;
  });
}

// Gröller & Wegenkittl 1994, §2.3 twist: rotate (a, b) by φ(t).
void apply(const TwistOp& op, OpContext& ctx, const Index3&) {
  const int along = static_cast<int>(op.axis);
  const std::array<int, 2> ab = perpendicularAxes(op.axis);
  const int a = ab[0], b = ab[1];  // not a structured binding: clang 14 cannot capture those
  forSelected(ctx, [&](const Vec3& p) {
    Vec3 q = p - ctx.center;
    const double phi = profileValue(op.profile, op.k, op.omega, q[along]);
    const double c = std::cos(phi), s = std::sin(phi);
    const double qa = q[a], qb = q[b];
    q[a] = qa * c - qb * s;
    q[b] = qa * s + qb * c;
    return ctx.center + q;
  });
}

// Gröller & Wegenkittl 1994, §2.4 / Barr's bend over the whole grid. With y the toward- and z the
// along-component: θ = k·z, ŷ = 1/k − (1/k − y)·cos θ, ẑ = (1/k − y)·sin θ, written
// in the algebraically equal form ŷ = y·cos θ + ½·k·z²·sinc²(θ/2), ẑ = z·sinc θ − y·sin θ,
// which is exact at k = 0 and smooth as k → 0.
void apply(const BendOp& op, OpContext& ctx, const Index3&) {
  const int along = static_cast<int>(op.axis), toward = static_cast<int>(op.toward);
  forSelected(ctx, [&](const Vec3& p) {
    Vec3 q = p - ctx.center;
    const double z = q[along], y = q[toward];
    const double theta = op.k * z;
    const double half = sinc(0.5 * theta);
    q[toward] = y * std::cos(theta) + 0.5 * op.k * z * z * half * half;
    q[along] = z * sinc(theta) - y * std::sin(theta);
    return ctx.center + q;
  });
}

// Gröller & Wegenkittl 1994, §2.5 magnet: f = s·((dmax − d)/dmax)^p, P̂ = P + f·(M − P) for d < dmax.
void apply(const MagnetOp& op, OpContext& ctx, const Index3&) {
  if (!(op.dmax > 0.0)) return;
  forSelected(ctx, [&](const Vec3& p) {
    const Vec3 toMagnet = op.point - p;
    const double d = std::sqrt(toMagnet.x * toMagnet.x + toMagnet.y * toMagnet.y + toMagnet.z * toMagnet.z);
    if (d >= op.dmax) return p;
    const double f = op.strength * std::pow((op.dmax - d) / op.dmax, op.falloff);
    return p + f * toMagnet;
  });
}

// Gröller & Wegenkittl 1994, §2.6 point morphing: P̂ = P + strength·Σ α_j / (|P − P_j|² + r_j²).
void apply(const MorphOp& op, OpContext& ctx, const Index3&) {
  if (op.pairs.empty()) return;
  std::vector<Vec3> alpha;
  std::vector<double> radius;
  solveMorph(op, alpha, radius);
  forSelected(ctx, [&](const Vec3& p) {
    Vec3 sum{0.0};
    for (std::size_t j = 0; j < op.pairs.size(); ++j) {
      const Vec3 d = p - op.pairs[j].from;
      sum += alpha[j] / (d.x * d.x + d.y * d.y + d.z * d.z + radius[j] * radius[j]);
    }
    return p + op.strength * sum;
  });
}

void apply(const CalculatorOp& op, OpContext& ctx, const Index3& resolution) {
  CompiledCalculator calculator(op);
  calculator.apply(ctx.nodes, resolution, ctx.mask, ctx.center, ctx.time);
}

// Colonna, "Animation of fractal objects", §2 and §3.2: each node moves by amplitude ⊙ F at
// (q + wind·t, t). The field is built once per evaluation, then read for every selected node;
// nodes are independent, so a grid is split over the worker pool.
void apply(const FieldOp& op, OpContext& ctx, const Index3&) {
  FractalField(op).displaceNodes(ctx.nodes, ctx.mask, ctx.time);
}

void apply(const NodesOp& op, OpContext& ctx, const Index3& resolution) {
  for (const NodeMove& move : op.moves) {
    const Index3& ix = move.index;
    // Moves outside the current resolution are kept in the file but have no node to move.
    if (ix[0] < 0 || ix[1] < 0 || ix[2] < 0 || ix[0] >= resolution[0] || ix[1] >= resolution[1] ||
        ix[2] >= resolution[2])
      continue;
    const std::size_t n =
        std::size_t(ix[0]) + std::size_t(resolution[0]) * (ix[1] + std::size_t(resolution[1]) * ix[2]);
    if (ctx.mask[n]) ctx.nodes[n] += move.displacement;
  }
}

}  // namespace

double triangleWave(double x) {
  // Quarter periods of sin: rises 0→1 on [0, π/2], falls to -1 at 3π/2, back to 0 at 2π.
  double m = std::fmod(x / (0.5 * M_PI), 4.0);
  if (m < 0) m += 4.0;
  if (m < 1.0) return m;
  if (m < 3.0) return 2.0 - m;
  return m - 4.0;
}

EulerRotation::EulerRotation(const Vec3& anglesDegrees) {
  const Vec3 r = anglesDegrees * (M_PI / 180.0);
  const double cx = std::cos(r.x), sx = std::sin(r.x), cy = std::cos(r.y), sy = std::sin(r.y);
  const double cz = std::cos(r.z), sz = std::sin(r.z);
  // R = Rz·Ry·Rx (x applied first), multiplied out row by row.
  m[0] = {cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx};
  m[1] = {sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx};
  m[2] = {-sy, cy * sx, cy * cx};
}

Vec3 rotateEuler(const Vec3& q, const Vec3& anglesDegrees) { return EulerRotation(anglesDegrees).apply(q); }

Vec3 applyPlacement(const Placement& placement, const Vec3& q) {
  return placement.translate + rotateEuler(placement.scale * q, placement.rotate);
}

Vec3 operationCenter(const Operation& op, const std::vector<Vec3>& nodes, const std::vector<unsigned char>& mask) {
  if (op.center.kind == Center::Kind::Point) return op.center.point;
  Vec3 sum{0.0};
  std::size_t count = 0;
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if (op.center.kind == Center::Kind::Grid || mask[n]) {
      sum += nodes[n];
      ++count;
    }
  if (count == 0) {  // empty selection: fall back to the grid centroid
    for (const Vec3& p : nodes) sum += p;
    count = nodes.size();
  }
  return sum / double(count);
}

void solveMorph(const MorphOp& morph, std::vector<Vec3>& alpha, std::vector<double>& radius) {
  const std::size_t n = morph.pairs.size();
  radius.assign(n, 1.0);
  alpha.assign(n, Vec3{0.0});
  if (n == 0) return;
  auto dist2 = [](const Vec3& a, const Vec3& b) {
    const Vec3 d = a - b;
    return d.x * d.x + d.y * d.y + d.z * d.z;
  };
  // r_i: distance from P_i to the nearest other P_j (1 for a single pair).
  if (n > 1) {
    for (std::size_t i = 0; i < n; ++i) {
      double best = INFINITY;
      for (std::size_t j = 0; j < n; ++j)
        if (j != i) best = std::min(best, dist2(morph.pairs[i].from, morph.pairs[j].from));
      radius[i] = std::sqrt(best);
      if (!(radius[i] > 1e-12))
        throw ModelError("pairs", "two morph start points coincide (pair " + std::to_string(i + 1) +
                                      "), so the morph system is singular");
    }
  }
  // A α = Q − P with A_ij = R_j(|P_i − P_j|); Gaussian elimination with partial pivoting.
  std::vector<double> a(n * n);
  std::vector<Vec3> rhs(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j)
      a[i * n + j] = 1.0 / (dist2(morph.pairs[i].from, morph.pairs[j].from) + radius[j] * radius[j]);
    rhs[i] = morph.pairs[i].to - morph.pairs[i].from;
  }
  double scale = 0.0;
  for (double v : a) scale = std::max(scale, std::abs(v));
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    for (std::size_t r = col + 1; r < n; ++r)
      if (std::abs(a[r * n + col]) > std::abs(a[pivot * n + col])) pivot = r;
    if (!(std::abs(a[pivot * n + col]) > 1e-12 * scale))
      throw ModelError("pairs", "the morph system is singular (start points are too close together)");
    if (pivot != col) {
      for (std::size_t c = 0; c < n; ++c) std::swap(a[col * n + c], a[pivot * n + c]);
      std::swap(rhs[col], rhs[pivot]);
    }
    for (std::size_t r = col + 1; r < n; ++r) {
      const double f = a[r * n + col] / a[col * n + col];
      if (f == 0.0) continue;
      for (std::size_t c = col; c < n; ++c) a[r * n + c] -= f * a[col * n + c];
      rhs[r] -= f * rhs[col];
    }
  }
  for (std::size_t i = n; i-- > 0;) {
    Vec3 v = rhs[i];
    for (std::size_t c = i + 1; c < n; ++c) v -= a[i * n + c] * alpha[c];
    alpha[i] = v / a[i * n + i];
  }
  for (const Vec3& v : alpha)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw ModelError("pairs", "the morph system is singular (start points are too close together)");
}

void applyOperation(const Operation& op, std::vector<Vec3>& nodes, const Index3& resolution, double time) {
  const std::vector<unsigned char> mask = selectionMask(op.selection, resolution);
  OpContext ctx{nodes, mask, operationCenter(op, nodes, mask), time};
  std::visit([&](const auto& params) { apply(params, ctx, resolution); }, op.params);
}

Grid evaluateFunction(const Function& function, std::size_t upToOp, bool applyPlacementToo, double time) {
  Grid grid(function.resolution);
  const std::size_t end = std::min(upToOp, function.ops.size());
  for (std::size_t o = 0; o < end; ++o) {
    const Operation& op = function.ops[o];
    if (op.muted) continue;
    const std::string path = "ops[" + std::to_string(o) + "]";
    try {
      applyOperation(op, grid.nodes(), grid.resolution(), time);
    } catch (const ModelError& error) {
      throw error.under(path);
    }
    for (const Vec3& p : grid.nodes())
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || std::abs(p.x) > limits::kMaxCoordinate ||
          std::abs(p.y) > limits::kMaxCoordinate || std::abs(p.z) > limits::kMaxCoordinate)
        throw ModelError(path, "the operation moves a node to a non-finite or absurdly distant position");
  }
  if (applyPlacementToo) {
    const EulerRotation rotation(function.placement.rotate);
    for (Vec3& p : grid.nodes()) p = function.placement.translate + rotation.apply(function.placement.scale * p);
  }
  return grid;
}

std::shared_ptr<const Grid> evaluateFunctionAt(const Function& function, const std::string& path, double time) {
  try {
    return std::make_shared<const Grid>(evaluateFunction(function, std::size_t(-1), true, time));
  } catch (const ModelError& e) {
    throw e.under(path);
  }
}

bool dependsOnTime(const Function& function) {
  for (const Operation& op : function.ops) {
    if (op.muted) continue;
    if (std::holds_alternative<FieldOp>(op.params)) return true;
    if (const auto* calc = std::get_if<CalculatorOp>(&op.params); calc && calculatorUsesTime(*calc)) return true;
  }
  return false;
}

}  // namespace gridifs
