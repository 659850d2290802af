#include "explore/attractor_verdict.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "base/hash.h"
#include "job/prepared_render.h"
#include "render/chaos_renderer.h"

namespace gridifs {
namespace {

// The small render: a thumbnail's frame, and enough points to see a shape in 16³ voxels. About
// 10 ms on one core; fixed seeds and one thread, so a verdict is the same on every machine.
constexpr int kFrameWidth = 64, kFrameHeight = 48;
constexpr std::int64_t kFrameSamples = 40'000;
constexpr std::int64_t kPointSamples = 20'000;
constexpr int kVoxels = 16;
constexpr std::size_t kStretchProbes = 512;

// The thresholds: what a glance at a preview calls a speck, a flood, a line or a runaway.
constexpr double kMinCovered = 0.01;                                 // under 1% of the frame: a speck
constexpr double kMaxCovered = 0.92;                                 // over 92%: the frame is flooded
constexpr double kMinSpread = 12.0 / (kVoxels * kVoxels * kVoxels);  // fewer than 12 voxels: a point
constexpr double kMinThickness = 0.02;                               // principal extents 50 : 1 and thinner: a line
constexpr double kMaxContraction = 1.0;  // expanding on average: the chaos game does not settle
constexpr double kMaxEscaped = 0.5;      // half the points lost: the command line refuses to render it

/// The eigenvalues of a symmetric 3×3 matrix, largest first (Smith's closed form).
std::array<double, 3> symmetricEigenvalues(const std::array<double, 6>& m) {
  // m: xx, yy, zz, xy, xz, yz
  const double p1 = m[3] * m[3] + m[4] * m[4] + m[5] * m[5];
  const double q = (m[0] + m[1] + m[2]) / 3.0;
  const double p2 = (m[0] - q) * (m[0] - q) + (m[1] - q) * (m[1] - q) + (m[2] - q) * (m[2] - q) + 2.0 * p1;
  const double p = std::sqrt(p2 / 6.0);
  if (p < 1e-300) return {q, q, q};
  const double b[6] = {(m[0] - q) / p, (m[1] - q) / p, (m[2] - q) / p, m[3] / p, m[4] / p, m[5] / p};
  const double det =
      b[0] * (b[1] * b[2] - b[5] * b[5]) - b[3] * (b[3] * b[2] - b[5] * b[4]) + b[4] * (b[3] * b[5] - b[1] * b[4]);
  const double r = std::clamp(det / 2.0, -1.0, 1.0);
  const double phi = std::acos(r) / 3.0;
  const double e1 = q + 2.0 * p * std::cos(phi);
  const double e3 = q + 2.0 * p * std::cos(phi + 2.0943951023931953);
  return {e1, 3.0 * q - e1 - e3, e3};
}

RenderJobOptions smallRender(const std::filesystem::path& folder) {
  RenderJobOptions options;
  options.threads = 1;
  options.width = kFrameWidth;
  options.height = kFrameHeight;
  options.samples = kFrameSamples;
  options.seed = 1;
  options.folder = folder;
  options.setResolution = 64;
  return options;
}

/// How much of the frame the project's camera sees covered by the compiled IFS's points.
double coverage(const std::shared_ptr<const CompiledIfs>& ifs, const Project& project,
                const std::filesystem::path& folder) {
  const RenderImage frame =
      renderToCompletion(ifs, outputRenderJob(project, smallRender(folder)), renderDisplaySettings(project));
  return double(frame.hitPixels) / double(kFrameWidth * kFrameHeight);
}

/// Everything but the frame's coverage, which depends on the camera.
AttractorVerdict measure(const PreparedRender& prepared) {
  AttractorVerdict v;
  // How the points spread through X.
  RenderJob pointsJob = prepared.output;
  pointsJob.samples = kPointSamples;
  std::vector<float> xyz;
  xyz.reserve(std::size_t(kPointSamples) * 3);
  const RenderStats stats = generatePoints(*prepared.ifs, pointsJob, [&](const PointBatch& batch, const RenderStats&) {
    xyz.insert(xyz.end(), batch.xyz, batch.xyz + batch.count * 3);
    return true;
  });
  const std::size_t n = xyz.size() / 3;
  std::vector<bool> occupied(std::size_t(kVoxels * kVoxels * kVoxels), false);
  for (std::size_t i = 0; i < n; ++i) {
    int cell[3];
    for (int d = 0; d < 3; ++d)
      cell[d] = std::clamp(int((xyz[i * 3 + std::size_t(d)] + 1.0f) * 0.5f * kVoxels), 0, kVoxels - 1);
    occupied[std::size_t(cell[0] + kVoxels * (cell[1] + kVoxels * cell[2]))] = true;
  }
  v.spread = double(std::count(occupied.begin(), occupied.end(), true)) / double(occupied.size());
  v.escaped = stats.samples > 0 ? stats.badFraction() : 1.0;
  // Where the points lie, stray ones left out (flames throw a few far away).
  if (n > 0)
    for (int d = 0; d < 3; ++d) {
      std::vector<float> axis(n);
      for (std::size_t i = 0; i < n; ++i) axis[i] = xyz[i * 3 + std::size_t(d)];
      const std::size_t lo = n / 100, hi = n - 1 - n / 100;
      std::nth_element(axis.begin(), axis.begin() + std::ptrdiff_t(lo), axis.end());
      v.low[d] = axis[lo];
      std::nth_element(axis.begin(), axis.begin() + std::ptrdiff_t(hi), axis.end());
      v.high[d] = axis[hi];
    }
  // The principal extents of the points inside those bounds.
  std::array<double, 6> covariance{};
  double mean[3] = {0, 0, 0};
  std::size_t inside = 0;
  auto within = [&](std::size_t i) {
    for (int d = 0; d < 3; ++d) {
      const double c = xyz[i * 3 + std::size_t(d)];
      if (c < v.low[d] || c > v.high[d]) return false;
    }
    return true;
  };
  for (std::size_t i = 0; i < n; ++i)
    if (within(i)) {
      for (int d = 0; d < 3; ++d) mean[d] += xyz[i * 3 + std::size_t(d)];
      ++inside;
    }
  if (inside > 0) {
    for (double& m : mean) m /= double(inside);
    for (std::size_t i = 0; i < n; ++i) {
      if (!within(i)) continue;
      const double x = xyz[i * 3] - mean[0], y = xyz[i * 3 + 1] - mean[1], z = xyz[i * 3 + 2] - mean[2];
      covariance[0] += x * x, covariance[1] += y * y, covariance[2] += z * z;
      covariance[3] += x * y, covariance[4] += x * z, covariance[5] += y * z;
    }
    for (double& c : covariance) c /= double(inside);
  }
  const std::array<double, 3> extent = symmetricEigenvalues(covariance);
  v.thickness = extent[0] > 0.0 ? std::sqrt(std::max(0.0, extent[1]) / extent[0]) : 0.0;

  // Whether the maps contract on average at the attractor's points: the mean log of how much
  // each map, drawn by its probability, stretches a small step there.
  double logStretch = 0.0;
  std::size_t probes = 0;
  const CompiledIfs& ifs = *prepared.ifs;
  std::uint64_t random = 0x5EEDull;
  for (std::size_t i = 0; i < kStretchProbes && n > 0 && !ifs.functions.empty(); ++i) {
    random = splitmix64(random);
    const std::size_t at = std::size_t(random % n);
    random = splitmix64(random);
    const CompiledFunction& f = ifs.functions[ifs.choose(random)];
    if (!f.matrix.empty() || !f.points.empty()) continue;  // free-form matrices and set maps: no grid
    // A step a thousandth of the point's size: far out (a runaway) a fixed one is below float's
    // resolution and would read as no stretch at all.
    const std::array<float, 3> p = {xyz[at * 3], xyz[at * 3 + 1], xyz[at * 3 + 2]};
    const float size = std::max({1.0f, std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])});
    if (!std::isfinite(size)) continue;
    const float step = 1e-3f * size;
    std::array<float, 3> q = p;
    q[i % 3] += p[i % 3] > 0.0f ? -step : step;  // towards the centre: inside X where p is
    std::uint64_t r1 = random, r2 = random;      // the same random draws for both points
    const std::array<float, 3> fp = f.evaluateMap(p, r1), fq = f.evaluateMap(q, r2);
    const double d = std::sqrt(double(fp[0] - fq[0]) * (fp[0] - fq[0]) + double(fp[1] - fq[1]) * (fp[1] - fq[1]) +
                               double(fp[2] - fq[2]) * (fp[2] - fq[2]));
    if (!std::isfinite(d)) continue;
    logStretch += std::log(std::max(d, 1e-9) / double(step));
    ++probes;
  }
  v.contraction = probes > 0 ? std::exp(logStretch / double(probes)) : 0.0;

