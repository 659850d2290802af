#include "field/field_step.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>

#include "base/parallel.h"
#include "field/field_lattice.h"
#include "field/fractal_field.h"

namespace gridifs {

namespace {

using field_lattice::AxisCell;
using field_lattice::axisCell;
using field_lattice::hermite;
using field_lattice::indexContribution;
using Level = FractalField::Level;

constexpr int kAxes = 3;     // displacement axes: seeds S, S+1, S+2
constexpr int kSpace = 3;    // spatial dimensions of the collapsed mesh
constexpr int kCorners = 8;  // of a 3D cell; bit d of a corner's number: upper along d
// A node's hashed vertices per axis without a cache: cubic, the 8 corners at the four time
// steps around t and their 24 outward neighbours at the two time steps of the cell; linear,
// the 8 corners at the two time steps of the cell.
constexpr int kCubicVertices = kCorners * 4 + kCorners * kSpace * 2;
constexpr int kLinearVertices = kCorners * 2;
// Above this many vertices a level is hashed per node rather than collapsed into a box.
constexpr std::size_t kMaxBoxVertices = std::size_t(1) << 21;

// The sum over levels of p(k)·F_k per displacement axis and selected node.
using Totals = std::array<std::vector<double>, kAxes>;

// The time dimension of one level at t. By linearity of hermite() in its values and slopes, the
// appendix's last (time) reduction hermite(V0, V1, S0, S1, u) splits into the spatial reduction
// of g = value0·f(t0) + value1·f(t1) plus the trilinear interpolation of the time slopes
// e = slope0·(f(t1) − f(t−1))/2 + slope1·(f(t2) − f(t0))/2 (central differences, as the
// appendix takes them). Linear interpolation: g = (1 − u)·f(t0) + u·f(t1), no e.
// The one-dimensional bases of the appendix's reduction at a position u in a cell: linear
// (1 − u, u), Hermite value and Hermite slope, so that hermite(f0, f1, d0, d1, u) =
// value0·f0 + value1·f1 + slope0·d0 + slope1·d1.
struct CellBases {
  double linear0, linear1, value0, value1, slope0, slope1;
};

inline CellBases cellBases(double u) {
  const double u2 = u * u, u3 = u2 * u;
  return {1.0 - u, u, 2.0 * u3 - 3.0 * u2 + 1.0, 3.0 * u2 - 2.0 * u3, u3 - 2.0 * u2 + u, u3 - u2};
}

struct TimeCollapse {
  std::array<std::uint32_t, 4> index{};  // hash shares of the time steps −1, 0, +1, +2
  double value0 = 0.0, value1 = 0.0, slope0 = 0.0, slope1 = 0.0;
};

TimeCollapse timeCollapse(const Level& level, double t, bool cubic) {
  TimeCollapse c;
  const AxisCell cell = axisCell(t, level.offset[3], level.cell[3]);
  for (int step = 0; step < 4; ++step) c.index[step] = indexContribution(cell.base + step - 1, level.wrap[3], 3);
  const CellBases b = cellBases(cell.u);
  c.value0 = cubic ? b.value0 : b.linear0;
  c.value1 = cubic ? b.value1 : b.linear1;
  c.slope0 = cubic ? b.slope0 : 0.0;
  c.slope1 = cubic ? b.slope1 : 0.0;
  return c;
}

inline double lerp(double a, double b, double u) { return a + u * (b - a); }

// The appendix's reduction in x, then y, then z: cubic in the value along a dimension, linear in
// the remaining slopes. value: g at the cell's corners; beyond[c][d]: g at corner c's outward
// neighbour along d; timeSlope: e at the corners, interpolated trilinearly.
double pseudoCubic(std::array<double, kCorners> value, const std::array<std::array<double, kSpace>, kCorners>& beyond,
                   std::array<double, kCorners> timeSlope, const std::array<double, kSpace>& u) {
  std::array<std::array<double, kSpace>, kCorners> slope{};
  for (int c = 0; c < kCorners; ++c)
    for (int d = 0; d < kSpace; ++d) {
      const double partner = value[c ^ (1 << d)];
      slope[c][d] = ((c >> d) & 1) ? 0.5 * (beyond[c][d] - partner) : 0.5 * (partner - beyond[c][d]);
    }
  for (int d = 0; d < kSpace; ++d) {
    const int stride = 1 << d;
    for (int c = 0; c < kCorners; c += stride * 2) {
      const int c1 = c + stride;
      value[c] = hermite(value[c], value[c1], slope[c][d], slope[c1][d], u[d]);
      for (int j = d + 1; j < kSpace; ++j) slope[c][j] = lerp(slope[c][j], slope[c1][j], u[d]);
      timeSlope[c] = lerp(timeSlope[c], timeSlope[c1], u[d]);
    }
  }
  return value[0] + timeSlope[0];
}

double trilinear(std::array<double, kCorners> value, const std::array<double, kSpace>& u) {
  for (int d = 0; d < kSpace; ++d) {
    const int stride = 1 << d;
    for (int c = 0; c < kCorners; c += stride * 2) value[c] = lerp(value[c], value[c + stride], u[d]);
  }
  return value[0];
}

// The lattice vertices a set of nodes reaches on one level: the box from one below the lowest
// cell to two above the highest along each spatial dimension.
struct VertexBox {
  std::array<std::int64_t, kSpace> lo{};
  std::array<std::int64_t, kSpace> size{};
  std::size_t count() const { return std::size_t(size[0]) * std::size_t(size[1]) * std::size_t(size[2]); }
  std::size_t at(std::int64_t i, std::int64_t j, std::int64_t k) const {
    return std::size_t(i + size[0] * (j + size[1] * k));
  }
};

struct BoxBuilder {
  std::array<std::int64_t, kSpace> low{std::numeric_limits<std::int64_t>::max(),
                                       std::numeric_limits<std::int64_t>::max(),
                                       std::numeric_limits<std::int64_t>::max()};
  std::array<std::int64_t, kSpace> high{std::numeric_limits<std::int64_t>::min(),
                                        std::numeric_limits<std::int64_t>::min(),
                                        std::numeric_limits<std::int64_t>::min()};
  void add(int d, std::int64_t base) {
    low[d] = std::min(low[d], base);
    high[d] = std::max(high[d], base);
  }
  /// Whether the box is small enough to hold (spans compared in double: far-apart nodes must
  /// not overflow the index arithmetic).
  bool fits() const {
    double count = 1.0;
    for (int d = 0; d < kSpace; ++d) count *= double(high[d]) - double(low[d]) + 4.0;
    return count <= double(kMaxBoxVertices);
  }
  VertexBox box() const {
    VertexBox b;
    for (int d = 0; d < kSpace; ++d) {
      b.lo[d] = low[d] - 1;
      b.size[d] = high[d] - low[d] + 4;
    }
    return b;
  }
};

// One level's mesh collapsed at t over a box: g and e per displacement axis, x fastest.
struct CollapsedMesh {
  VertexBox box;
  std::array<std::vector<double>, kAxes> g, e;
};

// The hash shares of a box's vertex indices per spatial dimension (wrapped where periodic).
std::array<std::vector<std::uint32_t>, kSpace> boxShares(const Level& level, const VertexBox& box) {
  std::array<std::vector<std::uint32_t>, kSpace> share;
  for (int d = 0; d < kSpace; ++d) {
    share[d].resize(std::size_t(box.size[d]));
    for (std::int64_t i = 0; i < box.size[d]; ++i)
      share[d][std::size_t(i)] = indexContribution(box.lo[d] + i, level.wrap[d], d);
  }
  return share;
}

// g (and e, cubic) of one box row for the three axes: vertex i of the row has the hash input
// share[i] + rowShare + the time step's share. The three axes take two hashes per vertex and time
// step, as in hashAndSum below; the values are randomFromSum's, collapsed in time as
// TimeCollapse says, in one vector loop over the row.
template <typename Real, bool Cubic, bool OddSeed>
GRIDIFS_FIELD_VECTOR_CLONES void collapseHashes(const std::uint32_t* share, std::size_t width, std::uint32_t rowShare,
                                                const TimeCollapse& time, std::uint32_t firstPairKey,
                                                std::uint32_t secondPairKey, Real* g0, Real* g1, Real* g2, Real* e0,
                                                Real* e1, Real* e2) {
  using field_lattice::mix32;
  using field_lattice::randomHalf;
  constexpr Real scale = Real(field_lattice::kRandomScale);
  constexpr int kSteps = Cubic ? 4 : 2;
  constexpr int kFirst = Cubic ? 0 : 1;
  std::uint32_t times[kSteps];
  for (int step = 0; step < kSteps; ++step) times[step] = rowShare + time.index[std::size_t(kFirst + step)];
  const Real v0 = Real(time.value0), v1 = Real(time.value1), s0 = Real(0.5 * time.slope0), s1 = Real(0.5 * time.slope1);
  // In chunks along the row, one time step at a time, so every loop runs over the row's vertices.
  constexpr std::size_t kChunk = 64;
  Real f[kSteps][kAxes][kChunk];
  for (std::size_t begin = 0; begin < width; begin += kChunk) {
    const std::size_t count = std::min(kChunk, width - begin);
    const std::uint32_t* row = share + begin;
    for (int step = 0; step < kSteps; ++step)
      for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t index = row[i] + times[step];
        const std::uint32_t first = mix32(index + firstPairKey);
        const std::uint32_t second = mix32(index + secondPairKey);
        f[step][0][i] = Real(OddSeed ? randomHalf(first, 16) : randomHalf(first, 0)) * scale;
        f[step][1][i] = Real(OddSeed ? randomHalf(second, 0) : randomHalf(first, 16)) * scale;
        f[step][2][i] = Real(OddSeed ? randomHalf(second, 16) : randomHalf(second, 0)) * scale;
      }
    Real* g[kAxes] = {g0 + begin, g1 + begin, g2 + begin};
    Real* e[kAxes] = {e0 + begin, e1 + begin, e2 + begin};
    for (int a = 0; a < kAxes; ++a) {
      if constexpr (Cubic) {
        for (std::size_t i = 0; i < count; ++i) {
          g[a][i] = v0 * f[1][a][i] + v1 * f[2][a][i];
          e[a][i] = s0 * (f[2][a][i] - f[0][a][i]) + s1 * (f[3][a][i] - f[1][a][i]);
        }
      } else {
        for (std::size_t i = 0; i < count; ++i) g[a][i] = v0 * f[0][a][i] + v1 * f[1][a][i];
      }
    }
  }
}

// g (and e, cubic) of the box row (j, k) for the three axes into g[a][0..width), e[a][0..width).
template <typename Real>
void collapseRow(const Level& level, const TimeCollapse& time, bool cubic,
                 const std::array<std::vector<std::uint32_t>, kSpace>& share, std::size_t j, std::size_t k,
                 const std::array<Real*, kAxes>& g, const std::array<Real*, kAxes>& e) {
  const std::size_t width = share[0].size();
  const std::uint32_t rowShare = share[1][j] + share[2][k];
  // Axes 0 and 2 lie in consecutive seed pairs; axis 0's half says which case this is.
  const bool odd = level.shifts[0] != 0;
  const auto run = [&](auto kernel) {
    kernel(share[0].data(), width, rowShare, time, level.keys[0], level.keys[2], g[0], g[1], g[2], e[0], e[1], e[2]);
  };
  if (cubic)
    odd ? run(collapseHashes<Real, true, true>) : run(collapseHashes<Real, true, false>);
  else
    odd ? run(collapseHashes<Real, false, true>) : run(collapseHashes<Real, false, false>);
}

void collapse(const Level& level, const TimeCollapse& time, bool cubic, const VertexBox& box, int threads,
              CollapsedMesh& mesh) {
  mesh.box = box;
  const auto share = boxShares(level, box);
  for (int a = 0; a < kAxes; ++a) {
    mesh.g[a].resize(box.count());
    mesh.e[a].resize(cubic ? box.count() : 0);
  }
  const std::size_t width = std::size_t(box.size[0]);
  parallelFor(std::size_t(box.size[1] * box.size[2]), threads, 8, [&](std::size_t begin, std::size_t end) {
    for (std::size_t row = begin; row < end; ++row) {
      std::array<double*, kAxes> g{}, e{};
      for (int a = 0; a < kAxes; ++a) {
        g[a] = mesh.g[a].data() + row * width;
        e[a] = cubic ? mesh.e[a].data() + row * width : nullptr;
      }
      collapseRow(level, time, cubic, share, row % std::size_t(box.size[1]), row / std::size_t(box.size[1]), g, e);
    }
  });
}

struct NodeCell {
  std::array<std::int64_t, kSpace> base{};
  std::array<double, kSpace> u{};
};

NodeCell nodeCell(const Level& level, const Vec3& s) {
  NodeCell n;
  for (int d = 0; d < kSpace; ++d) {
    const AxisCell c = axisCell(s[d], level.offset[d], level.cell[d]);
    n.base[d] = c.base;
    n.u[d] = c.u;
  }
  return n;
}

// One level at one node read from its collapsed mesh, for the three axes.
void readCollapsed(const CollapsedMesh& mesh, bool cubic, const NodeCell& cell, double* out) {
  const VertexBox& box = mesh.box;
  const std::array<std::int64_t, kSpace> stride{1, box.size[0], box.size[0] * box.size[1]};
  const std::size_t origin = box.at(cell.base[0] - box.lo[0], cell.base[1] - box.lo[1], cell.base[2] - box.lo[2]);
  std::array<std::size_t, kCorners> corner{};
  for (int c = 0; c < kCorners; ++c) {
    std::int64_t offset = 0;
    for (int d = 0; d < kSpace; ++d) offset += ((c >> d) & 1) * stride[d];
    corner[c] = origin + std::size_t(offset);
  }
  for (int a = 0; a < kAxes; ++a) {
    const double* g = mesh.g[a].data();
    std::array<double, kCorners> value{};
    for (int c = 0; c < kCorners; ++c) value[c] = g[corner[c]];
    if (!cubic) {
      out[a] = trilinear(value, cell.u);
      continue;
    }
    const double* e = mesh.e[a].data();
    std::array<std::array<double, kSpace>, kCorners> beyond{};
    std::array<double, kCorners> timeSlope{};
    for (int c = 0; c < kCorners; ++c) {
      timeSlope[c] = e[corner[c]];
      for (int d = 0; d < kSpace; ++d)
        beyond[c][d] = g[((c >> d) & 1) ? corner[c] + std::size_t(stride[d]) : corner[c] - std::size_t(stride[d])];
    }
    out[a] = pseudoCubic(value, beyond, timeSlope, cell.u);
  }
}

// One level at a block of nodes whose vertices no other node shares. The pseudo-cubic is linear
// in the random values, and its weights are products of one-dimensional bases: along each
// dimension the appendix's reduction weighs a value by the Hermite value basis, a slope along
// the dimension being reduced by the Hermite slope basis, and the slopes of later dimensions (and
// the time slopes) by the linear one. So each node's weights are computed once for the three
// axes, and each axis is one sum of weight × RDN over the node's vertices, hashed in the same
// loop (no random value is stored).
constexpr std::size_t kBlock = 32;

// A hashed vertex: its index step (0..3 for −1, 0, +1, +2 from the cell's lower vertex) along x,
// y, z and t. Cubic: the 8 corners at the four time steps, then each corner's outward
// neighbour along x, y, z at the time steps 0 and +1; linear: the 8 corners at 0 and +1.
struct VertexSteps {
  std::array<std::uint8_t, 4> step{};
};

constexpr std::array<VertexSteps, kCubicVertices> cubicVertices() {
  std::array<VertexSteps, kCubicVertices> v{};
  for (int c = 0; c < kCorners; ++c)
    for (int time = 0; time < 4; ++time)
      v[std::size_t(c * 4 + time)].step = {std::uint8_t(1 + (c & 1)), std::uint8_t(1 + ((c >> 1) & 1)),
                                           std::uint8_t(1 + ((c >> 2) & 1)), std::uint8_t(time)};
  for (int c = 0; c < kCorners; ++c)
    for (int d = 0; d < kSpace; ++d)
      for (int time = 0; time < 2; ++time) {
        VertexSteps& s = v[std::size_t(kCorners * 4 + (c * kSpace + d) * 2 + time)];
        for (int e = 0; e < kSpace; ++e) s.step[std::size_t(e)] = std::uint8_t(1 + ((c >> e) & 1));
        s.step[std::size_t(d)] = ((c >> d) & 1) ? 3 : 0;
        s.step[3] = std::uint8_t(1 + time);
      }
  return v;
}

constexpr std::array<VertexSteps, kLinearVertices> linearVertices() {
  std::array<VertexSteps, kLinearVertices> v{};
  for (int c = 0; c < kCorners; ++c)
    for (int time = 0; time < 2; ++time)
      v[std::size_t(c * 2 + time)].step = {std::uint8_t(1 + (c & 1)), std::uint8_t(1 + ((c >> 1) & 1)),
                                           std::uint8_t(1 + ((c >> 2) & 1)), std::uint8_t(1 + time)};
  return v;
}

constexpr std::array<VertexSteps, kCubicVertices> kCubicSteps = cubicVertices();
constexpr std::array<VertexSteps, kLinearVertices> kLinearSteps = linearVertices();

// A block's inputs, node-minor ([…][node]) so that every loop below runs over the block's nodes
// in vector instructions.
struct BlockScratch {
  std::array<std::array<std::array<std::uint32_t, kBlock>, 4>, kSpace> share{};  // [d][step][node]
  std::array<std::array<double, kBlock>, kSpace> u{};
  // Each vertex's weight is Σ_t factor[v][t] · base[term t of v] (see blockWeights): the x bases
  // per node, and the factors per node or, when the block's nodes share their y and z cells, per
  // block (index 0).
  std::array<std::array<float, kBlock>, 6> base{};
  std::vector<std::array<std::array<float, kBlock>, 3>> factor =
      std::vector<std::array<std::array<float, kBlock>, 3>>(kCubicVertices);
  std::array<std::array<double, kBlock>, kAxes> out{};
};

// The x bases: the linear one, the Hermite value one and the Hermite slope one (with the central
// differences' 1/2), each for the lower (0) and upper (1) side of the cell.
enum XBase : std::uint8_t { kLinear0, kLinear1, kValue0, kValue1, kSlope0, kSlope1 };

// Which x bases a vertex's weight sums (in the order of kCubicSteps or kLinearSteps).
struct VertexTerms {
  std::uint8_t count = 0;
  std::array<std::uint8_t, 3> base{};
};

constexpr std::array<VertexTerms, kCubicVertices> cubicTerms() {
  std::array<VertexTerms, kCubicVertices> v{};
  for (int c = 0; c < kCorners; ++c) {
    const int bx = c & 1;
    const auto l = std::uint8_t(kLinear0 + bx), h = std::uint8_t(kValue0 + bx), x = std::uint8_t(kSlope0 + (1 - bx));
    v[std::size_t(c * 4 + 0)] = {1, {l, 0, 0}};
    v[std::size_t(c * 4 + 1)] = {3, {h, x, l}};
    v[std::size_t(c * 4 + 2)] = {3, {h, x, l}};
    v[std::size_t(c * 4 + 3)] = {1, {l, 0, 0}};
    for (int d = 0; d < kSpace; ++d)
      for (int time = 0; time < 2; ++time)
        v[std::size_t(kCorners * 4 + (c * kSpace + d) * 2 + time)] = {1,
                                                                      {d == 0 ? std::uint8_t(kSlope0 + bx) : l, 0, 0}};
  }
  return v;
}

constexpr std::array<VertexTerms, kLinearVertices> linearTerms() {
  std::array<VertexTerms, kLinearVertices> v{};
  for (int c = 0; c < kCorners; ++c)
    for (int time = 0; time < 2; ++time) v[std::size_t(c * 2 + time)] = {1, {std::uint8_t(kLinear0 + (c & 1)), 0, 0}};
  return v;
}

constexpr std::array<VertexTerms, kCubicVertices> kCubicTerms = cubicTerms();
constexpr std::array<VertexTerms, kLinearVertices> kLinearTerms = linearTerms();

// The weight of each hashed vertex (in the order of kCubicSteps or kLinearSteps) in a node's
// value, times RDN's integer scale. Cubic, for corner c with bits (bx, by, bz): its value
// weighs hv(bx)·hv(by)·hv(bz), its slope along x hs(bx)·hv(by)·hv(bz), along y
// l(bx)·hs(by)·hv(bz), along z l(bx)·l(by)·hs(bz), its time slope l(bx)·l(by)·l(bz), with
// hv, hs the Hermite value and slope bases of hermite() and l the linear one; the slopes are
// the central differences of pseudoCubic(), the collapsed values and time slopes those of
// TimeCollapse. A corner's slope along d is (beyond − partner)/2 at an upper corner,
// (partner − beyond)/2 at a lower one, so it weighs its outward neighbour and the partner corner
// across the cell. Every weight is then a sum of at most three x bases (hv, hs, l of the node's
// x position) times factors of y, z and time, which are formed once per block when its nodes
// share their y and z cells (a row of a tensor grid: SharedYz) and per node otherwise, in the
// same way, so a node's weights do not depend on its block. The one-dimensional bases in double,
// their products and sums in single precision (hashAndSum sums in single precision).
template <bool SharedYz>
GRIDIFS_FIELD_VECTOR_CLONES void blockWeights(bool cubic, const TimeCollapse& time,
                                              const std::array<std::array<double, kBlock>, kSpace>& u,
                                              BlockScratch& out) {
  constexpr double scale = field_lattice::kRandomScale;
  constexpr std::size_t kYz = SharedYz ? 1 : kBlock;  // y·z factors per block
  for (std::size_t n = 0; n < kBlock; ++n) {
    const CellBases b = cellBases(u[0][n]);
    out.base[kLinear0][n] = float(b.linear0);
    out.base[kLinear1][n] = float(b.linear1);
    out.base[kValue0][n] = float(b.value0);
    out.base[kValue1][n] = float(b.value1);
    out.base[kSlope0][n] = float(0.5 * b.slope0);
    out.base[kSlope1][n] = float(0.5 * b.slope1);
  }
  // Per (by, bz) = q: the y·z factors of a corner's value (and x slope), y slope, z slope and
  // time slope, formed in double and rounded once (the factors below are their products with
  // the time weights in single precision).
  float yzValue[4][kYz], yzSlopeY[4][kYz], yzSlopeZ[4][kYz], yzLinear[4][kYz];
  for (std::size_t m = 0; m < kYz; ++m) {
    double l[2][2], h[2][2], sl[2][2];  // [y or z][side]
    for (int d = 0; d < 2; ++d) {
      const CellBases b = cellBases(u[std::size_t(d + 1)][m]);
      l[d][0] = b.linear0;
      l[d][1] = b.linear1;
      h[d][0] = b.value0;
      h[d][1] = b.value1;
      sl[d][0] = 0.5 * b.slope0;
      sl[d][1] = 0.5 * b.slope1;
    }
    for (int q = 0; q < 4; ++q) {
      const int by = q & 1, bz = q >> 1;
      yzValue[q][m] = float(h[0][by] * h[1][bz]);
      yzSlopeY[q][m] = float(sl[0][by] * h[1][bz]);
      yzSlopeZ[q][m] = float(l[0][by] * sl[1][bz]);
      yzLinear[q][m] = float(l[0][by] * l[1][bz]);
    }
  }
  const auto factor = [&](int vertex, int term) -> float* {
    return out.factor[std::size_t(vertex)][std::size_t(term)].data();
  };
  const float v0 = float(time.value0 * scale), v1 = float(time.value1 * scale);
  if (!cubic) {
    for (int c = 0; c < kCorners; ++c)
      for (std::size_t m = 0; m < kYz; ++m) {
        factor(c * 2, 0)[m] = v0 * yzLinear[c >> 1][m];
        factor(c * 2 + 1, 0)[m] = v1 * yzLinear[c >> 1][m];
      }
    return;
  }
  const float s0 = float(0.5 * time.slope0 * scale), s1 = float(0.5 * time.slope1 * scale);
  for (int c = 0; c < kCorners; ++c) {
    const int bx = c & 1, by = (c >> 1) & 1, bz = c >> 2, q = c >> 1;
    const float signX = bx ? 1.0f : -1.0f, signY = by ? 1.0f : -1.0f, signZ = bz ? 1.0f : -1.0f;
    // The corner's value at the time steps 0 and +1 is hv(bx)·V + hs(1 − bx)·X + l(bx)·P (its
    // value and its shares in the partners' slopes along x, y and z); its time slope l(bx)·T.
    for (std::size_t m = 0; m < kYz; ++m) {
      const float value = yzValue[q][m];
      const float partners = signY * yzSlopeY[q ^ 1][m] + signZ * yzSlopeZ[q ^ 2][m];
      const float timeSlope = yzLinear[q][m];
      factor(c * 4, 0)[m] = -s0 * timeSlope;
      factor(c * 4 + 1, 0)[m] = v0 * value;
      factor(c * 4 + 1, 1)[m] = signX * (v0 * value);
      factor(c * 4 + 1, 2)[m] = v0 * partners - s1 * timeSlope;
      factor(c * 4 + 2, 0)[m] = v1 * value;
      factor(c * 4 + 2, 1)[m] = signX * (v1 * value);
      factor(c * 4 + 2, 2)[m] = v1 * partners + s0 * timeSlope;
      factor(c * 4 + 3, 0)[m] = s1 * timeSlope;
      // The outward neighbours: ±v times the corner's slope factor along their dimension.
      for (int step = 0; step < 2; ++step) {
        const float v = step == 0 ? v0 : v1;
        const int outward = kCorners * 4 + c * kSpace * 2 + step;
        factor(outward, 0)[m] = signX * (v * value);
        factor(outward + 2, 0)[m] = signY * (v * yzSlopeY[q][m]);
        factor(outward + 4, 0)[m] = signZ * (v * yzSlopeZ[q][m]);
      }
    }
  }
}

// out[a][n] = Σ_v weight[v][n] · RDN integer of axis a at vertex v for node n (v in order),
// where vertex v's hash input adds node n's shares of v's steps: the hashes and the sums in one
// loop over the block's nodes. The three axes (seeds S, S+1, S+2) take two hashes per vertex,
// of the seed pairs holding S and S+2: even S reads the pair (S, S+1) whole and the upper half
// of the next; odd S the lower half of the first and the next pair whole.
// GCC's unroll-and-jam fuses two vertices' loops into one it then leaves scalar: keep it off.
#if defined(__GNUC__) && !defined(__clang__)
#define GRIDIFS_NO_UNROLL_AND_JAM __attribute__((optimize("no-loop-unroll-and-jam")))
#else
#define GRIDIFS_NO_UNROLL_AND_JAM
#endif

template <bool OddSeed, bool SharedYz>
GRIDIFS_FIELD_VECTOR_CLONES GRIDIFS_NO_UNROLL_AND_JAM void hashAndSum(
    const VertexSteps* vertices, const VertexTerms* terms, int count, const BlockScratch& in,
    const std::array<std::uint32_t, 4>& times, std::uint32_t firstPairKey, std::uint32_t secondPairKey,
    std::array<std::array<double, kBlock>, kAxes>& out) {
  using field_lattice::mix32;
  using field_lattice::randomHalf;
  const auto yzAt = [](std::size_t n) { return SharedYz ? std::size_t(0) : n; };
  float sum[kAxes][kBlock] = {};
  for (int v = 0; v < count; ++v) {
    const VertexSteps& s = vertices[v];
    const std::uint32_t* x = in.share[0][s.step[0]].data();
    const std::uint32_t* y = in.share[1][s.step[1]].data();
    const std::uint32_t* z = in.share[2][s.step[2]].data();
    const std::uint32_t t = times[s.step[3]];
    // Shared y and z cells: the rest of each hash input is one number per vertex and pair.
    const std::uint32_t firstRest = y[0] + z[0] + t + firstPairKey, secondRest = y[0] + z[0] + t + secondPairKey;
    const VertexTerms& term = terms[v];
    const float* b0 = in.base[term.base[0]].data();
    const float* b1 = in.base[term.base[1]].data();
    const float* b2 = in.base[term.base[2]].data();
    const float* f0 = in.factor[std::size_t(v)][0].data();
    const float* f1 = in.factor[std::size_t(v)][1].data();
    const float* f2 = in.factor[std::size_t(v)][2].data();
    const auto accumulate = [&](std::size_t n, float w) {
      const std::uint32_t index = SharedYz ? 0u : y[n] + z[n] + t;
      const std::uint32_t first = mix32(SharedYz ? x[n] + firstRest : x[n] + index + firstPairKey);
      const std::uint32_t second = mix32(SharedYz ? x[n] + secondRest : x[n] + index + secondPairKey);
      const std::int32_t a0 = OddSeed ? randomHalf(first, 16) : randomHalf(first, 0);
      const std::int32_t a1 = OddSeed ? randomHalf(second, 0) : randomHalf(first, 16);
      const std::int32_t a2 = OddSeed ? randomHalf(second, 16) : randomHalf(second, 0);
      sum[0][n] = std::fma(w, float(a0), sum[0][n]);
      sum[1][n] = std::fma(w, float(a1), sum[1][n]);
      sum[2][n] = std::fma(w, float(a2), sum[2][n]);
    };
    // The weight formed in the same loop (one product, or a sum of three), never stored.
    if (term.count == 1) {
      for (std::size_t n = 0; n < kBlock; ++n) accumulate(n, b0[n] * f0[yzAt(n)]);
    } else {
      for (std::size_t n = 0; n < kBlock; ++n)
        accumulate(n, std::fma(b0[n], f0[yzAt(n)], std::fma(b1[n], f1[yzAt(n)], b2[n] * f2[yzAt(n)])));
    }
  }
  for (int a = 0; a < kAxes; ++a)
    for (std::size_t n = 0; n < kBlock; ++n) out[a][n] = double(sum[a][n]);
}

// A sample's cell along one dimension as the hashing reads it: the index shares of the four
// steps around it and the position inside.
struct SampleCell {
  std::array<std::uint32_t, 4> share{};
  double u = 0.0;
};

SampleCell sampleCell(const Level& level, int d, const AxisCell& cell) {
  SampleCell c;
  c.u = cell.u;
  for (int step = 0; step < 4; ++step)
    c.share[std::size_t(step)] = indexContribution(cell.base + step - 1, level.wrap[d], d);
  return c;
}

// Fills node n of a block with its cells along x, y and z.
void putNode(std::size_t n, const SampleCell& x, const SampleCell& y, const SampleCell& z, BlockScratch& scratch) {
  const SampleCell* cell[kSpace] = {&x, &y, &z};
  for (int d = 0; d < kSpace; ++d) {
    scratch.u[d][n] = cell[d]->u;
    for (int step = 0; step < 4; ++step) scratch.share[d][step][n] = cell[d]->share[std::size_t(step)];
  }
}

// One level at a block of up to kBlock nodes whose cells are in `scratch` (a short block repeats
// its last node to fill the vectors; those values are not used). sharedYz: every node of the
// block has the same y and z cells.
void hashDirect(const Level& level, const TimeCollapse& time, bool cubic, std::size_t count, bool sharedYz,
                BlockScratch& scratch, const std::array<double*, kAxes>& total) {
  if (sharedYz)
    blockWeights<true>(cubic, time, scratch.u, scratch);
  else
    blockWeights<false>(cubic, time, scratch.u, scratch);
  const VertexSteps* steps = cubic ? kCubicSteps.data() : kLinearSteps.data();
  const VertexTerms* terms = cubic ? kCubicTerms.data() : kLinearTerms.data();
  const int vertices = cubic ? kCubicVertices : kLinearVertices;
  const bool odd = level.shifts[0] != 0;
  const auto run = [&](auto kernel) {
    kernel(steps, terms, vertices, scratch, time.index, level.keys[0], level.keys[2], scratch.out);
  };
  if (sharedYz)
    odd ? run(hashAndSum<true, true>) : run(hashAndSum<false, true>);
  else
    odd ? run(hashAndSum<true, false>) : run(hashAndSum<false, false>);
  for (int a = 0; a < kAxes; ++a)
    for (std::size_t n = 0; n < count; ++n) total[a][n] += level.weight * scratch.out[a][n];
}

// Nodes at every (xs[i], ys[j], zs[k]), x fastest: an undistorted grid or a heightfield.
struct TensorGrid {
  std::array<std::vector<double>, kSpace> coordinate;
};

bool findTensorGrid(const std::vector<Vec3>& nodes, TensorGrid& grid) {
  const std::size_t n = nodes.size();
  if (n < 64) return false;
  std::size_t nx = 1;
  while (nx < n && nodes[nx].y == nodes[0].y && nodes[nx].z == nodes[0].z) ++nx;
  std::size_t ny = 1;
  while (ny * nx < n && nodes[ny * nx].z == nodes[0].z) ++ny;
  if (n % (nx * ny) != 0) return false;
  const std::size_t nz = n / (nx * ny);
  for (int d = 0; d < kSpace; ++d) grid.coordinate[d].clear();
  for (std::size_t i = 0; i < nx; ++i) grid.coordinate[0].push_back(nodes[i].x);
  for (std::size_t j = 0; j < ny; ++j) grid.coordinate[1].push_back(nodes[j * nx].y);
  for (std::size_t k = 0; k < nz; ++k) grid.coordinate[2].push_back(nodes[k * nx * ny].z);
  // Row by row, without branching per node, so the comparisons run in vector instructions.
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 0; j < ny; ++j) {
      const Vec3* row = &nodes[nx * (j + ny * k)];
      const double y = grid.coordinate[1][j], z = grid.coordinate[2][k];
      bool differs = false;
      for (std::size_t i = 0; i < nx; ++i)
        differs |= (row[i].x != grid.coordinate[0][i]) | (row[i].y != y) | (row[i].z != z);
      if (differs) return false;
    }
  return true;
}

