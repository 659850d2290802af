// Free form, complete (Thollot, Zair, Tosan & Vandorpe 1997, §5): Bézier presets of every degree,
// uniform B-spline presets, the joint conditions of fractal curves and patches, control points
// added and removed, and F̂ of any affine IFS on a control net (flat or a paraboloid).
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "edit/project_edit.h"
#include "freeform/free_form.h"
#include "freeform/free_form_basis.h"
#include "freeform/free_form_deformation.h"
#include "freeform/free_form_joints.h"
#include "freeform/free_form_presets.h"
#include "freeform/free_form_resize.h"
#include "schema/validation.h"
#include "tests/core/chaos_points.h"

using namespace gridifs;
using test_support::chaosPoints;

namespace {

Project completePreset(FreeFormPreset which, int degree = 3, double roughness = 0.0) {
  Project p = defaultNewProject();
  FreeFormPresetOptions options;
  options.degree = degree;
  options.roughness = roughness;
  applyFreeFormPreset(p, which, options);
  return p;
}

Vec3 deCasteljau(std::vector<Vec3> q, double t) {
  for (std::size_t level = 1; level < q.size(); ++level)
    for (std::size_t i = 0; i + level < q.size(); ++i) q[i] = (1.0 - t) * q[i] + t * q[i + 1];
  return q[0];
}

void expectRowsSumToOne(const BarycentricMatrix& m) {
  for (const auto& row : m) {
    double s = 0.0;
    for (double v : row) s += v;
    EXPECT_NEAR(s, 1.0, 1e-12);
  }
}

/// A grid function x ↦ R_z(angle)·(scale·x) + translate.
Function affine(const std::string& name, double scale, double angleDegrees, Vec3 translate, double zScale = -1.0) {
  Function f;
  f.name = name;
  f.resolution = {3, 3, 3};
  f.placement.scale = Vec3{scale, scale, zScale < 0.0 ? scale : zScale};
  f.placement.rotate = Vec3{0.0, 0.0, angleDegrees};
  f.placement.translate = translate;
  return f;
}

/// The Sierpinski gasket on the triangle (-1, -1), (1, -1), (0, 1) in the plane z = 0.
Project gridGasket() {
  Project p = defaultNewProject();
  p.functions = {affine("a", 0.5, 0, {-0.5, -0.5, 0}), affine("b", 0.5, 0, {0.5, -0.5, 0}),
                 affine("c", 0.5, 0, {0.0, 0.5, 0})};
  return p;
}

double nearest(const std::vector<Vec3>& cloud, Vec3 p) {
  double best = 1e9;
  for (const Vec3& q : cloud) best = std::min(best, double(glm::length(q - p)));
  return best;
}

}  // namespace

TEST(FreeFormPresets, BezierMatricesOfEveryDegreeSubdivideTheBernsteinBasis) {
  for (int n = kMinPresetDegree; n <= kMaxPresetDegree; ++n)
    for (double r : {0.5, 0.3}) {
      const auto left = deCasteljauLeft(n, r), right = deCasteljauRight(n, r);
      expectRowsSumToOne(left);
      expectRowsSumToOne(right);
      for (double s : {0.0, 0.37, 1.0}) {
        const auto l = applyMatrix(bernstein(n, s), left), rr = applyMatrix(bernstein(n, s), right);
        const auto el = bernstein(n, r * s), er = bernstein(n, r + (1.0 - r) * s);
        for (int j = 0; j <= n; ++j) {
          EXPECT_NEAR(l[std::size_t(j)], el[std::size_t(j)], 1e-12) << "degree " << n;
          EXPECT_NEAR(rr[std::size_t(j)], er[std::size_t(j)], 1e-12) << "degree " << n;
        }
      }
    }
}

TEST(FreeFormPresets, EveryDegreeGivesAValidCurveAndPatch) {
  for (int n = kMinPresetDegree; n <= kMaxPresetDegree; ++n) {
    for (FreeFormPreset which : {FreeFormPreset::BezierCurve, FreeFormPreset::BSplineCurve}) {
      const Project p = completePreset(which, n);
      EXPECT_EQ(p.space->control_points.size(), std::size_t(n + 1));
      EXPECT_NO_THROW(validateProject(p)) << freeFormPresetName(which) << " " << n;
    }
    for (FreeFormPreset which : {FreeFormPreset::BezierPatch, FreeFormPreset::BSplinePatch}) {
      const Project p = completePreset(which, n);
      EXPECT_EQ(p.space->control_points.size(), std::size_t((n + 1) * (n + 1)));
      EXPECT_EQ(p.functions.size(), 4u);
      EXPECT_NO_THROW(validateProject(p)) << freeFormPresetName(which) << " " << n;
    }
  }
  Project p = defaultNewProject();
  FreeFormPresetOptions options;
  options.degree = 8;
  try {
    applyFreeFormPreset(p, FreeFormPreset::BezierCurve, options);
    FAIL() << "degree 8 accepted";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.path(), "degree");
  }
}