  return v;
}

void decide(AttractorVerdict& v) {
  v.why.clear();
  // A point has no extent at all, a line no width: the voxels tell the first, the principal
  // extents the second, before the frame's coverage (a line covers little of any frame).
  if (v.escaped > kMaxEscaped || v.contraction >= kMaxContraction)
    v.why = "runs off";
  else if (v.spread < kMinSpread)
    v.why = "a speck";
  else if (v.thickness < kMinThickness)
    v.why = "a line";
  else if (v.covered < kMinCovered)
    v.why = "a speck";
  else if (v.covered > kMaxCovered)
    v.why = "a flood";
  v.worth = v.why.empty();
}

/// The camera turned on the attractor's points as the modeller's F frames a view: its target at
/// their centre, near enough that they fill about two thirds of the frame.
void frameCamera(Project& p, const AttractorVerdict& verdict) {
  const Vec3 centre = (verdict.low + verdict.high) * 0.5;
  const double radius = std::max(0.05, 0.5 * glm::length(verdict.high - verdict.low));
  const double halfFov = 0.5 * p.camera.fov * 3.141592653589793 / 180.0;
  p.camera.target = centre;
  p.camera.distance = std::clamp(radius / std::tan(halfFov) / 0.8, 0.5, 50.0);
}

}  // namespace

AttractorVerdict judgeAttractor(const Project& project, const std::filesystem::path& folder) {
  const PreparedRender prepared = prepareRender(project, smallRender(folder));
  AttractorVerdict v = measure(prepared);
  v.covered = coverage(prepared.ifs, prepared.project, folder);
  decide(v);
  return v;
}

AttractorVerdict judgeFramed(Project& project, const std::filesystem::path& folder) {
  // The maps are compiled once (a median project's density volume is the dear part); only the
  // frame's coverage is measured again for the framed camera.
  const PreparedRender prepared = prepareRender(project, smallRender(folder));
  AttractorVerdict v = measure(prepared);
  v.covered = coverage(prepared.ifs, prepared.project, folder);
  decide(v);
  if (v.why == "runs off" || v.spread < kMinSpread) return v;  // no camera helps these
  frameCamera(project, v);
  Project framed = prepared.project;
  framed.camera = project.camera;
  v.covered = coverage(prepared.ifs, framed, folder);
  decide(v);
  return v;
}

}  // namespace gridifs
