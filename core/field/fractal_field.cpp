#include "field/fractal_field.h"

#include <algorithm>
#include <cmath>

#include "base/hash.h"
#include "field/field_lattice.h"
#include "field/field_step.h"

namespace gridifs {

namespace {

using field_lattice::hermite;
using field_lattice::kDims;
using field_lattice::randomFromSum;
constexpr int kCorners = 1 << kDims;

// The hash key and half of seed + axis at a level: seeds 2m and 2m + 1 share the key of pair m.
field_lattice::RandomKey levelKey(std::uint64_t seed, int axis, int level) {
  const std::uint64_t axisSeed = seed + static_cast<std::uint64_t>(axis);
  return {field_lattice::foldKey(splitmix64(splitmix64(axisSeed >> 1) + static_cast<std::uint64_t>(level))),
          (axisSeed & 1u) ? 16u : 0u};
}

}  // namespace

const char* toString(FieldInterpolation interpolation) {
  return interpolation == FieldInterpolation::Linear ? "linear" : "cubic";
}

bool parseFieldInterpolation(const std::string& text, FieldInterpolation& out) {
  if (text == "linear") {
    out = FieldInterpolation::Linear;
  } else if (text == "cubic") {
    out = FieldInterpolation::Cubic;
  } else {
    return false;
  }
  return true;
}

FractalField::FractalField(const FractalFieldParams& params) : params_(params) {
  levelCount_ = std::clamp(params.octaves, 1, FractalFieldParams::kMaxOctaves);
  // p(k) ∝ gain^k, normalised (Colonna §2.3 leaves the weights free as long as they decrease).
  double total = 0.0;
  for (int k = 1; k <= levelCount_; ++k) total += std::pow(params.gain, k);
  // The generalised golden ratio for four dimensions (the real root of x^5 = x + 1): its
  // powers give offsets that stay far from each other level after level.
  constexpr double kPhi4 = 1.1673039782614187;
  for (int k = 1; k <= levelCount_; ++k) {
    Level& level = levels_[k - 1];
    const double size = params.scale * std::pow(params.ratio, k - 1);
    for (int d = 0; d < kDims; ++d) {
      const double period = params.period[d];
      if (period > 0.0) {
        level.wrap[d] = std::max<std::int64_t>(1, std::llround(period / size));
        level.cell[d] = period / static_cast<double>(level.wrap[d]);
      } else {
        level.wrap[d] = 0;
        level.cell[d] = size;
      }
      const double alpha = 1.0 / std::pow(kPhi4, d + 1);
      const double fraction = 0.5 + k * alpha;
      level.offset[d] = level.cell[d] * (fraction - std::floor(fraction));
    }
    level.weight = std::pow(params.gain, k) / total;
    for (int axis = 0; axis < 3; ++axis) {
      const field_lattice::RandomKey key = levelKey(params.seed, axis, k);
      level.keys[axis] = key.key;
      level.shifts[axis] = key.shift;
    }
  }
}

double FractalField::bound() const {
  return params_.interpolation == FieldInterpolation::Linear ? 1.0 : 1.0 + kDims / 4.0;
}

FractalField::MeshGeometry FractalField::mesh(int level) const {
  const Level& l = levels_[std::clamp(level, 1, levelCount_) - 1];
  MeshGeometry g;
  for (int d = 0; d < kDims; ++d) {
    g.origin[d] = -l.offset[d];
    g.cell[d] = l.cell[d];
  }
  g.weight = l.weight;
  return g;
}

FieldPoint FractalField::wrapped(FieldPoint s) const {
  for (int d = 0; d < kDims; ++d) {
    const double period = params_.period[d];
    if (period > 0.0) s[d] -= period * std::floor(s[d] / period);
  }
  return s;
}

Vec3 FractalField::displacement(const Vec3& q, double t) const {
  const Vec3 shift = params_.windShift(t);
  const FieldPoint s = wrapped({q.x + shift.x, q.y + shift.y, q.z + shift.z, t});
  Vec3 sum{0.0, 0.0, 0.0};
  for (int k = 0; k < levelCount_; ++k) {
    const Level& level = levels_[k];
    double f[3];
    levelValues(level, level.keys, level.shifts, 3, s, f);
    sum += level.weight * Vec3{f[0], f[1], f[2]};
  }
  return params_.amplitude * sum;
}

void FractalField::displaceNodes(std::vector<Vec3>& nodes, const std::vector<unsigned char>& mask, double t,
                                 int threads) const {
  fieldStepDisplace(*this, nodes, mask, t, threads);
}

double FractalField::value(int axis, FieldPoint s) const {
  s = wrapped(s);
  double sum = 0.0;
  for (int k = 0; k < levelCount_; ++k) {
    const Level& level = levels_[k];
    double f = 0.0;
    const field_lattice::RandomKey key = levelKey(params_.seed, axis, k + 1);
    levelValues(level, {key.key, 0, 0}, {key.shift, 0, 0}, 1, s, &f);
    sum += level.weight * f;
  }
  return sum;
}

namespace {

// The cell of one level that holds a sample point: its lower vertex's hash contribution per
// dimension and step (-1, 0, +1, +2 from it, wrapped where periodic) and the position inside.
struct CellStencil {
  std::array<std::array<std::uint32_t, 4>, kDims> index{};  // [dimension][step + 1]
  std::array<double, kDims> u{};
};

}  // namespace

template <typename Level>
static CellStencil stencilFor(const Level& level, const FieldPoint& s) {
  CellStencil st;
  for (int d = 0; d < kDims; ++d) {
    const field_lattice::AxisCell cell = field_lattice::axisCell(s[d], level.offset[d], level.cell[d]);
    st.u[d] = cell.u;
    for (int step = 0; step < 4; ++step)
      st.index[d][step] = field_lattice::indexContribution(cell.base + step - 1, level.wrap[d], d);
  }
  return st;
}

void FractalField::levelValues(const Level& level, const std::array<std::uint32_t, 3>& keys,
                               const std::array<std::uint32_t, 3>& shifts, int axes, const FieldPoint& s,
                               double* out) const {
  const CellStencil st = stencilFor(level, s);
  // The hash inputs of the 2^4 cell corners, and of each corner's outward neighbour along each
  // dimension (step -1 below a lower corner, +2 beyond an upper one).
  std::array<std::uint32_t, kCorners> corner{};
  for (int c = 0; c < kCorners; ++c) {
    std::uint32_t sum = 0;
    for (int d = 0; d < kDims; ++d) sum += st.index[d][1 + ((c >> d) & 1)];
    corner[c] = sum;
  }
  if (params_.interpolation == FieldInterpolation::Linear) {
    std::array<double, kCorners> weight{};
    for (int c = 0; c < kCorners; ++c) {
      double w = 1.0;
      for (int d = 0; d < kDims; ++d) w *= ((c >> d) & 1) ? st.u[d] : 1.0 - st.u[d];
      weight[c] = w;
    }
    for (int a = 0; a < axes; ++a) {
      double result = 0.0;
      for (int c = 0; c < kCorners; ++c) result += weight[c] * randomFromSum(corner[c], {keys[a], shifts[a]});
      out[a] = result;
    }
    return;
  }
  std::array<std::array<std::uint32_t, kDims>, kCorners> outward{};
  for (int c = 0; c < kCorners; ++c) {
    for (int d = 0; d < kDims; ++d) {
      const int bit = (c >> d) & 1;
      outward[c][d] = corner[c] - st.index[d][1 + bit] + st.index[d][bit ? 3 : 0];
    }
  }
  for (int a = 0; a < axes; ++a) {
    // Values at the corners and their slopes by central differences (the appendix's
    // ∂f/∂u = (f(u+1) - f(u-1)) / 2), which reach one node outside the cell.
    std::array<double, kCorners> value{};
    std::array<std::array<double, kDims>, kCorners> slope{};
    for (int c = 0; c < kCorners; ++c) value[c] = randomFromSum(corner[c], {keys[a], shifts[a]});
    for (int c = 0; c < kCorners; ++c) {
      for (int d = 0; d < kDims; ++d) {
        const double beyond = randomFromSum(outward[c][d], {keys[a], shifts[a]});
        const double partner = value[c ^ (1 << d)];
        slope[c][d] = ((c >> d) & 1) ? 0.5 * (beyond - partner) : 0.5 * (partner - beyond);
      }
    }
    // Reduce one dimension at a time: cubic in the value along it, linear in the remaining
    // slopes (the appendix's B points), until one value is left.
    for (int d = 0; d < kDims; ++d) {
      const int stride = 1 << d;
      for (int c = 0; c < kCorners; c += stride * 2) {
        const int c1 = c + stride;
        value[c] = hermite(value[c], value[c1], slope[c][d], slope[c1][d], st.u[d]);
        for (int j = d + 1; j < kDims; ++j) slope[c][j] += st.u[d] * (slope[c1][j] - slope[c][j]);
      }
    }
    out[a] = value[0];
  }
}

}  // namespace gridifs