TEST(FreeFormPresets, QuinticBezierAttractorIsTheCurveOfItsPoints) {
  const Project p = completePreset(FreeFormPreset::BezierCurve, 5);
  const auto& cp = p.space->control_points;
  std::vector<Vec3> curve;
  for (int i = 0; i <= 4000; ++i) curve.push_back(deCasteljau(cp, i / 4000.0));
  const auto points = chaosPoints(p, 20000);
  ASSERT_GT(points.size(), 19000u);
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); i += 20) worst = std::max(worst, nearest(curve, points[i]));
  EXPECT_LT(worst, 2e-3);  // the curve sampled every 1/4000 of its parameter
}

TEST(FreeFormPresets, UniformBSplineSubdivisionIsTheStandardOne) {
  // The cubic's halves by hand: edge points (p_i + p_{i+1})/2 and vertex points
  // (p_{i−1} + 6p_i + p_{i+1})/8 (Lane & Riesenfeld's refinement).
  const BarycentricMatrix left{{0.5, 0.5, 0, 0}, {0.125, 0.75, 0.125, 0}, {0, 0.5, 0.5, 0}, {0, 0.125, 0.75, 0.125}};
  const BarycentricMatrix right{{0.125, 0.75, 0.125, 0}, {0, 0.5, 0.5, 0}, {0, 0.125, 0.75, 0.125}, {0, 0, 0.5, 0.5}};
  const auto l = bsplineSubdivisionLeft(3), r = bsplineSubdivisionRight(3);
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) {
      EXPECT_NEAR(l[i][j], left[i][j], 1e-12);
      EXPECT_NEAR(r[i][j], right[i][j], 1e-12);
    }
  for (int n = 1; n <= kMaxPresetDegree; ++n) {
    const auto ln = bsplineSubdivisionLeft(n), rn = bsplineSubdivisionRight(n);
    expectRowsSumToOne(ln);
    for (const auto& row : ln)
      for (double v : row) EXPECT_GE(v, -1e-12);
    for (double t : {0.0, 0.4, 1.0}) {
      const auto a = applyMatrix(uniformBSpline(n, t), ln), b = uniformBSpline(n, 0.5 * t);
      const auto c = applyMatrix(uniformBSpline(n, t), rn), d = uniformBSpline(n, 0.5 + 0.5 * t);
      for (int j = 0; j <= n; ++j) {
        EXPECT_NEAR(a[std::size_t(j)], b[std::size_t(j)], 1e-10) << "degree " << n;
        EXPECT_NEAR(c[std::size_t(j)], d[std::size_t(j)], 1e-10) << "degree " << n;
      }
    }
  }
}

TEST(FreeFormJoints, PresetsMeetAndAHandEditNamesThePairItBreaks) {
  for (FreeFormPreset which : {FreeFormPreset::BezierCurve, FreeFormPreset::BSplineCurve, FreeFormPreset::BezierPatch,
                               FreeFormPreset::BSplinePatch})
    for (int n : {2, 3, 5}) {
      const Project p = completePreset(which, n);
      EXPECT_FALSE(freeFormJoints(p).empty());
      EXPECT_TRUE(failingJoints(p).empty()) << freeFormPresetName(which) << " " << n;
    }
  // Zair & Tosan's fractal curves keep their joint (§5.3.2).
  EXPECT_TRUE(failingJoints(completePreset(FreeFormPreset::BezierCurve, 4, 0.3)).empty());
  EXPECT_TRUE(failingJoints(completePreset(FreeFormPreset::BezierPatch, 3, 0.3)).empty());

  const Project curve = completePreset(FreeFormPreset::BezierCurve, 3);
  Project edited = curve;
  applyEdit(edited, SetMatrixEntry{0, 3, 2, 0.2});  // the left half's last row: its end moves
  const auto broken = brokenJoints(curve, edited);
  ASSERT_EQ(broken.size(), 1u);
  EXPECT_EQ(broken[0].first, 0u);
  EXPECT_EQ(broken[0].second, 1u);
  EXPECT_FALSE(broken[0].edge);
  EXPECT_NE(describeJoint(edited, broken[0]).find("left -> right"), std::string::npos);
  // An inner row moves the inside of a piece, not its ends.
  Project inner = curve;
  applyEdit(inner, SetMatrixEntry{0, 1, 2, 0.1});
  EXPECT_TRUE(brokenJoints(curve, inner).empty());

  const Project patch = completePreset(FreeFormPreset::BezierPatch, 2);
  Project bent = patch;
  applyEdit(bent, SetMatrixEntry{0, 8, 4, 0.3});  // q00's far corner row
  const auto edges = brokenJoints(patch, bent);
  ASSERT_FALSE(edges.empty());
  for (const auto& j : edges) {
    EXPECT_TRUE(j.edge);
    EXPECT_TRUE(j.first == 0 || j.second == 0) << describeJoint(bent, j);
  }
  // The gasket's pieces never met end to start: an edit breaks nothing.
  const Project gasket = completePreset(FreeFormPreset::Sierpinski);
  Project g2 = gasket;
  applyEdit(g2, SetMatrixEntry{0, 1, 2, 0.1});
  EXPECT_TRUE(brokenJoints(gasket, g2).empty());
}

