// Free-form IFS (Thollot, Zair, Tosan & Vandorpe 1997, §3.1, §5): file format and validation,
// the presets' matrices, and the chaos game plotting P·λ through the control points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "freeform/free_form.h"
#include "freeform/free_form_presets.h"
#include "io/project_io.h"
#include "tests/core/chaos_points.h"
#include "volume/measure_attractor.h"

using namespace gridifs;
using test_support::chaosPoints;

namespace {

Project preset(FreeFormPreset which, double roughness = 0.0) {
  Project p = defaultNewProject();
  FreeFormPresetOptions options;
  options.roughness = roughness;
  applyFreeFormPreset(p, which, options);
  return p;
}

Vec3 bezier(const std::vector<Vec3>& points, double t) {
  // de Casteljau evaluation, independent of the Bernstein matrices under test.
  std::vector<Vec3> q = points;
  for (std::size_t level = 1; level < q.size(); ++level)
    for (std::size_t i = 0; i + level < q.size(); ++i) q[i] = (1.0 - t) * q[i] + t * q[i + 1];
  return q[0];
}

/// Distance from p to the curve and the parameter of the nearest point (dense search, then refined).
std::pair<double, double> nearestOnCurve(const std::vector<Vec3>& points, Vec3 p) {
  double best = 1e9, bestT = 0.0;
  for (int i = 0; i <= 2000; ++i) {
    const double t = i / 2000.0, d = glm::length(bezier(points, t) - p);
    if (d < best) best = d, bestT = t;
  }
  for (double h = 1.0 / 4000.0; h > 1e-9; h *= 0.5)
    for (double t : {bestT - h, bestT + h})
      if (t >= 0.0 && t <= 1.0)
        if (const double d = glm::length(bezier(points, t) - p); d < best) best = d, bestT = t;
  return {best, bestT};
}

std::string loadError(const std::string& text) {
  try {
    parseProject(text);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "";
}

const char* kCurveHead =
    R"({"format": "gridifs", "version": 1, "space": {"control_points": [[0,0,0],[1,0,0],[1,1,0]]},)";

}  // namespace

TEST(FreeForm, DeCasteljauMatricesSubdivideTheBernsteinBasis) {
  for (double r : {0.5, 0.3}) {
    const auto left = deCasteljauLeft(3, r), right = deCasteljauRight(3, r);
    for (const auto* t : {&left, &right})
      for (const auto& row : *t) {
        double sum = 0.0;
        for (double v : row) sum += v;
        EXPECT_NEAR(sum, 1.0, 1e-12);
      }
    for (double s : {0.0, 0.2, 0.7, 1.0}) {
      const auto l = applyMatrix(bernstein(3, s), left), rr = applyMatrix(bernstein(3, s), right);
      const auto el = bernstein(3, r * s), er = bernstein(3, r + (1.0 - r) * s);
      for (int j = 0; j < 4; ++j) {
        EXPECT_NEAR(l[std::size_t(j)], el[std::size_t(j)], 1e-12);
        EXPECT_NEAR(rr[std::size_t(j)], er[std::size_t(j)], 1e-12);
      }
    }
  }
}

TEST(FreeForm, BezierPresetAttractorLiesOnTheCurveAndCoversIt) {
  const Project p = preset(FreeFormPreset::BezierCurve);
  const auto& cp = p.space->control_points;
  const auto points = chaosPoints(p, 40000);
  ASSERT_GT(points.size(), 39000u);
  std::set<int> bins;
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); i += 7) {
    const auto [d, t] = nearestOnCurve(cp, points[i]);
    worst = std::max(worst, d);
    bins.insert(std::min(99, int(t * 100.0)));
  }
  EXPECT_LT(worst, 2e-5);        // float arithmetic in the kernel
  EXPECT_EQ(bins.size(), 100u);  // every 1% of the parameter range is reached
}

TEST(FreeForm, BezierPresetDensityVolumeLiesOnTheCurveAndCoversIt) {
  const Project p = preset(FreeFormPreset::BezierCurve);
  const auto& cp = p.space->control_points;
  VolumeJob job;
  job.settings.resolution = 48;
  job.settings.samples = 400000;
  job.threads = 2;
  const DensityVolume v = computeDensityVolume(p, job);
  ASSERT_EQ(v.density.size(), 48u * 48u * 48u);
  // Every visited voxel holds a point of the curve (its centre is within half a diagonal).
  const double halfDiagonal = 0.5 * std::sqrt(3.0) * v.lattice.voxelSize();
  std::size_t visited = 0;
  for (std::uint32_t i = 0; i < v.density.size(); ++i) {
    if (v.density[i] <= 0.0f) continue;
    ++visited;
    EXPECT_LT(nearestOnCurve(cp, v.lattice.centre(i)).first, halfDiagonal + 1e-6) << "voxel " << i;
  }
  // And the voxels the curve passes through are visited (points near a voxel's faces are left
  // out: the curve may only graze that voxel, which few of the samples then reach).
  std::size_t missed = 0, onCurve = 0;
  for (int i = 0; i <= 400; ++i) {
    const Vec3 q = (bezier(cp, i / 400.0) + 1.0) * (0.5 * 48.0);
    const int x = int(q.x), y = int(q.y), z = int(q.z);
    if (x < 0 || y < 0 || z < 0 || x >= 48 || y >= 48 || z >= 48) continue;
    const Vec3 inside = q - glm::floor(q);
    if (glm::any(glm::lessThan(inside, Vec3(0.15))) || glm::any(glm::greaterThan(inside, Vec3(0.85)))) continue;
    ++onCurve;
    if (v.at(x, y, z) <= 0.0f) ++missed;
  }
  EXPECT_GT(onCurve, 50u);
  EXPECT_EQ(missed, 0u);
  EXPECT_GT(visited, 48u);
  // The same seed gives the same volume.
  EXPECT_EQ(computeDensityVolume(p, job).density, v.density);
}