// Tensor grids: one level over the whole grid, one dimension at a time.
//
// The appendix's reduction is linear in g and e, and each of its steps acts along one dimension,
// so a level's value is a sum of tensor products of one-dimensional operators on the collapsed
// mesh: with C the cubic along a dimension whose end slopes are central differences (Catmull-Rom),
// H its value part and D its slope part (C = H + D), and L the linear interpolation,
//   value = H_z H_y C_x g + H_z D_y L_x g + D_z L_y L_x g + L_z L_y L_x e
// (x reduced first: cubic in the value, linear in the later slopes; then y; then z), and
// n-linear interpolation is L_z L_y L_x g. Operators along different dimensions commute, so they
// are applied in the order that keeps each step a weighted sum of contiguous rows: z over whole
// layers of the box (q1 = H_z g, q2 = D_z g + L_z e), then y over their rows
// (y1 = H_y q1, y2 = D_y q1 + L_y q2), then x along each row (C_x y1 + L_x y2), which lands in
// the grid's node order. Along x the samples are taken sixteen at a time as a small dense band
// of weights over the box vertices they reach, so that pass is vector arithmetic too.

// The passes work in single precision, like the per-node sums: a level's values carry a relative
// rounding error of about 1e-7, far below anything visible, at twice the vector width.
using Pass = float;