TEST(FreeFormResize, ABezierCurveIsDegreeElevatedAndReducedAndStaysBezier) {
  const Project cubic = completePreset(FreeFormPreset::BezierCurve, 3);
  Project p = cubic;
  applyEdit(p, AddControlPoint{});
  ASSERT_EQ(p.space->control_points.size(), 5u);
  double r = 0.0;
  EXPECT_TRUE(isBezierCurve(p, &r));
  EXPECT_DOUBLE_EQ(r, 0.5);
  for (double t : {0.0, 0.3, 0.8, 1.0})
    EXPECT_LT(glm::length(deCasteljau(p.space->control_points, t) - deCasteljau(cubic.space->control_points, t)),
              1e-12);
  EXPECT_NO_THROW(validateProject(p));
  applyEdit(p, RemoveControlPoint{2});
  ASSERT_EQ(p.space->control_points.size(), 4u);
  EXPECT_TRUE(isBezierCurve(p));
  EXPECT_NO_THROW(validateProject(p));
  EXPECT_EQ(AddControlPoint{}.label(), "Add control point");
}

TEST(FreeFormResize, AnyOtherIfsGetsAZeroColumnAndKeepsItsAttractor) {
  const Project gasket = completePreset(FreeFormPreset::Sierpinski);
  Project p = gasket;
  applyEdit(p, AddControlPoint{Vec3{0.0, 0.0, 1.0}});
  ASSERT_EQ(p.space->control_points.size(), 4u);
  EXPECT_NO_THROW(validateProject(p));
  for (const Function& f : p.functions) {
    ASSERT_EQ(f.matrix.size(), 4u);
    expectRowsSumToOne(f.matrix);
    for (const auto& row : f.matrix) EXPECT_EQ(row[3], 0.0);
    EXPECT_LT(simplexContraction(f.matrix), 1.0);
  }
  // The attractor is unchanged: every point is on the plane z = 0 of the first three.
  for (const Vec3& q : chaosPoints(p, 5000)) EXPECT_NEAR(q.z, 0.0, 1e-6);
  // Removing it gives the gasket back exactly (its column was zero).
  applyEdit(p, RemoveControlPoint{3});
  EXPECT_EQ(p, gasket);
  // Never fewer than two points.
  Project two = completePreset(FreeFormPreset::BezierCurve, 1);
  EXPECT_THROW(applyEdit(two, RemoveControlPoint{0}), ModelError);
  // Removing a point of a patch shares its coordinate among the others.
  Project patch = completePreset(FreeFormPreset::BezierPatch, 2);
  applyEdit(patch, RemoveControlPoint{4});
  EXPECT_NO_THROW(validateProject(patch));
  for (const Function& f : patch.functions) expectRowsSumToOne(f.matrix);
}

TEST(ControlNet, AFlatNetReproducesThePlanarAttractorOfRotatingMaps) {
  // A dragon-like IFS whose maps rotate: a tensor-product patch could not carry them, a
  // triangular net of any degree can.
  Project grid = defaultNewProject();
  grid.functions = {affine("turn", 0.7071, 45, {-0.3, 0.0, 0.0}, 0.5),
                    affine("back", 0.7071, 135, {0.3, 0.0, 0.0}, 0.5)};
  const auto reference = chaosPoints(grid, 40000);
  for (int degree : {1, 2, 4}) {
    ControlNetOptions options;
    options.degree = degree;
    const ControlNetResult r = mapOntoControlNet(grid, options);
    EXPECT_EQ(r.dimension, 2);
    EXPECT_EQ(r.project.space->control_points.size(), std::size_t((degree + 1) * (degree + 2) / 2));
    EXPECT_TRUE(r.notes.empty());
    ASSERT_NO_THROW(validateProject(r.project));
    EXPECT_EQ(r.project.functions[1].name, "back");
    const auto mapped = chaosPoints(r.project, 4000);
    double worst = 0.0;
    for (std::size_t i = 0; i < mapped.size(); i += 10) worst = std::max(worst, nearest(reference, mapped[i]));
    EXPECT_LT(worst, 0.02) << "degree " << degree;
  }
}

