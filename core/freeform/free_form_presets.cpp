#include "freeform/free_form_presets.h"

#include <cmath>

#include "base/hash.h"
#include "freeform/free_form_basis.h"

namespace gridifs {
namespace {

double binomial(int n, int k) {
  double c = 1.0;
  for (int i = 1; i <= k; ++i) c = c * double(n - k + i) / double(i);
  return c;
}

/// A deterministic value in [-1, 1] for (seed, a, b).
double jitter(std::uint64_t seed, std::uint64_t a, std::uint64_t b) {
  const std::uint64_t h = splitmix64(splitmix64(seed ^ 0x9E3779B97F4A7C15ull) ^ splitmix64(a * 131 + b));
  return double(h >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

/// Blends `row` towards a random probability vector: (1 − amount)·row + amount·q, q ≥ 0 with
/// Σq = 1. The row still sums to 1 and stays non-negative, so the matrix stays a Markov matrix
/// and the attractor keeps the convex-hull property.
void perturbRow(std::vector<double>& row, double amount, std::uint64_t seed, std::uint64_t id) {
  std::vector<double> q(row.size());
  double total = 0.0;
  for (std::size_t j = 0; j < row.size(); ++j) total += q[j] = 1.0 + jitter(seed, id, j);  // in [0, 2]
  if (!(total > 0.0)) return;
  for (std::size_t j = 0; j < row.size(); ++j) row[j] = (1.0 - amount) * row[j] + amount * q[j] / total;
}

/// Zair & Tosan's fractal curves (Thollot et al. 1997, §5.3.2): the two subdivision matrices with
/// their inner rows blended towards their own unit rows, row_i ← (1 − a_i)·row_i + a_i·e_i, a_i in
/// [amount/2, amount]. The matrices stay triangular Markov matrices, so their eigenvalues are the
/// new diagonal: 1, r + a(1 − r), r² + a(1 − r²), … Once the third exceeds the square of the second
/// the curve is no longer smooth but self-affine and rough. The end rows (the fixed points, the
/// curve's end points) and the joint row (left's last = right's first, T0·c1 = T1·c0) stay as they
/// are, so the curve still starts and ends at the end control points and the halves still meet.
void roughenHalves(BarycentricMatrix& left, BarycentricMatrix& right, double amount, std::uint64_t seed,
                   std::uint64_t salt) {
  if (amount == 0.0) return;
  for (std::size_t i = 1; i + 1 < left.size(); ++i) {
    for (auto* t : {&left, &right}) {
      const double a = amount * (0.75 + 0.25 * jitter(seed, salt * 1000 + (t == &left ? 0 : 100), i));
      auto& row = (*t)[i];
      for (std::size_t j = 0; j < row.size(); ++j) row[j] = (1.0 - a) * row[j] + (i == j ? a : 0.0);
    }
  }
}

Function matrixFunction(const std::string& name, BarycentricMatrix matrix, Vec3 color, double paletteIndex) {
  Function f;
  f.name = name;
  f.kind = FunctionKind::Matrix;
  f.matrix = std::move(matrix);
  f.color = color;
  f.palette_index = paletteIndex;
  return f;
}

const Vec3 kColors[4] = {{1.0, 0.55, 0.2}, {0.3, 0.7, 1.0}, {0.5, 1.0, 0.45}, {1.0, 0.35, 0.6}};

}  // namespace

const char* freeFormPresetName(FreeFormPreset preset) {
  switch (preset) {
    case FreeFormPreset::BezierCurve:
      return "bezier-curve";
    case FreeFormPreset::BezierPatch:
      return "bezier-patch";
    case FreeFormPreset::Sierpinski:
      return "sierpinski";
    case FreeFormPreset::SierpinskiPatch:
      return "sierpinski-patch";
    case FreeFormPreset::BSplineCurve:
      return "bspline-curve";
    case FreeFormPreset::BSplinePatch:
      return "bspline-patch";
  }
  return "bezier-curve";
}

bool parseFreeFormPreset(const std::string& name, FreeFormPreset& out) {
  for (FreeFormPreset p : {FreeFormPreset::BezierCurve, FreeFormPreset::BezierPatch, FreeFormPreset::Sierpinski,
                           FreeFormPreset::SierpinskiPatch, FreeFormPreset::BSplineCurve, FreeFormPreset::BSplinePatch})
    if (name == freeFormPresetName(p)) {
      out = p;
      return true;
    }
  return false;
}

std::vector<double> bernstein(int degree, double t) {
  std::vector<double> b(std::size_t(degree) + 1);
  for (int i = 0; i <= degree; ++i)
    b[std::size_t(i)] = binomial(degree, i) * std::pow(t, i) * std::pow(1.0 - t, degree - i);
  return b;
}

BarycentricMatrix deCasteljauLeft(int degree, double r) {
  // Row i holds the i-th control point of the left piece: Σ_j B_j^i(r) p_j (de Casteljau).
  const std::size_t m = std::size_t(degree) + 1;
  BarycentricMatrix t(m, std::vector<double>(m, 0.0));
  for (int i = 0; i <= degree; ++i)
    for (int j = 0; j <= i; ++j)
      t[std::size_t(i)][std::size_t(j)] = binomial(i, j) * std::pow(r, j) * std::pow(1.0 - r, i - j);
  return t;
}

BarycentricMatrix deCasteljauRight(int degree, double r) {
  // Row i: the right piece's i-th control point, Σ_{j≥i} B_{j−i}^{n−i}(r) p_j.
  const std::size_t m = std::size_t(degree) + 1;
  BarycentricMatrix t(m, std::vector<double>(m, 0.0));
  for (int i = 0; i <= degree; ++i)
    for (int j = i; j <= degree; ++j)
      t[std::size_t(i)][std::size_t(j)] =
          binomial(degree - i, j - i) * std::pow(r, j - i) * std::pow(1.0 - r, degree - j);
  return t;
}

std::vector<Vec3> defaultCurveControlPoints(int degree) {
  if (degree == 3) return {{-0.9, 0.0, -0.6}, {-0.4, 0.3, 0.9}, {0.4, -0.3, -0.9}, {0.9, 0.0, 0.6}};  // +z is up
  // A zigzag polygon along x, gentler at its ends, turning a little in y.
  std::vector<Vec3> points;
  for (int i = 0; i <= degree; ++i) {
    const double u = double(i) / degree, end = (i == 0 || i == degree) ? 0.6 : 1.0;
    points.push_back(Vec3{-0.9 + 1.8 * u, 0.3 * std::sin(2.0 * M_PI * u), 0.8 * end * (i % 2 ? 1.0 : -1.0)});
  }
  return points;
}

std::vector<Vec3> defaultPatchControlPoints(int degree) {
  std::vector<Vec3> points;
  if (degree == 3) {
    const double z[4][4] = {{0.0, 0.3, 0.2, -0.1}, {0.2, 0.8, 0.6, 0.1}, {-0.1, 0.5, 0.9, 0.2}, {-0.3, 0.0, 0.2, 0.0}};
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 4; ++k) points.push_back(Vec3{-0.9 + 0.6 * i, -0.9 + 0.6 * k, z[i][k] - 0.3});
    return points;
  }
  // A bump, higher towards one corner, over the square [-0.9, 0.9]².
  for (int i = 0; i <= degree; ++i)
    for (int k = 0; k <= degree; ++k) {
      const double u = double(i) / degree, v = double(k) / degree;
      points.push_back(
          Vec3{-0.9 + 1.8 * u, -0.9 + 1.8 * v, 1.1 * std::sin(M_PI * u) * std::sin(M_PI * v) * (0.6 + 0.4 * u) - 0.3});
    }
  return points;
}

std::vector<Vec3> defaultTriangleControlPoints() { return {{-0.9, -0.75, 0.0}, {0.9, -0.75, 0.0}, {0.0, 0.85, 0.0}}; }

namespace {

void checkOptions(const FreeFormPresetOptions& options) {
  if (!(options.degree >= kMinPresetDegree && options.degree <= kMaxPresetDegree))
    throw ModelError("degree", "expected a degree between " + std::to_string(kMinPresetDegree) + " and " +
                                   std::to_string(kMaxPresetDegree) + ", found " + std::to_string(options.degree));
  if (!(options.split > 0.0 && options.split < 1.0)) throw ModelError("split", "expected a number between 0 and 1");
  if (!(options.roughness >= 0.0 && options.roughness <= 1.0))
    throw ModelError("roughness", "expected a number between 0 and 1");
}

/// Thollot et al. 1997, §5.4.2: a patch is the attractor of the tensor products of its curves'
/// matrices, piece qIK = s-half I ⊗ t-half K; the gasket (§5.5) keeps three of the four quarters.
void addPatchPieces(Project& project, const BarycentricMatrix* s[2], const BarycentricMatrix* t[2], bool gasket) {
  int c = 0;
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 2; ++k) {
      if (gasket && i == 1 && k == 1) continue;
      project.functions.push_back(matrixFunction("q" + std::to_string(i) + std::to_string(k),
                                                 kroneckerProduct(*s[i], *t[k]), kColors[c], c / 3.0));
      ++c;
    }
}

void addSierpinski(Project& project, const FreeFormPresetOptions& options) {
  project.space->control_points = defaultTriangleControlPoints();
  for (std::size_t k = 0; k < 3; ++k) {
    // λ ← (λ + e_k)/2: every row is half itself and half corner k.
    BarycentricMatrix t(3, std::vector<double>(3, 0.0));
    for (std::size_t i = 0; i < 3; ++i) {
      t[i][i] += 0.5;
      t[i][k] += 0.5;
    }
    if (options.roughness != 0.0)
      for (std::size_t i = 0; i < 3; ++i)
        if (i != k) perturbRow(t[i], options.roughness, options.seed, 10 * k + i);
    project.functions.push_back(matrixFunction("corner " + std::to_string(k + 1), t, kColors[k], k / 2.0));
  }
}

}  // namespace

void applyFreeFormPreset(Project& project, FreeFormPreset preset, const FreeFormPresetOptions& options) {
  checkOptions(options);
  project.functions.clear();
  project.transitions.clear();
  project.space = FreeFormSpace{};
  const int n = options.degree;
  const bool bspline = preset == FreeFormPreset::BSplineCurve || preset == FreeFormPreset::BSplinePatch;
  BarycentricMatrix left = bspline ? bsplineSubdivisionLeft(n) : deCasteljauLeft(n, options.split);
  BarycentricMatrix right = bspline ? bsplineSubdivisionRight(n) : deCasteljauRight(n, options.split);
  switch (preset) {
    case FreeFormPreset::BezierCurve:
    case FreeFormPreset::BSplineCurve:
      if (!bspline) roughenHalves(left, right, options.roughness, options.seed, 1);
      project.space->control_points = defaultCurveControlPoints(n);
      project.functions.push_back(matrixFunction("left", left, kColors[0], 0.0));
      project.functions.push_back(matrixFunction("right", right, kColors[1], 1.0));
      break;
    case FreeFormPreset::BezierPatch:
    case FreeFormPreset::BSplinePatch:
    case FreeFormPreset::SierpinskiPatch: {
      BarycentricMatrix left2 = left, right2 = right;
      if (!bspline) {
        roughenHalves(left, right, options.roughness, options.seed, 1);
        roughenHalves(left2, right2, options.roughness, options.seed, 2);
      }
      project.space->control_points = defaultPatchControlPoints(n);
      const BarycentricMatrix* s[2] = {&left, &right};
      const BarycentricMatrix* t[2] = {&left2, &right2};
      addPatchPieces(project, s, t, preset == FreeFormPreset::SierpinskiPatch);
      break;
    }
    case FreeFormPreset::Sierpinski:
      addSierpinski(project, options);
      break;
  }
}

}  // namespace gridifs