// Per sample along y or z: its lower box vertex and the weights of the four vertices around it
// (steps −1, 0, +1, +2) in D, and of the two of its cell (steps 0, +1) in H and L.
struct AxisTaps {
  std::vector<std::size_t> at;
  std::vector<std::array<Pass, 4>> d;
  std::vector<std::array<Pass, 2>> h, l;
};

struct TapWeights {
  std::array<double, 4> c, d;  // Catmull-Rom and its slope part
  std::array<double, 2> h, l;  // Hermite value part, linear
};

TapWeights tapWeights(double u) {
  const CellBases b = cellBases(u);
  const double hv0 = b.value0, hv1 = b.value1;
  // hermite()'s slope terms hs0·d0 + hs1·d1 with d0 = (f1 − f−1)/2, d1 = (f2 − f0)/2.
  const double hs0 = 0.5 * b.slope0, hs1 = 0.5 * b.slope1;
  return {{-hs0, hv0 - hs1, hv1 + hs0, hs1}, {-hs0, -hs1, hs0, hs1}, {hv0, hv1}, {b.linear0, b.linear1}};
}

AxisTaps axisTaps(const std::vector<AxisCell>& cells, std::int64_t lo) {
  AxisTaps taps;
  for (const AxisCell& cell : cells) {
    const TapWeights w = tapWeights(cell.u);
    taps.at.push_back(std::size_t(cell.base - lo));
    taps.d.push_back({Pass(w.d[0]), Pass(w.d[1]), Pass(w.d[2]), Pass(w.d[3])});
    taps.h.push_back({Pass(w.h[0]), Pass(w.h[1])});
    taps.l.push_back({Pass(w.l[0]), Pass(w.l[1])});
  }
  return taps;
}

