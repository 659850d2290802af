#include "model/field_step.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "base/parallel.h"
#include "model/field_lattice.h"
#include "model/fractal_field.h"

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

// The time dimension of one level at t. By linearity of hermite() in its values and slopes, the
// appendix's last (time) reduction hermite(V0, V1, S0, S1, u) splits into the spatial reduction
// of g = value0·f(t0) + value1·f(t1) plus the trilinear interpolation of the time slopes
// e = slope0·(f(t1) − f(t−1))/2 + slope1·(f(t2) − f(t0))/2 (central differences, as the
// appendix takes them). Linear interpolation: g = (1 − u)·f(t0) + u·f(t1), no e.
struct TimeCollapse {
  std::array<std::uint32_t, 4> index{};  // hash shares of the time steps −1, 0, +1, +2
  double value0 = 0.0, value1 = 0.0, slope0 = 0.0, slope1 = 0.0;
};

TimeCollapse timeCollapse(const Level& level, double t, bool cubic) {
  TimeCollapse c;
  const AxisCell cell = axisCell(t, level.offset[3], level.cell[3]);
  for (int step = 0; step < 4; ++step) c.index[step] = indexContribution(cell.base + step - 1, level.wrap[3], 3);
  const double u = cell.u;
  if (cubic) {
    // The Hermite basis of hermite(): value0·f0 + value1·f1 + slope0·d0 + slope1·d1.
    const double u2 = u * u;
    const double u3 = u2 * u;
    c.value0 = 2.0 * u3 - 3.0 * u2 + 1.0;
    c.value1 = 3.0 * u2 - 2.0 * u3;
    c.slope0 = u3 - 2.0 * u2 + u;
    c.slope1 = u3 - u2;
  } else {
    c.value0 = 1.0 - u;
    c.value1 = u;
  }
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

// Scratch for collapsing rows of a box (kept for callers that reuse it along their rows).
struct RowScratch {};

// g (and e, cubic) of one box row for the three axes: vertex i of the row has the hash input
// share[i] + rowShare + the time step's share. The three axes take two hashes per vertex and time
// step, as in hashAndSum below; the values are randomFromSum's, collapsed in time as
// TimeCollapse says, in one vector loop over the row.
template <bool Cubic, bool OddSeed>
GRIDIFS_FIELD_VECTOR_CLONES
void collapseHashes(const std::uint32_t* share, std::size_t width, std::uint32_t rowShare, const TimeCollapse& time,
                    std::uint32_t firstPairKey, std::uint32_t secondPairKey, double* g0, double* g1, double* g2,
                    double* e0, double* e1, double* e2) {
  using field_lattice::mix32;
  using field_lattice::randomHalf;
  constexpr double scale = field_lattice::kRandomScale;
  constexpr int kSteps = Cubic ? 4 : 2;
  constexpr int kFirst = Cubic ? 0 : 1;
  std::uint32_t times[kSteps];
  for (int step = 0; step < kSteps; ++step) times[step] = rowShare + time.index[std::size_t(kFirst + step)];
  const double v0 = time.value0, v1 = time.value1, s0 = time.slope0, s1 = time.slope1;
  // In chunks along the row, one time step at a time, so every loop runs over the row's vertices.
  constexpr std::size_t kChunk = 64;
  double f[kSteps][kAxes][kChunk];
  for (std::size_t begin = 0; begin < width; begin += kChunk) {
    const std::size_t count = std::min(kChunk, width - begin);
    const std::uint32_t* row = share + begin;
    for (int step = 0; step < kSteps; ++step)
      for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t index = row[i] + times[step];
        const std::uint32_t first = mix32(index + firstPairKey);
        const std::uint32_t second = mix32(index + secondPairKey);
        f[step][0][i] = double(OddSeed ? randomHalf(first, 16) : randomHalf(first, 0)) * scale;
        f[step][1][i] = double(OddSeed ? randomHalf(second, 0) : randomHalf(first, 16)) * scale;
        f[step][2][i] = double(OddSeed ? randomHalf(second, 16) : randomHalf(second, 0)) * scale;
      }
    double* g[kAxes] = {g0 + begin, g1 + begin, g2 + begin};
    double* e[kAxes] = {e0 + begin, e1 + begin, e2 + begin};
    for (int a = 0; a < kAxes; ++a) {
      if constexpr (Cubic) {
        for (std::size_t i = 0; i < count; ++i) {
          g[a][i] = v0 * f[1][a][i] + v1 * f[2][a][i];
          e[a][i] = s0 * (0.5 * (f[2][a][i] - f[0][a][i])) + s1 * (0.5 * (f[3][a][i] - f[1][a][i]));
        }
      } else {
        for (std::size_t i = 0; i < count; ++i) g[a][i] = v0 * f[0][a][i] + v1 * f[1][a][i];
      }
    }
  }
}