TEST(ControlNet, ParaboloidsLiftTheGasketOntoTheirSurface) {
  const Project grid = gridGasket();
  for (ControlNetShape shape : {ControlNetShape::EllipticParaboloid, ControlNetShape::HyperbolicParaboloid}) {
    ControlNetOptions options;
    options.shape = shape;
    options.height = 0.4;
    const ControlNetResult r = mapOntoControlNet(grid, options);
    ASSERT_EQ(r.project.space->control_points.size(), 6u);
    const double sign = shape == ControlNetShape::EllipticParaboloid ? 1.0 : -1.0;
    const auto points = chaosPoints(r.project, 5000);
    ASSERT_GT(points.size(), 4000u);
    for (std::size_t i = 0; i < points.size(); i += 5) {
      const Vec3 q = points[i];
      // The gasket's box is [-1, 1]² (centre 0, half-width 1): z = h·(x² ± y²).
      EXPECT_NEAR(q.z, 0.4 * (q.x * q.x + sign * q.y * q.y), 1e-4);
      EXPECT_GE(q.y, -1.0 - 1e-4);
      EXPECT_LE(std::abs(q.x), 1.0 + 1e-4);
    }
  }
}

TEST(ControlNet, ASpatialIfsGetsATetrahedralNet) {
  Project grid = defaultNewProject();
  grid.functions = {affine("a", 0.5, 0, {-0.5, -0.5, -0.5}), affine("b", 0.5, 0, {0.5, -0.5, -0.5}),
                    affine("c", 0.5, 0, {0.0, 0.5, -0.5}), affine("d", 0.5, 30, {0.0, 0.0, 0.5})};
  const auto reference = chaosPoints(grid, 40000);
  ControlNetOptions options;
  options.degree = 2;
  const ControlNetResult r = mapOntoControlNet(grid, options);
  EXPECT_EQ(r.dimension, 3);
  EXPECT_EQ(r.project.space->control_points.size(), 10u);
  const auto mapped = chaosPoints(r.project, 3000);
  double worst = 0.0;
  for (std::size_t i = 0; i < mapped.size(); i += 10) worst = std::max(worst, nearest(reference, mapped[i]));
  EXPECT_LT(worst, 0.05);
  options.degree = 6;  // 84 points: over the limit in space
  EXPECT_THROW(mapOntoControlNet(grid, options), ModelError);
}

TEST(ControlNet, RefusesWhatItCannotMapAndNotesWhatIsOnlyNearlyAffine) {
  auto pathOf = [](const Project& p, ControlNetOptions o) {
    try {
      mapOntoControlNet(p, o);
    } catch (const ModelError& e) {
      return e.path();
    }
    return std::string("(accepted)");
  };
  const Project grid = gridGasket();
  ControlNetOptions o;
  o.degree = 0;
  EXPECT_EQ(pathOf(grid, o), "degree");
  o.degree = 8;
  EXPECT_EQ(pathOf(grid, o), "degree");
  o.degree = 1;
  o.shape = ControlNetShape::EllipticParaboloid;
  EXPECT_EQ(pathOf(grid, o), "degree");
  EXPECT_EQ(pathOf(completePreset(FreeFormPreset::Sierpinski), {}), "space");
  Project flame = grid;
  flame.functions[1].variations["sinusoidal"] = 1.0;
  EXPECT_EQ(pathOf(flame, {}), "functions[1].variations");
  Project growing = grid;
  growing.functions[0].placement.scale = Vec3{1.5};
  EXPECT_EQ(pathOf(growing, {}), "functions");
  Project twisted = grid;
  Operation twist;
  twist.params = TwistOp{Axis::Z, Profile::Linear, 1.0, 1.0};
  twisted.functions[2].ops.push_back(twist);
  const ControlNetResult r = mapOntoControlNet(twisted, {});
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_NE(r.notes[0].find("functions[2]"), std::string::npos);
  // The edit replaces the project as one step.
  Project edited = grid;
  applyEdit(edited, MapOntoControlNet{});
  EXPECT_TRUE(edited.space.has_value());
  EXPECT_EQ(editLabel(ProjectEdit{MapOntoControlNet{}}), "Map onto a control net");
}