// The x pass as bands: samples in groups of kLanes; group q reads the box vertices
// first[q] .. first[q] + span[q] − 1, with weight c[q][v][lane] (C, or L when linear) and
// l[q][v][lane] (L) for vertex first[q] + v and sample kLanes·q + lane (zero beyond the samples).
constexpr std::size_t kLanes = 16;
struct XBands {
  std::vector<std::size_t> first, span, offset;  // offset: of group q's rows in c and l
  std::vector<std::array<Pass, kLanes>> c, l;
};

XBands xBands(const std::vector<AxisCell>& cells, std::int64_t lo, bool cubic) {
  XBands bands;
  for (std::size_t begin = 0; begin < cells.size(); begin += kLanes) {
    const std::size_t count = std::min(kLanes, cells.size() - begin);
    std::size_t low = std::numeric_limits<std::size_t>::max(), high = 0;
    for (std::size_t s = begin; s < begin + count; ++s) {
      const std::size_t at = std::size_t(cells[s].base - lo);
      low = std::min(low, at - 1);
      high = std::max(high, at + 2);
    }
    bands.first.push_back(low);
    bands.span.push_back(high - low + 1);
    bands.offset.push_back(bands.c.size());
    bands.c.resize(bands.c.size() + high - low + 1, std::array<Pass, kLanes>{});
    bands.l.resize(bands.c.size(), std::array<Pass, kLanes>{});
    std::array<Pass, kLanes>* c = bands.c.data() + bands.offset.back();
    std::array<Pass, kLanes>* l = bands.l.data() + bands.offset.back();
    for (std::size_t lane = 0; lane < count; ++lane) {
      const AxisCell& cell = cells[begin + lane];
      const TapWeights w = tapWeights(cell.u);
      const std::size_t at = std::size_t(cell.base - lo) - 1 - low;  // the sample's step −1, in the band
      for (int t = 0; t < 4; ++t) c[at + std::size_t(t)][lane] = Pass(cubic ? w.c[std::size_t(t)] : 0.0);
      for (int t = 0; t < 2; ++t) {
        l[at + 1 + std::size_t(t)][lane] = Pass(w.l[std::size_t(t)]);
        if (!cubic) c[at + 1 + std::size_t(t)][lane] = Pass(w.l[std::size_t(t)]);
      }
    }
  }
  return bands;
}