TEST(FreeForm, BicubicPatchPresetLiesOnThePatch) {
  const Project p = preset(FreeFormPreset::BezierPatch);
  const auto& cp = p.space->control_points;
  auto patch = [&](double s, double t) {
    std::vector<Vec3> rows;
    for (int i = 0; i < 4; ++i)
      rows.push_back(bezier(
          {cp[std::size_t(4 * i)], cp[std::size_t(4 * i + 1)], cp[std::size_t(4 * i + 2)], cp[std::size_t(4 * i + 3)]},
          t));
    return bezier(rows, s);
  };
  const auto points = chaosPoints(p, 8000);
  std::set<int> cells;
  double worst = 0.0;
  for (std::size_t n = 0; n < points.size(); n += 13) {
    double best = 1e9, bs = 0, bt = 0;
    for (int i = 0; i <= 60; ++i)
      for (int k = 0; k <= 60; ++k)
        if (const double d = glm::length(patch(i / 60.0, k / 60.0) - points[n]); d < best)
          best = d, bs = i / 60.0, bt = k / 60.0;
    for (double h = 1.0 / 120.0; h > 1e-9; h *= 0.5) {
      for (auto [ds, dt] : {std::pair{-h, 0.0}, {h, 0.0}, {0.0, -h}, {0.0, h}}) {
        const double s = std::clamp(bs + ds, 0.0, 1.0), t = std::clamp(bt + dt, 0.0, 1.0);
        if (const double d = glm::length(patch(s, t) - points[n]); d < best) best = d, bs = s, bt = t;
      }
    }
    worst = std::max(worst, best);
    cells.insert(std::min(4, int(bs * 5)) * 5 + std::min(4, int(bt * 5)));
  }
  EXPECT_LT(worst, 1e-4);
  EXPECT_EQ(cells.size(), 25u);
}

TEST(FreeForm, SierpinskiPresetIsTheAffineGasket) {
  const Project p = preset(FreeFormPreset::Sierpinski);
  const auto& c = p.space->control_points;
  // Barycentric coordinates of q in the triangle c0 c1 c2 (z = 0).
  auto coords = [&](Vec3 q) {
    const Vec3 v0 = c[1] - c[0], v1 = c[2] - c[0], v2 = q - c[0];
    const double d00 = glm::dot(v0, v0), d01 = glm::dot(v0, v1), d11 = glm::dot(v1, v1);
    const double d20 = glm::dot(v2, v0), d21 = glm::dot(v2, v1), den = d00 * d11 - d01 * d01;
    const double b = (d11 * d20 - d01 * d21) / den, g = (d00 * d21 - d01 * d20) / den;
    return std::array<double, 3>{1.0 - b - g, b, g};
  };
  const auto points = chaosPoints(p, 60000);
  std::set<std::vector<int>> level4;
  for (const Vec3& q : points) {
    ASSERT_NEAR(q.z, 0.0, 1e-6);
    auto l = coords(q);
    std::vector<int> address;
    // Each map halves towards a corner, so a gasket point has a coordinate ≥ 1/2 at every level;
    // undoing that map (λ ← 2λ − e_k) goes one level up.
    for (int level = 0; level < 8; ++level) {
      const int k = int(std::max_element(l.begin(), l.end()) - l.begin());
      ASSERT_GT(l[std::size_t(k)], 0.5 - 1e-3 * (1 << level)) << "level " << level;
      if (level < 4) address.push_back(k);
      for (int j = 0; j < 3; ++j) l[std::size_t(j)] = 2.0 * l[std::size_t(j)] - (j == k ? 1.0 : 0.0);
    }
    level4.insert(address);
  }
  EXPECT_EQ(level4.size(), 81u);  // 3^4 sub-triangles, all reached
}

TEST(FreeForm, PresetsRoundTripThroughTheFile) {
  for (FreeFormPreset which : {FreeFormPreset::BezierCurve, FreeFormPreset::BezierPatch, FreeFormPreset::Sierpinski,
                               FreeFormPreset::SierpinskiPatch})
    for (double roughness : {0.0, 0.2}) {
      const Project p = preset(which, roughness);
      EXPECT_NO_THROW(validateProject(p)) << freeFormPresetName(which);
      const Project back = parseProject(serializeProject(p));
      EXPECT_EQ(back, p) << freeFormPresetName(which);
    }
  // A grid project's file has no free-form fields.
  EXPECT_EQ(serializeProject(defaultNewProject()).find("matrix"), std::string::npos);
}

