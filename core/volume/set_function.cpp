#include "volume/set_function.h"

#include <atomic>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <limits>
#include <nanoflann.hpp>
#include <thread>

#include "base/hash.h"
#include "base/parallel.h"

namespace gridifs {
namespace {

/// Lattice coordinates of a voxel set's voxels, as nanoflann reads them.
struct VoxelCloud {
  std::vector<float> xyz;  // 3 per voxel
  std::size_t kdtree_get_point_count() const { return xyz.size() / 3; }
  float kdtree_get_pt(std::size_t i, std::size_t d) const { return xyz[3 * i + d]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using VoxelTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, VoxelCloud>, VoxelCloud, 3, std::uint32_t>;

/// Nearest-voxel queries on a voxel set without a scan: a voxel of the set is its own nearest;
/// for any other voxel the nearest one lies on the set's boundary (a set voxel with a 6-neighbour
/// outside it: from an interior voxel, one step towards the query along its largest offset is
/// closer), so the k-d tree holds the boundary only, about N² voxels of a solid instead of N³.
struct NearestVoxel {
  std::vector<std::uint64_t> members;  // one bit per lattice voxel
  std::vector<std::uint32_t> boundary;
  VoxelCloud cloud;
  std::unique_ptr<VoxelTree> tree;

  bool contains(std::uint32_t v) const { return (members[v >> 6] >> (v & 63)) & 1u; }

  NearestVoxel(const VoxelSet& set, int threads) {
    const VoxelLattice& lattice = set.lattice;
    members.assign((lattice.voxelCount() + 63) / 64, 0);
    for (std::uint32_t v : set.voxels) members[v >> 6] |= std::uint64_t(1) << (v & 63);
    std::vector<std::uint8_t> onBoundary(set.size(), 0);
    const int last = lattice.n - 1;
    const std::uint32_t strideJ = std::uint32_t(lattice.n), strideK = strideJ * strideJ;
    parallelFor(set.size(), threads, 1 << 14, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        const std::uint32_t v = set.voxels[i];
        const Index3 c = lattice.coordinates(v);
        onBoundary[i] = c[0] == 0 || c[1] == 0 || c[2] == 0 || c[0] == last || c[1] == last || c[2] == last ||
                        !contains(v - 1) || !contains(v + 1) || !contains(v - strideJ) || !contains(v + strideJ) ||
                        !contains(v - strideK) || !contains(v + strideK);
      }
    });
    for (std::size_t i = 0; i < set.size(); ++i)
      if (onBoundary[i]) boundary.push_back(set.voxels[i]);
    cloud.xyz.resize(boundary.size() * 3);
    for (std::size_t b = 0; b < boundary.size(); ++b) {
      const Index3 c = lattice.coordinates(boundary[b]);
      for (int d = 0; d < 3; ++d) cloud.xyz[3 * b + std::size_t(d)] = float(c[std::size_t(d)]);
    }
    tree = std::make_unique<VoxelTree>(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  }
  /// The voxel of the set nearest to voxel `v` (whose lattice coordinates are `q`): of several
  /// at the same distance, the first in the tree's traversal order for q. `hint` is a boundary
  /// position from the previous query of the caller (or 0xFFFFFFFF): successive queries are
  /// neighbours, so its distance is a tight bound that prunes most of the tree. The bound only
  /// skips subtrees farther than the nearest voxel, so the answer does not depend on the hint,
  /// nor on how the queries are shared among threads.
  std::uint32_t nearest(std::uint32_t v, const float q[3], std::uint32_t& hint) const {
    if (contains(v)) return v;
    NearestResult result;
    if (hint < boundary.size()) {
      float d2 = 0.0f;
      for (int d = 0; d < 3; ++d) {
        const float e = q[d] - cloud.xyz[3 * hint + std::size_t(d)];
        d2 += e * e;
      }
      // Squared distances between lattice points are integers, exact in float up to 512³: half
      // a unit past the hint's distance admits a nearest voxel at that same distance.
      result.bound = d2 + 0.5f;
    }
    tree->findNeighbors(result, q, nanoflann::SearchParams());
    hint = result.index;
    return boundary[result.index];
  }

  /// nanoflann's result set for one neighbour, searched within `bound` until a first point is
  /// found; a later point replaces it only when strictly nearer (nanoflann's own rule).
  struct NearestResult {
    float bound = std::numeric_limits<float>::max();
    float best = std::numeric_limits<float>::max();
    std::uint32_t index = 0xFFFFFFFFu;
    bool full() const { return index != 0xFFFFFFFFu; }
    float worstDist() const { return full() ? best : bound; }
    bool addPoint(float d, std::uint32_t i) {
      if (d < best) {
        best = d;
        index = i;
      }
      return true;
    }
  };
};

constexpr std::uint32_t kUnknown = 0xFFFFFFFFu;

/// body(begin, end) over chunks of `grain` queries handed out in order to `threads` plain threads
/// (the caller is one). Measured on a loaded 2-core machine, oneTBB's worker joined the median's
/// query loops for about 5% of their time (perf), leaving the searches on the calling thread;
/// threads that take chunks from a counter share them evenly.
void chunkedLoop(std::size_t count, int threads, std::size_t grain,
                 const std::function<void(std::size_t, std::size_t)>& body) {
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    while (true) {
      const std::size_t begin = next.fetch_add(grain);
      if (begin >= count) return;
      body(begin, std::min(count, begin + grain));
    }
  };
  std::vector<std::thread> helpers;
  const std::size_t chunks = (count + grain - 1) / grain;
  for (std::size_t i = 1; i < std::min(std::size_t(std::max(threads, 1)), chunks); ++i) helpers.emplace_back(work);
  work();
  for (auto& t : helpers) t.join();
}

/// Marks voxel v; returns whether it was new.
inline bool mark(std::vector<std::uint64_t>& marks, std::uint32_t v) {
  std::uint64_t& word = marks[v >> 6];
  const std::uint64_t bit = std::uint64_t(1) << (v & 63);
  const bool fresh = !(word & bit);
  word |= bit;
  return fresh;
}

/// out = the distinct lattice voxels of `candidates` (kNone skipped); clears the marks again.
void collect(const std::vector<std::uint32_t>& candidates, SetScratch& scratch, VoxelSet& out) {
  constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  const std::size_t words = (out.lattice.voxelCount() + 63) / 64;
  if (scratch.marks.size() != words) scratch.marks.assign(words, 0);
  out.voxels.clear();
  for (std::uint32_t v : candidates)
    if (v != kNone && mark(scratch.marks, v)) out.voxels.push_back(v);
  for (std::uint32_t v : out.voxels) scratch.marks[v >> 6] = 0;
}

}  // namespace

struct SetFunction::Impl {
  enum class Kind { Median, Constant, PointMap } kind;
  VoxelSet set;
  double rotate = 0.0;
  Vec3 axis{0.0, 0.0, 1.0};               // unit length
  std::unique_ptr<NearestVoxel> nearest;  // median: the k-d tree of `set`
  /// Median: the answer of `nearest` per lattice voxel once asked (kUnknown before). The sets of
  /// the iteration keep revisiting the same region, so most left-median queries become one load.
  /// Only up to 256³ (64 MiB); larger lattices ask the tree every time.
  mutable std::vector<std::uint32_t> memo;
  Vec3 centroid{0.0};
  CompiledFunction map;
  VoxelLattice lattice;
};

SetFunction::SetFunction(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SetFunction::SetFunction(SetFunction&&) noexcept = default;
SetFunction& SetFunction::operator=(SetFunction&&) noexcept = default;
SetFunction::~SetFunction() = default;

SetFunction SetFunction::median(VoxelSet condensation, double rotateDegreesPerUnit, Vec3 axis) {
  auto impl = std::make_unique<Impl>();
  impl->kind = Impl::Kind::Median;
  impl->lattice = condensation.lattice;
  impl->set = std::move(condensation);
  impl->rotate = rotateDegreesPerUnit;
  const double length = glm::length(axis);
  impl->axis = length > 0.0 && std::isfinite(length) ? axis / length : Vec3{0.0, 0.0, 1.0};
  impl->nearest = std::make_unique<NearestVoxel>(impl->set, 0);
  impl->centroid = latticeCentroid(impl->set);
  if (impl->lattice.n <= 256) impl->memo.assign(impl->lattice.voxelCount(), kUnknown);
  return SetFunction(std::move(impl));
}

SetFunction SetFunction::constant(VoxelSet condensation) {
  auto impl = std::make_unique<Impl>();
  impl->kind = Impl::Kind::Constant;
  impl->lattice = condensation.lattice;
  impl->set = std::move(condensation);
  return SetFunction(std::move(impl));
}

SetFunction SetFunction::pointMap(CompiledFunction map, VoxelLattice lattice) {
  auto impl = std::make_unique<Impl>();
  impl->kind = Impl::Kind::PointMap;
  impl->map = std::move(map);
  impl->lattice = lattice;
  impl->set.lattice = lattice;
  return SetFunction(std::move(impl));
}

const VoxelSet& SetFunction::condensation() const { return impl_->set; }
bool SetFunction::isConstant() const { return impl_->kind == Impl::Kind::Constant; }

void SetFunction::apply(const VoxelSet& in, VoxelSet& out, SetScratch& scratch, int threads) const {
  const Impl& f = *impl_;
  const VoxelLattice& lattice = f.lattice;
  out.lattice = lattice;
  constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  const int n = lattice.n;
  if (f.kind == Impl::Kind::Constant) {
    out.voxels = f.set.voxels;
    return;
  }
  std::vector<std::uint32_t>& candidates = scratch.candidates;
  if (f.kind == Impl::Kind::PointMap) {
    // Four subsamples per axis pair: the corners of a half-voxel cube around the centre.
    candidates.assign(in.size() * 8, kNone);
    parallelFor(in.size(), threads, 4096, [&](std::size_t begin, std::size_t end) {
      for (std::size_t v = begin; v < end; ++v) {
        const Vec3 c = lattice.centre(in.voxels[v]);
        const double q = 0.25 * lattice.voxelSize();
        for (int s = 0; s < 8; ++s) {
          const std::array<float, 3> p{float(c.x + ((s & 1) ? q : -q)), float(c.y + ((s & 2) ? q : -q)),
                                       float(c.z + ((s & 4) ? q : -q))};
          const std::array<float, 3> r = f.map.evaluate(p);
          int idx[3];
          bool inside = true;
          for (int d = 0; d < 3; ++d) {
            const double l = std::floor((double(r[std::size_t(d)]) + 1.0) * 0.5 * n);
            inside &= l >= 0.0 && l < n;
            idx[d] = inside ? int(l) : 0;
          }
          if (inside) candidates[8 * v + std::size_t(s)] = lattice.index(idx[0], idx[1], idx[2]);
        }
      }
    });
    collect(candidates, scratch, out);
    return;
  }
  // The median (§3.2): for every voxel of one set, the midpoint to the nearest voxel of the other.
  const NearestVoxel other(in, threads);  // B's tree; C's is built once
  const VoxelSet& c = f.set;
  const std::size_t left = in.size();
  candidates.assign(left + c.size(), kNone);
  double angle = 0.0;
  Vec3 pivot{0.0};
  if (f.rotate != 0.0) {
    // §4.1: rotate by an angle proportional to the distance between the sets (in X units).
    const Vec3 centreB = latticeCentroid(in);
    const double distance = glm::length(centreB - f.centroid) * lattice.voxelSize();
    angle = f.rotate * distance * M_PI / 180.0;
    pivot = 0.5 * (centreB + f.centroid);
  }
  const double cosA = std::cos(angle), sinA = std::sin(angle);
  // About z the rotation keeps the midpoint's z exactly (the paper's drawings lie in a plane);
  // about any other axis, Rodrigues' rotation matrix R = cos·I + sin·[k]× + (1 − cos)·k kᵀ.
  const bool aboutZ = f.axis == Vec3{0.0, 0.0, 1.0};
  double rot[3][3];
  {
    const Vec3& k = f.axis;
    const double cross[3][3] = {{0.0, -k.z, k.y}, {k.z, 0.0, -k.x}, {-k.y, k.x, 0.0}};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) rot[r][c] = (r == c ? cosA : 0.0) + sinA * cross[r][c] + (1.0 - cosA) * k[r] * k[c];
  }
  auto midpoint = [&](const Index3& a, const Index3& b, std::uint32_t tie) -> std::uint32_t {
    int m[3];
    if (angle == 0.0) {
      for (int d = 0; d < 3; ++d) {
        const int sum = a[std::size_t(d)] + b[std::size_t(d)];
        // Halves of odd sums go up or down by a hash of the pair, so rounding does not drift.
        m[d] = (sum + ((sum & 1) ? int((tie >> d) & 1u) : 0)) >> 1;
      }
    } else {
      double r[3];
      if (aboutZ) {
        const double x = 0.5 * (a[0] + b[0]) - pivot.x, y = 0.5 * (a[1] + b[1]) - pivot.y;
        r[0] = pivot.x + cosA * x - sinA * y;
        r[1] = pivot.y + sinA * x + cosA * y;
        r[2] = 0.5 * (a[2] + b[2]);
      } else {
        const double q[3] = {0.5 * (a[0] + b[0]) - pivot.x, 0.5 * (a[1] + b[1]) - pivot.y,
                             0.5 * (a[2] + b[2]) - pivot.z};
        for (int d = 0; d < 3; ++d) r[d] = pivot[d] + rot[d][0] * q[0] + rot[d][1] * q[1] + rot[d][2] * q[2];
      }
      for (int d = 0; d < 3; ++d) {
        m[d] = int(std::lround(r[d]));
        if (m[d] < 0 || m[d] >= n) return kNone;
      }
    }
    return lattice.index(m[0], m[1], m[2]);
  };
  // The left median's queries are mostly memo look-ups and the right median's are tree searches:
  // two loops, so that each shares work of one cost among the threads. A query's answer does not
  // depend on the chunks, so the image is the same for any number of threads.
  chunkedLoop(left, threads, 2048, [&](std::size_t begin, std::size_t end) {
    std::uint32_t hint = kUnknown;
    for (std::size_t q = begin; q < end; ++q) {
      const std::uint32_t from = in.voxels[q];
      const Index3 a = lattice.coordinates(from);
      const float p[3] = {float(a[0]), float(a[1]), float(a[2])};
      std::uint32_t to;
      if (!f.memo.empty()) {
        // Distinct voxels of `in` write distinct entries, so the chunks never share one.
        std::uint32_t& known = f.memo[from];
        if (known == kUnknown) known = f.nearest->nearest(from, p, hint);
        to = known;
      } else {
        to = f.nearest->nearest(from, p, hint);
      }
      const Index3 b = lattice.coordinates(to);
      candidates[q] = midpoint(a, b, std::uint32_t(splitmix64((std::uint64_t(from) << 32) | to)));
    }
  });
  chunkedLoop(c.size(), threads, 512, [&](std::size_t begin, std::size_t end) {
    std::uint32_t hint = kUnknown;
    for (std::size_t q = begin; q < end; ++q) {
      const std::uint32_t from = c.voxels[q];
      const Index3 a = lattice.coordinates(from);
      const float p[3] = {float(a[0]), float(a[1]), float(a[2])};
      const std::uint32_t to = other.nearest(from, p, hint);
      const Index3 b = lattice.coordinates(to);
      candidates[left + q] = midpoint(a, b, std::uint32_t(splitmix64((std::uint64_t(from) << 32) | to)));
    }
  });
  collect(candidates, scratch, out);
}

}  // namespace gridifs