// The collapsed layers (constant z) of one level's box, computed when first asked for and kept
// while the samples along z still need them (a few at a time: the samples' cells move upward).
class LayerCache {
 public:
  LayerCache(const Level& level, const TimeCollapse& time, bool cubic, const VertexBox& box,
             const std::array<std::vector<std::uint32_t>, kSpace>& share)
      : level_(level),
        time_(time),
        cubic_(cubic),
        box_(box),
        share_(share),
        layerSize_(std::size_t(box.size[0] * box.size[1])) {}

  // g (quantity 0) or e (quantity 1) of axis a on layer k, in [j][i] order (x fastest).
  const Pass* layer(std::size_t k, int a, int quantity) {
    Slot& slot = find(k);
    return slot.values.data() + (std::size_t(quantity) * kAxes + std::size_t(a)) * layerSize_;
  }

 private:
  struct Slot {
    std::int64_t k = -1;
    std::uint64_t used = 0;
    std::vector<Pass> values;  // [quantity][axis][j][i]
  };
  static constexpr int kSlots = 8;

  Slot& find(std::size_t k) {
    ++clock_;
    Slot* oldest = &slots_[0];
    for (Slot& slot : slots_) {
      if (slot.k == std::int64_t(k)) {
        slot.used = clock_;
        return slot;
      }
      if (slot.used < oldest->used) oldest = &slot;
    }
    fill(*oldest, k);
    oldest->used = clock_;
    return *oldest;
  }