// g (and e, cubic) of the box row (j, k) for the three axes into g[a][0..width), e[a][0..width).
void collapseRow(const Level& level, const TimeCollapse& time, bool cubic,
                 const std::array<std::vector<std::uint32_t>, kSpace>& share, std::size_t j, std::size_t k,
                 RowScratch&, const std::array<double*, kAxes>& g, const std::array<double*, kAxes>& e) {
  const std::size_t width = share[0].size();
  const std::uint32_t rowShare = share[1][j] + share[2][k];
  // Axes 0 and 2 lie in consecutive seed pairs; axis 0's half says which case this is.
  const bool odd = level.shifts[0] != 0;
  const auto run = [&](auto kernel) {
    kernel(share[0].data(), width, rowShare, time, level.keys[0], level.keys[2], g[0], g[1], g[2], e[0], e[1], e[2]);
  };
  if (cubic)
    odd ? run(collapseHashes<true, true>) : run(collapseHashes<true, false>);
  else
    odd ? run(collapseHashes<false, true>) : run(collapseHashes<false, false>);
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
    RowScratch scratch;
    for (std::size_t row = begin; row < end; ++row) {
      std::array<double*, kAxes> g{}, e{};
      for (int a = 0; a < kAxes; ++a) {
        g[a] = mesh.g[a].data() + row * width;
        e[a] = cubic ? mesh.e[a].data() + row * width : nullptr;
      }
      collapseRow(level, time, cubic, share, row % std::size_t(box.size[1]), row / std::size_t(box.size[1]), scratch, g,
                  e);
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
  std::vector<double> weight = std::vector<double>(kBlock * kCubicVertices);  // [vertex][node]
  std::array<std::array<double, kBlock>, kAxes> out{};
};

// The weight of each hashed vertex (in the order of kCubicSteps or kLinearSteps) in a node's
// value, times RDN's integer scale. Cubic, for corner c with bits (bx, by, bz): its value
// weighs hv(bx)·hv(by)·hv(bz), its slope along x hs(bx)·hv(by)·hv(bz), along y
// l(bx)·hs(by)·hv(bz), along z l(bx)·l(by)·hs(bz), its time slope l(bx)·l(by)·l(bz), with
// hv, hs the Hermite value and slope bases of hermite() and l the linear one; the slopes are
// the central differences of pseudoCubic(), the collapsed values and time slopes those of
// TimeCollapse. Each product is taken as x-factor · (y-factor · z-factor), so a block whose
// nodes share their y and z cells (a row of a tensor grid: SharedYz) forms the y·z products once
// and gets the same bits as any other block. The slope bases carry the central differences'
// 1/2 (exact), so a slope's share in a corner is one addition. Built without fused
// multiply-adds like every clone.
template <bool SharedYz>
GRIDIFS_FIELD_VECTOR_CLONES
void blockWeights(bool cubic, const TimeCollapse& time, const std::array<std::array<double, kBlock>, kSpace>& u,
                  double* weight) {
  constexpr double scale = field_lattice::kRandomScale;
  constexpr std::size_t kYz = SharedYz ? 1 : kBlock;  // y·z products per block
  const auto at = [&](int vertex) { return weight + std::size_t(vertex) * kBlock; };
  const auto yzAt = [](std::size_t n) { return SharedYz ? std::size_t(0) : n; };
  // The one-dimensional bases: l, and (cubic) hv and hs/2, per dimension, side and node.
  double lin[kSpace][2][kBlock], hv[kSpace][2][kBlock], hs[kSpace][2][kBlock];
  for (int d = 0; d < kSpace; ++d) {
    const std::size_t nodes = d == 0 ? kBlock : kYz;
    for (std::size_t n = 0; n < nodes; ++n) {
      const double x = u[d][n], x2 = x * x, x3 = x2 * x;
      lin[d][0][n] = 1.0 - x;
      lin[d][1][n] = x;
      hv[d][0][n] = 2.0 * x3 - 3.0 * x2 + 1.0;
      hv[d][1][n] = 3.0 * x2 - 2.0 * x3;
      hs[d][0][n] = 0.5 * (x3 - 2.0 * x2 + x);
      hs[d][1][n] = 0.5 * (x3 - x2);
    }
  }
  // Per (by, bz): the y·z factors of a corner's value (and x slope), y slope, z slope, time slope.
  double yzValue[4][kYz], yzSlopeY[4][kYz], yzSlopeZ[4][kYz], yzLinear[4][kYz];
  for (int q = 0; q < 4; ++q) {
    const int by = q & 1, bz = q >> 1;
    for (std::size_t n = 0; n < kYz; ++n) {
      yzValue[q][n] = hv[1][by][n] * hv[2][bz][n];
      yzSlopeY[q][n] = hs[1][by][n] * hv[2][bz][n];
      yzSlopeZ[q][n] = lin[1][by][n] * hs[2][bz][n];
      yzLinear[q][n] = lin[1][by][n] * lin[2][bz][n];
    }
  }
  if (!cubic) {
    const double v0 = time.value0 * scale, v1 = time.value1 * scale;
    for (int c = 0; c < kCorners; ++c) {
      const int bx = c & 1, q = c >> 1;
      double* w0 = at(c * 2);
      double* w1 = at(c * 2 + 1);
      for (std::size_t n = 0; n < kBlock; ++n) {
        const double l = lin[0][bx][n] * yzLinear[q][yzAt(n)];
        w0[n] = v0 * l;
        w1[n] = v1 * l;
      }
    }
    return;
  }
  // Per corner: the weight of its value, of its half slope along each dimension, of its time slope.
  double value[kCorners][kBlock], slope[kCorners][kSpace][kBlock], timeSlope[kCorners][kBlock];
  for (int c = 0; c < kCorners; ++c) {
    const int bx = c & 1, q = c >> 1;
    for (std::size_t n = 0; n < kBlock; ++n) {
      const std::size_t m = yzAt(n);
      value[c][n] = hv[0][bx][n] * yzValue[q][m];
      slope[c][0][n] = hs[0][bx][n] * yzValue[q][m];
      slope[c][1][n] = lin[0][bx][n] * yzSlopeY[q][m];
      slope[c][2][n] = lin[0][bx][n] * yzSlopeZ[q][m];
      timeSlope[c][n] = lin[0][bx][n] * yzLinear[q][m];
    }
  }
  // A corner's slope along d is (beyond − partner)/2 at an upper corner, (partner − beyond)/2 at
  // a lower one: it weighs its outward neighbour and the partner corner across the cell.
  const double v0 = time.value0 * scale, v1 = time.value1 * scale;
  const double s0 = 0.5 * time.slope0 * scale, s1 = 0.5 * time.slope1 * scale;
  for (int c = 0; c < kCorners; ++c) {
    double corner[kBlock];
    for (std::size_t n = 0; n < kBlock; ++n) corner[n] = value[c][n];
    for (int d = 0; d < kSpace; ++d) {
      const int partner = c ^ (1 << d);
      const bool upper = (c >> d) & 1;
      // This corner's share in its partner's slope, and its outward neighbour's in its own.
      if (upper)
        for (std::size_t n = 0; n < kBlock; ++n) corner[n] = corner[n] + slope[partner][d][n];
      else
        for (std::size_t n = 0; n < kBlock; ++n) corner[n] = corner[n] - slope[partner][d][n];
      double* o0 = at(kCorners * 4 + (c * kSpace + d) * 2);
      double* o1 = at(kCorners * 4 + (c * kSpace + d) * 2 + 1);
      const double outward0 = upper ? v0 : -v0, outward1 = upper ? v1 : -v1;
      for (std::size_t n = 0; n < kBlock; ++n) {
        o0[n] = outward0 * slope[c][d][n];
        o1[n] = outward1 * slope[c][d][n];
      }
    }
    double* fm = at(c * 4);
    double* f0 = at(c * 4 + 1);
    double* f1 = at(c * 4 + 2);
    double* f2 = at(c * 4 + 3);
    for (std::size_t n = 0; n < kBlock; ++n) {
      const double e = timeSlope[c][n];
      fm[n] = -(s0 * e);
      f0[n] = v0 * corner[n] - s1 * e;
      f1[n] = v1 * corner[n] + s0 * e;
      f2[n] = s1 * e;
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

template <bool OddSeed>
GRIDIFS_FIELD_VECTOR_CLONES GRIDIFS_NO_UNROLL_AND_JAM
void hashAndSum(const VertexSteps* vertices, int count, const BlockScratch& in, const std::array<std::uint32_t, 4>& times,
                std::uint32_t firstPairKey, std::uint32_t secondPairKey,
                std::array<std::array<double, kBlock>, kAxes>& out) {
  using field_lattice::mix32;
  using field_lattice::randomHalf;
  double sum[kAxes][kBlock] = {};
  for (int v = 0; v < count; ++v) {
    const VertexSteps& s = vertices[v];
    const std::uint32_t* x = in.share[0][s.step[0]].data();
    const std::uint32_t* y = in.share[1][s.step[1]].data();
    const std::uint32_t* z = in.share[2][s.step[2]].data();
    const std::uint32_t t = times[s.step[3]];
    const double* w = in.weight.data() + std::size_t(v) * kBlock;
    for (std::size_t n = 0; n < kBlock; ++n) {
      const std::uint32_t index = x[n] + y[n] + z[n] + t;
      const std::uint32_t first = mix32(index + firstPairKey);
      const std::uint32_t second = mix32(index + secondPairKey);
      const std::int32_t a0 = OddSeed ? randomHalf(first, 16) : randomHalf(first, 0);
      const std::int32_t a1 = OddSeed ? randomHalf(second, 0) : randomHalf(first, 16);
      const std::int32_t a2 = OddSeed ? randomHalf(second, 16) : randomHalf(second, 0);
      sum[0][n] += w[n] * double(a0);
      sum[1][n] += w[n] * double(a1);
      sum[2][n] += w[n] * double(a2);
    }
  }
  for (int a = 0; a < kAxes; ++a)
    for (std::size_t n = 0; n < kBlock; ++n) out[a][n] = sum[a][n];
}

void hashAndSum(const VertexSteps* vertices, int count, const BlockScratch& in, const std::array<std::uint32_t, 4>& times,
                const Level& level, std::array<std::array<double, kBlock>, kAxes>& out) {
  // Axes 0 and 2 lie in consecutive seed pairs; axis 0's half says which case this is.
  if (level.shifts[0] != 0)
    hashAndSum<true>(vertices, count, in, times, level.keys[0], level.keys[2], out);
  else
    hashAndSum<false>(vertices, count, in, times, level.keys[0], level.keys[2], out);
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
  for (int step = 0; step < 4; ++step) c.share[std::size_t(step)] = indexContribution(cell.base + step - 1, level.wrap[d], d);
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
                BlockScratch& scratch, Vec3* total) {
  if (sharedYz)
    blockWeights<true>(cubic, time, scratch.u, scratch.weight.data());
  else
    blockWeights<false>(cubic, time, scratch.u, scratch.weight.data());
  if (cubic)
    hashAndSum(kCubicSteps.data(), kCubicVertices, scratch, time.index, level, scratch.out);
  else
    hashAndSum(kLinearSteps.data(), kLinearVertices, scratch, time.index, level, scratch.out);
  for (std::size_t n = 0; n < count; ++n)
    total[n] += level.weight * Vec3{scratch.out[0][n], scratch.out[1][n], scratch.out[2][n]};
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
  std::size_t m = 0;
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i, ++m)
        if (nodes[m].x != grid.coordinate[0][i] || nodes[m].y != grid.coordinate[1][j] ||
            nodes[m].z != grid.coordinate[2][k])
          return false;
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
// are applied in the order that keeps every step a weighted sum of contiguous rows: z first over
// whole layers of the box, then x over the rows of each layer, then (after a transpose of the
// small intermediate) y over rows of samples, which lands in the grid's node order.

// Per sample along one dimension: its lower box vertex and the weights of the four vertices
// around it (steps −1, 0, +1, +2) in C, D, H and L.
struct AxisTaps {
  std::vector<std::size_t> at;             // the lower vertex of the sample's cell, in box indices
  std::vector<std::array<double, 4>> c, d;  // Catmull-Rom, and its slope part
  std::vector<std::array<double, 2>> h, l;  // Hermite value part, linear (steps 0, +1)
};

AxisTaps axisTaps(const std::vector<AxisCell>& cells, std::int64_t lo) {
  AxisTaps taps;
  for (const AxisCell& cell : cells) {
    const double u = cell.u, u2 = u * u, u3 = u2 * u;
    const double hv0 = 2.0 * u3 - 3.0 * u2 + 1.0, hv1 = 3.0 * u2 - 2.0 * u3;
    // hermite()'s slope terms hs0·d0 + hs1·d1 with d0 = (f1 − f−1)/2, d1 = (f2 − f0)/2.
    const double hs0 = 0.5 * (u3 - 2.0 * u2 + u), hs1 = 0.5 * (u3 - u2);
    taps.at.push_back(std::size_t(cell.base - lo));
    taps.d.push_back({-hs0, -hs1, hs0, hs1});
    taps.c.push_back({-hs0, hv0 - hs1, hv1 + hs0, hs1});
    taps.h.push_back({hv0, hv1});
    taps.l.push_back({1.0 - u, u});
  }
  return taps;
}

// One axis of one sample layer of a tensor grid: the three passes over the collapsed layers
// around it. g[0..3], e[0..3]: the box layers at the steps −1, 0, +1, +2 along z from the sample's
// cell ([i][j], y fastest; e unused when linear); out: the values of the layer's nodes, [j][i].
struct LayerPasses {
  std::size_t bx = 0, by = 0, nx = 0, ny = 0;
  const AxisTaps* x = nullptr;
  const AxisTaps* y = nullptr;
  // Scratch: q1, q2 per box layer; x1..x3 per [sample i][j]; t1..t3 their transposes.
  double *q1 = nullptr, *q2 = nullptr, *x1 = nullptr, *x2 = nullptr, *x3 = nullptr, *t1 = nullptr, *t2 = nullptr,
         *t3 = nullptr;
};

GRIDIFS_FIELD_VECTOR_CLONES
void layerPasses(const LayerPasses& p, bool cubic, const std::array<const double*, 4>& g,
                 const std::array<const double*, 4>& e, const std::array<double, 2>& zh, const std::array<double, 4>& zd,
                 const std::array<double, 2>& zl, double* out) {
  const std::size_t layer = p.bx * p.by, by = p.by, nx = p.nx;
  if (!cubic) {
    // L_y L_x L_z g.
    {
      const double l0 = zl[0], l1 = zl[1];
      const double* __restrict g0 = g[1];
      const double* __restrict g1 = g[2];
      double* __restrict q1 = p.q1;
      for (std::size_t n = 0; n < layer; ++n) q1[n] = l0 * g0[n] + l1 * g1[n];
    }
    for (std::size_t i = 0; i < nx; ++i) {
      const double* __restrict r = p.q1 + p.x->at[i] * by;
      const double l0 = p.x->l[i][0], l1 = p.x->l[i][1];
      double* __restrict x1 = p.x1 + i * by;
      for (std::size_t j = 0; j < by; ++j) x1[j] = l0 * r[j] + l1 * r[by + j];
    }
    {
      const double* __restrict x1 = p.x1;
      double* __restrict t1 = p.t1;
      for (std::size_t i = 0; i < nx; ++i)
        for (std::size_t j = 0; j < by; ++j) t1[j * nx + i] = x1[i * by + j];
    }
    for (std::size_t j = 0; j < p.ny; ++j) {
      const double* __restrict r = p.t1 + p.y->at[j] * nx;
      const double l0 = p.y->l[j][0], l1 = p.y->l[j][1];
      double* __restrict row = out + j * nx;
      for (std::size_t i = 0; i < nx; ++i) row[i] = l0 * r[i] + l1 * r[nx + i];
    }
    return;
  }
  // z: q1 = H_z g, q2 = D_z g + L_z e. (Weights in locals and restrict pointers: the vectorizer
  // must see that no store changes them.)
  {
    const double h0 = zh[0], h1 = zh[1], d0 = zd[0], d1 = zd[1], d2 = zd[2], d3 = zd[3], l0 = zl[0], l1 = zl[1];
    const double* __restrict gm = g[0];
    const double* __restrict g0 = g[1];
    const double* __restrict g1 = g[2];
    const double* __restrict g2 = g[3];
    const double* __restrict e0 = e[1];
    const double* __restrict e1 = e[2];
    double* __restrict q1 = p.q1;
    double* __restrict q2 = p.q2;
    for (std::size_t n = 0; n < layer; ++n) {
      q1[n] = h0 * g0[n] + h1 * g1[n];
      q2[n] = ((d0 * gm[n] + d1 * g0[n]) + (d2 * g1[n] + d3 * g2[n])) + (l0 * e0[n] + l1 * e1[n]);
    }
  }
  // x: x1 = C_x q1, x2 = L_x q1, x3 = L_x q2, per sample i along the layer's rows.
  for (std::size_t i = 0; i < nx; ++i) {
    const std::size_t at = p.x->at[i] * by;
    const double* __restrict a = p.q1 + at;
    const double* __restrict b = p.q2 + at;
    const double c0 = p.x->c[i][0], c1 = p.x->c[i][1], c2 = p.x->c[i][2], c3 = p.x->c[i][3];
    const double l0 = p.x->l[i][0], l1 = p.x->l[i][1];
    double* __restrict x1 = p.x1 + i * by;
    double* __restrict x2 = p.x2 + i * by;
    double* __restrict x3 = p.x3 + i * by;
    for (std::size_t j = 0; j < by; ++j) {
      x1[j] = (c0 * a[j - by] + c1 * a[j]) + (c2 * a[by + j] + c3 * a[2 * by + j]);
      x2[j] = l0 * a[j] + l1 * a[by + j];
      x3[j] = l0 * b[j] + l1 * b[by + j];
    }
  }
  {
    const double* __restrict x1 = p.x1;
    const double* __restrict x2 = p.x2;
    const double* __restrict x3 = p.x3;
    double* __restrict t1 = p.t1;
    double* __restrict t2 = p.t2;
    double* __restrict t3 = p.t3;
    for (std::size_t i = 0; i < nx; ++i)
      for (std::size_t j = 0; j < by; ++j) {
        t1[j * nx + i] = x1[i * by + j];
        t2[j * nx + i] = x2[i * by + j];
        t3[j * nx + i] = x3[i * by + j];
      }
  }
  // y: H_y x1 + D_y x2 + L_y x3, per sample j along rows of samples i.
  for (std::size_t j = 0; j < p.ny; ++j) {
    const std::size_t at = p.y->at[j] * nx;
    const double* __restrict a = p.t1 + at;
    const double* __restrict b = p.t2 + at;
    const double* __restrict c = p.t3 + at;
    const double h0 = p.y->h[j][0], h1 = p.y->h[j][1];
    const double d0 = p.y->d[j][0], d1 = p.y->d[j][1], d2 = p.y->d[j][2], d3 = p.y->d[j][3];
    const double l0 = p.y->l[j][0], l1 = p.y->l[j][1];
    double* __restrict row = out + j * nx;
    for (std::size_t i = 0; i < nx; ++i)
      row[i] = ((h0 * a[i] + h1 * a[nx + i]) + ((d0 * b[i - nx] + d1 * b[i]) + (d2 * b[nx + i] + d3 * b[2 * nx + i]))) +
               (l0 * c[i] + l1 * c[nx + i]);
  }
}

// The collapsed layers (constant z) of one level's box, computed when first asked for and kept
// while the samples along z still need them (a few at a time: the samples' cells move upward).
class LayerCache {
 public:
  LayerCache(const Level& level, const TimeCollapse& time, bool cubic, const VertexBox& box,
             const std::array<std::vector<std::uint32_t>, kSpace>& share)
      : level_(level), time_(time), cubic_(cubic), box_(box),
        // collapseRow works along its first dimension's shares; a layer is wanted along y, so
        // its rows are the box's columns: the same vertices and sums, the shares swapped.
        columnShare_{share[1], share[0], share[2]},
        layerSize_(std::size_t(box.size[0] * box.size[1])) {}

  // g (quantity 0) or e (quantity 1) of axis a on layer k, in [i][j] order (y fastest).
  const double* layer(std::size_t k, int a, int quantity) {
    Slot& slot = find(k);
    return slot.values.data() + (std::size_t(quantity) * kAxes + std::size_t(a)) * layerSize_;
  }

 private:
  struct Slot {
    std::int64_t k = -1;
    std::uint64_t used = 0;
    std::vector<double> values;  // [quantity][axis][i][j]
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
    for (std::size_t i = 0; i < bx; ++i) {
      std::array<double*, kAxes> g{}, e{};
      for (int a = 0; a < kAxes; ++a) {
        g[a] = slot.values.data() + std::size_t(a) * layerSize_ + i * by;
        e[a] = cubic_ ? slot.values.data() + (kAxes + std::size_t(a)) * layerSize_ + i * by : nullptr;
      }
      collapseRow(level_, time_, cubic_, columnShare_, i, k, scratch_, g, e);
    }
  }

  const Level& level_;
  const TimeCollapse& time_;
  bool cubic_;
  VertexBox box_;
  std::array<std::vector<std::uint32_t>, kSpace> columnShare_;
  std::size_t layerSize_;
  std::array<Slot, kSlots> slots_{};
  std::uint64_t clock_ = 0;
  RowScratch scratch_;
};

void separable(const Level& level, const TimeCollapse& time, bool cubic, const VertexBox& box,
               const std::array<std::vector<AxisCell>, kSpace>& cells, int threads, std::vector<Vec3>& total) {
  const std::size_t nx = cells[0].size(), ny = cells[1].size(), nz = cells[2].size();
  const std::size_t bx = std::size_t(box.size[0]), by = std::size_t(box.size[1]);
  const auto share = boxShares(level, box);
  std::array<AxisTaps, kSpace> taps;
  for (int d = 0; d < kSpace; ++d) taps[d] = axisTaps(cells[d], box.lo[d]);
  parallelFor(nz, threads, 1, [&](std::size_t begin, std::size_t end) {
    LayerCache layers(level, time, cubic, box, share);
    std::vector<double> scratch(2 * bx * by + 6 * nx * by);
    LayerPasses passes;
    passes.bx = bx;
    passes.by = by;
    passes.nx = nx;
    passes.ny = ny;
    passes.x = &taps[0];
    passes.y = &taps[1];
    double* free = scratch.data();
    for (double** buffer : {&passes.q1, &passes.q2}) {
      *buffer = free;
      free += bx * by;
    }
    for (double** buffer : {&passes.x1, &passes.x2, &passes.x3, &passes.t1, &passes.t2, &passes.t3}) {
      *buffer = free;
      free += nx * by;
    }
    std::vector<double> value(kAxes * nx * ny);  // [axis][sample j][sample i]
    const AxisTaps& tz = taps[2];
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t z = tz.at[k];
      for (int a = 0; a < kAxes; ++a) {
        std::array<const double*, 4> g{}, e{};
        for (int step = 0; step < 4; ++step) {
          // Linear interpolation reads the layers at the steps 0 and +1 only.
          if (!cubic && (step == 0 || step == 3)) continue;
          g[std::size_t(step)] = layers.layer(z + std::size_t(step) - 1, a, 0);
          if (cubic && (step == 1 || step == 2)) e[std::size_t(step)] = layers.layer(z + std::size_t(step) - 1, a, 1);
        }
        layerPasses(passes, cubic, g, e, tz.h[k], tz.d[k], tz.l[k], value.data() + std::size_t(a) * nx * ny);
      }
      Vec3* layer = &total[nx * ny * k];
      for (std::size_t n = 0; n < nx * ny; ++n)
        layer[n] += level.weight * Vec3{value[n], value[nx * ny + n], value[2 * nx * ny + n]};
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
  selected.reserve(nodes.size());
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if (mask[n]) selected.push_back(n);
  if (selected.empty()) return;

  // The sample points s = (q + wind·t, t), wrapped (Colonna §3.2).
  const auto sampleOf = [&](const Vec3& q) {
    const FieldPoint s = field.wrapped({q.x + p.wind.x * t, q.y + p.wind.y * t, q.z + p.wind.z * t, t});
    return Vec3{s[0], s[1], s[2]};
  };
  const double time = field.wrapped({0.0, 0.0, 0.0, t})[3];
  TensorGrid grid;
  // Nodes that are not finite (a previous op blew up) keep the per-node path: no box holds them.
  bool finite = true;
  for (std::size_t n : selected)
    if (!std::isfinite(nodes[n].x) || !std::isfinite(nodes[n].y) || !std::isfinite(nodes[n].z)) finite = false;
  const bool tensor = finite && selected.size() == nodes.size() && findTensorGrid(nodes, grid);
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

  std::vector<Vec3> total(selected.size(), Vec3{0.0, 0.0, 0.0});
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
            total[n] += level.weight * Vec3{v[0], v[1], v[2]};
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
            for (int step = 0; step < 4; ++step) {
              std::copy_n(xShares[std::size_t(step)].data() + row, kBlock, scratch.share[0][step].data());
              scratch.share[1][step].fill(y.share[std::size_t(step)]);
              scratch.share[2][step].fill(z.share[std::size_t(step)]);
            }
            std::copy_n(xU.data() + row, kBlock, scratch.u[0].data());
            scratch.u[1].fill(y.u);
            scratch.u[2].fill(z.u);
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
          hashDirect(level, collapsed, cubic, count, sharedYz, scratch, &total[first]);
        }
      });
    }
  }
  for (std::size_t n = 0; n < selected.size(); ++n) nodes[selected[n]] += p.amplitude * total[n];
}

}  // namespace gridifs