TEST(FreeForm, RoughnessKeepsRowsAndTheJointButLeavesTheCurve) {
  const Project smooth = preset(FreeFormPreset::BezierCurve), rough = preset(FreeFormPreset::BezierCurve, 0.25);
  const auto& left = rough.functions[0].matrix;
  const auto& right = rough.functions[1].matrix;
  EXPECT_EQ(left.back(), right.front());  // the two halves still meet
  EXPECT_EQ(left.front(), smooth.functions[0].matrix.front());
  const auto points = chaosPoints(rough, 20000);
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); i += 50)
    worst = std::max(worst, nearestOnCurve(smooth.space->control_points, points[i]).first);
  EXPECT_GT(worst, 1e-3);  // a different, rough curve
}

TEST(FreeForm, ValidationNamesTheJsonPath) {
  const std::string fn = R"("functions": [{"kind": "matrix", "matrix": )";
  EXPECT_NE(loadError(std::string(kCurveHead) + fn + R"([[1,0,0],[0.5,0.6,0],[0,0,1]]}]})")
                .find("functions[0].matrix[1]: the row sums to 1.1"),
            std::string::npos);
  EXPECT_NE(
      loadError(std::string(kCurveHead) + fn + R"([[1,0,0],[0,0,1]]}]})").find("functions[0].matrix: expected 3 rows"),
      std::string::npos);
  EXPECT_NE(loadError(std::string(kCurveHead) + fn + R"([[1,0,0],[0,1],[0,0,1]]}]})")
                .find("functions[0].matrix[1]: expected 3 entries"),
            std::string::npos);
  // Within 1e-9 is accepted; beyond is not.
  EXPECT_EQ(loadError(std::string(kCurveHead) + fn + R"([[1,0,0],[0.5,0.5000000000005,0],[0,0,1]]}]})"), "");
  EXPECT_NE(loadError(std::string(kCurveHead) + fn + R"([[1,0,0],[0.5,0.500000001,0],[0,0,1]]}]})"), "");
  EXPECT_NE(loadError(std::string(kCurveHead) + R"("functions": [{"name": "g"}]})")
                .find("functions[0].kind: a project with control points"),
            std::string::npos);
  EXPECT_NE(loadError(R"({"format": "gridifs", "version": 1, "functions": [{"kind": "matrix", "matrix": [[1]]}]})")
                .find("functions[0].kind: a \"matrix\" function needs control points"),
            std::string::npos);
  EXPECT_NE(loadError(R"({"format": "gridifs", "version": 1, "space": {"control_points": [[0,0,0]]},
                          "functions": [{"kind": "matrix", "matrix": [[1]]}]})")
                .find("space.control_points: expected between 2 and 64"),
            std::string::npos);
  EXPECT_NE(loadError(std::string(kCurveHead) + fn + R"([[1,0,0],[0,1,0],[0,0,1]], "ops": []}]})")
                .find("functions[0].ops: a \"matrix\" function has no grid"),
            std::string::npos);
  EXPECT_NE(loadError(R"({"format": "gridifs", "version": 1, "functions": [{}],
                          "final": {"resolution": [9, 4, 4], "interpolation": "bezier"}})")
                .find("final.resolution[0]: a \"bezier\" lattice has at most 8 nodes per axis"),
            std::string::npos);
}

TEST(FreeForm, NegativeEntriesAreAllowedWithAWarning) {
  Project p = preset(FreeFormPreset::BezierCurve);
  p.functions[0].matrix[1] = {0.6, 0.6, -0.2, 0.0};
  EXPECT_NO_THROW(validateProject(p));
  ASSERT_EQ(freeFormWarnings(p).size(), 1u);
  EXPECT_NE(freeFormWarnings(p)[0].find("convex hull"), std::string::npos);
}

TEST(FreeForm, ChaosGameIsDeterministicAndUsesTransitions) {
  Project p = preset(FreeFormPreset::Sierpinski);
  EXPECT_EQ(chaosPoints(p, 5000), chaosPoints(p, 5000));
  // Corner 0 may never follow itself: no point lies in the sub-triangle f_0∘f_0 (λ_0 > 3/4).
  p.transitions = {{0, 1, 1}, {1, 1, 1}, {1, 1, 1}};
  const auto& c = p.space->control_points;
  int inside = 0;
  for (const Vec3& q : chaosPoints(p, 40000)) {
    // λ_0 from the distance to the opposite edge.
    const Vec3 e = c[2] - c[1], n = glm::normalize(Vec3{-e.y, e.x, 0.0});
    const double l0 = glm::dot(q - c[1], n) / glm::dot(c[0] - c[1], n);
    inside += l0 > 0.75 + 1e-4;
  }
  EXPECT_EQ(inside, 0);
}