  void fill(Slot& slot, std::size_t k) {
    slot.k = std::int64_t(k);
    slot.values.resize(layerSize_ * kAxes * (cubic_ ? 2 : 1));
    const std::size_t bx = std::size_t(box_.size[0]), by = std::size_t(box_.size[1]);
    for (std::size_t j = 0; j < by; ++j) {
      std::array<Pass*, kAxes> g{}, e{};
      for (int a = 0; a < kAxes; ++a) {
        g[a] = slot.values.data() + std::size_t(a) * layerSize_ + j * bx;
        e[a] = cubic_ ? slot.values.data() + (kAxes + std::size_t(a)) * layerSize_ + j * bx : nullptr;
      }
      collapseRow(level_, time_, cubic_, share_, j, k, g, e);
    }
  }

  const Level& level_;
  const TimeCollapse& time_;
  bool cubic_;
  VertexBox box_;
  const std::array<std::vector<std::uint32_t>, kSpace>& share_;
  std::size_t layerSize_;
  std::array<Slot, kSlots> slots_{};
  std::uint64_t clock_ = 0;
};

// One axis of one sample layer of a tensor grid: the three passes over the collapsed layers
// around it. g[0..3], e[0..3]: the box layers at the steps −1, 0, +1, +2 along z from the sample
// layer's cell ([j][i], x fastest; linear reads g[1], g[2] only, cubic e[1], e[2] only); out: the
// layer's nodes' totals, [j][i], to which weight times their values are added.
struct LayerPasses {
  std::size_t bx = 0, by = 0, nx = 0, ny = 0;
  const AxisTaps* y = nullptr;
  const XBands* x = nullptr;
  Pass *q1 = nullptr, *q2 = nullptr, *y1 = nullptr, *y2 = nullptr;  // [j][i]: by × bx, then ny × bx
};

// The rows of the passes. Each takes restrict pointers as parameters, so that once inlined the
// vectorizer still knows that no store changes the rows it reads.
inline void zRowsCubic(const Pass* __restrict gm, const Pass* __restrict g0, const Pass* __restrict g1,
                       const Pass* __restrict g2, const Pass* __restrict e0, const Pass* __restrict e1, std::size_t n,
                       const std::array<Pass, 2>& zh, const std::array<Pass, 4>& zd, const std::array<Pass, 2>& zl,
                       Pass* __restrict q1, Pass* __restrict q2) {
  const Pass h0 = zh[0], h1 = zh[1], d0 = zd[0], d1 = zd[1], d2 = zd[2], d3 = zd[3], l0 = zl[0], l1 = zl[1];
  for (std::size_t i = 0; i < n; ++i) {
    q1[i] = h0 * g0[i] + h1 * g1[i];
    q2[i] = ((d0 * gm[i] + d1 * g0[i]) + (d2 * g1[i] + d3 * g2[i])) + (l0 * e0[i] + l1 * e1[i]);
  }
}

inline void weighRows(const Pass* __restrict r0, const Pass* __restrict r1, Pass w0, Pass w1, std::size_t n,
                      Pass* __restrict out) {
  for (std::size_t i = 0; i < n; ++i) out[i] = w0 * r0[i] + w1 * r1[i];
}

