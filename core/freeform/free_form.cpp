#include "freeform/free_form.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gridifs {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw ModelError(path, message); }

std::string item(const std::string& path, std::size_t index) { return path + "[" + std::to_string(index) + "]"; }

void checkMatrix(const BarycentricMatrix& t, std::size_t m, const std::string& path) {
  if (t.size() != m)
    fail(path, "expected " + std::to_string(m) + " rows (one per control point), found " + std::to_string(t.size()));
  for (std::size_t i = 0; i < m; ++i) {
    const std::string row = item(path, i);
    if (t[i].size() != m)
      fail(row,
           "expected " + std::to_string(m) + " entries (one per control point), found " + std::to_string(t[i].size()));
    double sum = 0.0;
    for (std::size_t j = 0; j < m; ++j) {
      if (!std::isfinite(t[i][j])) fail(item(row, j), "expected a finite number");
      sum += t[i][j];
    }
    if (!(std::abs(sum - 1.0) <= kRowSumTolerance)) {
      std::ostringstream s;
      s.precision(12);
      s << "the row sums to " << sum << ", not 1 (barycentric coordinates must keep summing to 1)";
      fail(row, s.str());
    }
  }
}

}  // namespace

const char* functionKindName(FunctionKind kind) {
  switch (kind) {
    case FunctionKind::Matrix:
      return "matrix";
    case FunctionKind::Condensation:
      return "condensation";
    case FunctionKind::Median:
      return "median";
    case FunctionKind::Grid:
      break;
  }
  return "grid";
}

const char* latticeInterpolationName(LatticeInterpolation interpolation) {
  return interpolation == LatticeInterpolation::Bezier ? "bezier" : "trilinear";
}

void checkFreeForm(const Project& project) {
  std::size_t m = 0;
  if (project.space) {
    m = project.space->control_points.size();
    if (m < std::size_t(limits::kMinControlPoints) || m > std::size_t(limits::kMaxControlPoints))
      fail("space.control_points", "expected between " + std::to_string(limits::kMinControlPoints) + " and " +
                                       std::to_string(limits::kMaxControlPoints) + " control points, found " +
                                       std::to_string(m));
    for (std::size_t j = 0; j < m; ++j) {
      const Vec3& p = project.space->control_points[j];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        fail(item("space.control_points", j), "expected finite coordinates");
    }
  }
  for (std::size_t f = 0; f < project.functions.size(); ++f) {
    const Function& fn = project.functions[f];
    const std::string path = item("functions", f);
    if (fn.interpolation != LatticeInterpolation::Trilinear)
      fail(path + ".interpolation", "only the final function's lattice may be interpolated as \"bezier\"");
    if (isSetKind(fn.kind)) continue;  // checked by checkCondensationSets
    if (project.space && fn.kind != FunctionKind::Matrix)
      fail(path + ".kind", "a project with control points (\"space\") needs \"matrix\" functions");
    if (!project.space && fn.kind == FunctionKind::Matrix)
      fail(path + ".kind", "a \"matrix\" function needs control points (\"space\": {\"control_points\": …})");
    if (fn.kind == FunctionKind::Matrix) {
      if (!fn.ops.empty()) fail(path + ".ops", "a \"matrix\" function has no grid, so no grid operations");
      checkMatrix(fn.matrix, m, path + ".matrix");
    }
  }
  if (project.final_function) {
    const Function& fn = *project.final_function;
    if (fn.kind != FunctionKind::Grid) fail("final.kind", "the final function must be a grid (a lattice)");
    if (fn.interpolation == LatticeInterpolation::Bezier)
      for (int d = 0; d < 3; ++d)
        if (fn.resolution[d] > kMaxBezierLatticeNodes)
          fail(item("final.resolution", std::size_t(d)),
               "a \"bezier\" lattice has at most " + std::to_string(kMaxBezierLatticeNodes) +
                   " nodes per axis, found " + std::to_string(fn.resolution[d]));
  }
}

std::vector<std::string> freeFormWarnings(const Project& project) {
  std::vector<std::string> out;
  for (std::size_t f = 0; f < project.functions.size(); ++f) {
    const Function& fn = project.functions[f];
    if (fn.kind != FunctionKind::Matrix) continue;
    bool negative = false;
    for (const auto& row : fn.matrix)
      for (double v : row) negative |= v < 0.0;
    if (negative)
      out.push_back("functions[" + std::to_string(f) +
                    "].matrix has negative entries: the attractor may leave the convex hull of the control points");
  }
  return out;
}

double simplexContraction(const BarycentricMatrix& matrix) {
  double worst = 0.0;
  for (std::size_t i = 0; i < matrix.size(); ++i)
    for (std::size_t k = i + 1; k < matrix.size(); ++k) {
      double d = 0.0;
      for (std::size_t j = 0; j < matrix[i].size() && j < matrix[k].size(); ++j)
        d += std::abs(matrix[i][j] - matrix[k][j]);
      worst = std::max(worst, 0.5 * d);
    }
  return worst;
}

std::vector<double> applyMatrix(const std::vector<double>& lambda, const BarycentricMatrix& matrix) {
  const std::size_t m = matrix.empty() ? 0 : matrix[0].size();
  std::vector<double> out(m, 0.0);
  for (std::size_t i = 0; i < lambda.size() && i < matrix.size(); ++i)
    for (std::size_t j = 0; j < m; ++j) out[j] += lambda[i] * matrix[i][j];
  return out;
}

Vec3 projectBarycentric(const std::vector<Vec3>& controlPoints, const std::vector<double>& lambda) {
  Vec3 p{0.0};
  for (std::size_t j = 0; j < controlPoints.size() && j < lambda.size(); ++j) p += lambda[j] * controlPoints[j];
  return p;
}

BarycentricMatrix identityMatrix(std::size_t m) {
  BarycentricMatrix out(m, std::vector<double>(m, 0.0));
  for (std::size_t i = 0; i < m; ++i) out[i][i] = 1.0;
  return out;
}

BarycentricMatrix kroneckerProduct(const BarycentricMatrix& a, const BarycentricMatrix& b) {
  const std::size_t n = a.size(), m = b.size();
  BarycentricMatrix out(n * m, std::vector<double>(n * m, 0.0));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t k = 0; k < m; ++k)
        for (std::size_t l = 0; l < m; ++l) out[i * m + k][j * m + l] = a[i][j] * b[k][l];
  return out;
}

}  // namespace gridifs