// y1 = H_y q1 and y2 = D_y q1 + L_y q2 for one sample row; a points at q1's row of the cell's lower
// vertex, b at q2's, rows `stride` apart.
inline void yRowCubic(const Pass* __restrict a, const Pass* __restrict b, std::size_t stride, std::size_t n,
                      const std::array<Pass, 2>& h, const std::array<Pass, 4>& d, const std::array<Pass, 2>& l,
                      Pass* __restrict y1, Pass* __restrict y2) {
  const Pass h0 = h[0], h1 = h[1], d0 = d[0], d1 = d[1], d2 = d[2], d3 = d[3], l0 = l[0], l1 = l[1];
  const Pass* __restrict am = a - stride;
  const Pass* __restrict a1 = a + stride;
  const Pass* __restrict a2 = a + 2 * stride;
  const Pass* __restrict b1 = b + stride;
  for (std::size_t i = 0; i < n; ++i) {
    y1[i] = h0 * a[i] + h1 * a1[i];
    y2[i] = ((d0 * am[i] + d1 * a[i]) + (d2 * a1[i] + d3 * a2[i])) + (l0 * b[i] + l1 * b1[i]);
  }
}

// Σ over a band of vertices of value · weights, sixteen samples at a time, in vectors of sixteen
// lanes (GCC's vector extension: one AVX-512 register, two AVX2 ones). Two sums, of the even and
// the odd vertices, so that each addition need not wait for the one before.
using PassLanes = Pass __attribute__((vector_size(sizeof(Pass) * kLanes)));
inline void bandSum(const Pass* __restrict a, const std::array<Pass, kLanes>* __restrict c, std::size_t span,
                    PassLanes& even, PassLanes& odd) {
  std::size_t v = 0;
  for (; v + 1 < span; v += 2) {
    PassLanes w0, w1;
    std::memcpy(&w0, c[v].data(), sizeof w0);
    std::memcpy(&w1, c[v + 1].data(), sizeof w1);
    even += a[v] * w0;
    odd += a[v + 1] * w1;
  }
  if (v < span) {
    PassLanes w0;
    std::memcpy(&w0, c[v].data(), sizeof w0);
    even += a[v] * w0;
  }
}

GRIDIFS_FIELD_VECTOR_CLONES
void layerPasses(const LayerPasses& p, bool cubic, const std::array<const Pass*, 4>& g,
                 const std::array<const Pass*, 4>& e, const std::array<Pass, 2>& zh, const std::array<Pass, 4>& zd,
                 const std::array<Pass, 2>& zl, double weight, double* out) {
  const std::size_t layer = p.bx * p.by, bx = p.bx, nx = p.nx;
  // z: q1 = H_z g, q2 = D_z g + L_z e (linear: q1 = L_z g).
  if (cubic)
    zRowsCubic(g[0], g[1], g[2], g[3], e[1], e[2], layer, zh, zd, zl, p.q1, p.q2);
  else
    weighRows(g[1], g[2], zl[0], zl[1], layer, p.q1);
  // y: y1 = H_y q1, y2 = D_y q1 + L_y q2 (linear: y1 = L_y q1), per sample row j.
  for (std::size_t j = 0; j < p.ny; ++j) {
    const std::size_t at = p.y->at[j] * bx;
    if (cubic)
      yRowCubic(p.q1 + at, p.q2 + at, bx, bx, p.y->h[j], p.y->d[j], p.y->l[j], p.y1 + j * bx, p.y2 + j * bx);
    else
      weighRows(p.q1 + at, p.q1 + at + bx, p.y->l[j][0], p.y->l[j][1], bx, p.y1 + j * bx);
  }
  // x: C_x y1 + L_x y2 (linear: L_x y1), sixteen samples at a time over their band of vertices.
  const XBands& bands = *p.x;
  for (std::size_t j = 0; j < p.ny; ++j) {
    double* row = out + j * nx;
    for (std::size_t q = 0; q < bands.first.size(); ++q) {
      const std::size_t first = bands.first[q], span = bands.span[q];
      PassLanes c0{}, c1{}, l0{}, l1{};
      bandSum(p.y1 + j * bx + first, bands.c.data() + bands.offset[q], span, c0, c1);
      if (cubic) bandSum(p.y2 + j * bx + first, bands.l.data() + bands.offset[q], span, l0, l1);
      const PassLanes sum = (c0 + c1) + (l0 + l1);
      Pass lanes[kLanes];
      std::memcpy(lanes, &sum, sizeof lanes);
      const std::size_t count = std::min(kLanes, nx - q * kLanes);
      double* __restrict samples = row + q * kLanes;
      for (std::size_t lane = 0; lane < count; ++lane) samples[lane] += weight * double(lanes[lane]);
    }
  }
}

void separable(const Level& level, const TimeCollapse& time, bool cubic, const VertexBox& box,
               const std::array<std::vector<AxisCell>, kSpace>& cells, int threads, Totals& total) {
  const std::size_t nx = cells[0].size(), ny = cells[1].size(), nz = cells[2].size();
  const std::size_t bx = std::size_t(box.size[0]), by = std::size_t(box.size[1]);
  const auto share = boxShares(level, box);
  const XBands bands = xBands(cells[0], box.lo[0], cubic);
  const AxisTaps ty = axisTaps(cells[1], box.lo[1]);
  const AxisTaps tz = axisTaps(cells[2], box.lo[2]);
  parallelFor(nz, threads, 1, [&](std::size_t begin, std::size_t end) {
    LayerCache layers(level, time, cubic, box, share);
    std::vector<Pass> scratch(2 * bx * by + 2 * bx * ny);
    LayerPasses passes;
    passes.bx = bx;
    passes.by = by;
    passes.nx = nx;
    passes.ny = ny;
    passes.y = &ty;
    passes.x = &bands;
    passes.q1 = scratch.data();
    passes.q2 = passes.q1 + bx * by;
    passes.y1 = passes.q2 + bx * by;
    passes.y2 = passes.y1 + bx * ny;
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t z = tz.at[k];
      for (int a = 0; a < kAxes; ++a) {
        std::array<const Pass*, 4> g{}, e{};
        for (int step = 0; step < 4; ++step) {
          // Linear interpolation reads the layers at the steps 0 and +1 only.
          if (!cubic && (step == 0 || step == 3)) continue;
          g[std::size_t(step)] = layers.layer(z + std::size_t(step) - 1, a, 0);
          if (cubic && (step == 1 || step == 2)) e[std::size_t(step)] = layers.layer(z + std::size_t(step) - 1, a, 1);
        }
        layerPasses(passes, cubic, g, e, tz.h[k], tz.d[k], tz.l[k], level.weight, total[a].data() + nx * ny * k);
      }
    }
  });
}

}  // namespace

void fieldStepDisplace(const FractalField& field, std::vector<Vec3>& nodes, const std::vector<unsigned char>& mask,
                       double t, int threads) {
  const FractalFieldParams& p = field.params();
  const bool cubic = p.interpolation == FieldInterpolation::Cubic;
  const int workers = resolveThreadCount(threads);
  std::vector<std::size_t> selected;
  const bool everyNode = std::find(mask.begin(), mask.end(), 0) == mask.end();
  if (everyNode) {
    selected.resize(nodes.size());
    std::iota(selected.begin(), selected.end(), std::size_t(0));
  } else {
    for (std::size_t n = 0; n < nodes.size(); ++n)
      if (mask[n]) selected.push_back(n);
  }
  if (selected.empty()) return;

  // The sample points s = (q + ∫₀ᵗ wind, t), wrapped (Colonna §3.2).
  const Vec3 shift = p.windShift(t);
  const auto sampleOf = [&](const Vec3& q) {
    const FieldPoint s = field.wrapped({q.x + shift.x, q.y + shift.y, q.z + shift.z, t});
    return Vec3{s[0], s[1], s[2]};
  };
  const double time = field.wrapped({0.0, 0.0, 0.0, t})[3];
  TensorGrid grid;
  // Nodes that are not finite (a previous op blew up) keep the per-node path: no box holds them.
  // A tensor grid's nodes are finite when its coordinates are (NaN never passes its test).
  const auto finiteCoordinates = [&] {
    for (int d = 0; d < kSpace; ++d)
      for (double coordinate : grid.coordinate[d])
        if (!std::isfinite(coordinate)) return false;
    return true;
  };
  const bool tensor = everyNode && findTensorGrid(nodes, grid) && finiteCoordinates();
  bool finite = tensor;
  if (!tensor) {
    finite = true;
    for (std::size_t n : selected)
      if (!std::isfinite(nodes[n].x) || !std::isfinite(nodes[n].y) || !std::isfinite(nodes[n].z)) finite = false;
  }
  std::array<std::vector<double>, kSpace> axisSamples;  // tensor grids: the samples per dimension
  if (tensor)
    for (int d = 0; d < kSpace; ++d)
      for (double coordinate : grid.coordinate[d]) {
        Vec3 q{0.0, 0.0, 0.0};
        q[d] = coordinate;
        axisSamples[d].push_back(sampleOf(q)[d]);
      }
  // Tensor grids read their samples per grid line (axisSamples); other nodes one by one.
  std::vector<Vec3> samples(tensor ? 0 : selected.size());
  if (!tensor)
    parallelFor(selected.size(), workers, 4096, [&](std::size_t begin, std::size_t end) {
      for (std::size_t n = begin; n < end; ++n) samples[n] = sampleOf(nodes[selected[n]]);
    });

  Totals total;
  for (std::vector<double>& axis : total) axis.assign(selected.size(), 0.0);
  CollapsedMesh mesh;
  for (int k = 0; k < field.levelCount(); ++k) {
    const Level& level = field.level(k);
    const TimeCollapse collapsed = timeCollapse(level, time, cubic);
    BoxBuilder bounds;
    std::array<std::vector<AxisCell>, kSpace> axisCells;
    if (tensor) {
      for (int d = 0; d < kSpace; ++d)
        for (double s : axisSamples[d]) {
          axisCells[d].push_back(axisCell(s, level.offset[d], level.cell[d]));
          bounds.add(d, axisCells[d].back().base);
        }
    } else {
      for (const Vec3& s : samples) {
        const NodeCell cell = nodeCell(level, s);
        for (int d = 0; d < kSpace; ++d) bounds.add(d, cell.base[d]);
      }
    }
    const bool fits = finite && bounds.fits();
    const VertexBox box = fits ? bounds.box() : VertexBox{};
    // Collapse the box when that hashes a quarter or less of the vertices hashing each node's
    // own would: per node, the hashes and the interpolation are one vector loop, while the box's
    // collapse and passes cost several times more per hash (measured on a 32³ grid, 8 octaves).
    const std::size_t boxHashes = box.count() * (cubic ? 4 : 2);
    const std::size_t nodeHashes = selected.size() * std::size_t(cubic ? kCubicVertices : kLinearVertices);
    if (fits && 4 * boxHashes <= nodeHashes) {
      if (tensor) {
        separable(level, collapsed, cubic, box, axisCells, workers, total);
      } else {
        collapse(level, collapsed, cubic, box, workers, mesh);
        parallelFor(selected.size(), workers, 512, [&](std::size_t begin, std::size_t end) {
          for (std::size_t n = begin; n < end; ++n) {
            double v[kAxes];
            readCollapsed(mesh, cubic, nodeCell(level, samples[n]), v);
            for (int a = 0; a < kAxes; ++a) total[a][n] += level.weight * v[a];
          }
        });
      }
    } else {
      // Tensor grids: the cells along each dimension, found once per grid line.
      // Along x also node-minor, so a block inside one grid row copies its x cells whole.
      std::array<std::vector<SampleCell>, kSpace> lineCells;
      std::array<std::vector<std::uint32_t>, 4> xShares;
      std::vector<double> xU;
      if (tensor) {
        for (int d = 0; d < kSpace; ++d)
          for (const AxisCell& c : axisCells[d]) lineCells[d].push_back(sampleCell(level, d, c));
        for (const SampleCell& c : lineCells[0]) {
          for (int step = 0; step < 4; ++step) xShares[std::size_t(step)].push_back(c.share[std::size_t(step)]);
          xU.push_back(c.u);
        }
      }
      parallelFor((selected.size() + kBlock - 1) / kBlock, workers, 16, [&](std::size_t begin, std::size_t end) {
        BlockScratch scratch;
        const std::size_t nx = tensor ? lineCells[0].size() : 1, ny = tensor ? lineCells[1].size() : 1;
        for (std::size_t b = begin; b < end; ++b) {
          const std::size_t first = b * kBlock;
          const std::size_t count = std::min(kBlock, selected.size() - first);
          const std::size_t row = first % nx;
          const bool sharedYz = tensor && count == kBlock && row + kBlock <= nx;
          if (sharedYz) {
            // A whole block inside one grid row: its x cells are consecutive, y and z one each.
            const SampleCell& y = lineCells[1][(first / nx) % ny];
            const SampleCell& z = lineCells[2][first / (nx * ny)];
            // (A shared block's y and z are read from node 0 only.)
            for (int step = 0; step < 4; ++step) {
              std::copy_n(xShares[std::size_t(step)].data() + row, kBlock, scratch.share[0][step].data());
              scratch.share[1][step][0] = y.share[std::size_t(step)];
              scratch.share[2][step][0] = z.share[std::size_t(step)];
            }
            std::copy_n(xU.data() + row, kBlock, scratch.u[0].data());
            scratch.u[1][0] = y.u;
            scratch.u[2][0] = z.u;
          } else if (tensor) {
            // The block's grid position found once and stepped, not divided out per node.
            std::size_t i = row, j = (first / nx) % ny, k = first / (nx * ny);
            for (std::size_t n = 0; n < kBlock; ++n) {
              putNode(n, lineCells[0][i], lineCells[1][j], lineCells[2][k], scratch);
              if (n + 1 < count && ++i == nx) {
                i = 0;
                if (++j == ny) {
                  j = 0;
                  ++k;
                }
              }
            }
          } else {
            for (std::size_t n = 0; n < kBlock; ++n) {
              const Vec3& q = samples[first + std::min(n, count - 1)];
              putNode(n, sampleCell(level, 0, axisCell(q[0], level.offset[0], level.cell[0])),
                      sampleCell(level, 1, axisCell(q[1], level.offset[1], level.cell[1])),
                      sampleCell(level, 2, axisCell(q[2], level.offset[2], level.cell[2])), scratch);
            }
          }
          hashDirect(level, collapsed, cubic, count, sharedYz, scratch,
                     {total[0].data() + first, total[1].data() + first, total[2].data() + first});
        }
      });
    }
  }
  if (everyNode) {
    for (std::size_t n = 0; n < nodes.size(); ++n) {
      nodes[n].x += p.amplitude.x * total[0][n];
      nodes[n].y += p.amplitude.y * total[1][n];
      nodes[n].z += p.amplitude.z * total[2][n];
    }
    return;
  }
  for (std::size_t n = 0; n < selected.size(); ++n)
    nodes[selected[n]] += p.amplitude * Vec3{total[0][n], total[1][n], total[2][n]};
}

}  // namespace gridifs
