#include "freeform/free_form_resize.h"

#include <cmath>

#include "freeform/free_form.h"
#include "freeform/free_form_presets.h"

namespace gridifs {
namespace {

const char* const kPoints = "space.control_points";

bool near(const BarycentricMatrix& a, const BarycentricMatrix& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].size() != b[i].size()) return false;
    for (std::size_t j = 0; j < a[i].size(); ++j)
      if (!(std::abs(a[i][j] - b[i][j]) <= 1e-9)) return false;
  }
  return true;
}

std::size_t pointCount(const Project& project) {
  if (!project.space) throw ModelError(kPoints, "the project has no control points");
  return project.space->control_points.size();
}

}  // namespace

bool isBezierCurve(const Project& project, double* r) {
  if (!project.space || project.functions.size() != 2) return false;
  const std::size_t m = project.space->control_points.size();
  const BarycentricMatrix& left = project.functions[0].matrix;
  if (m < 2 || left.size() != m || left[1].size() != m) return false;
  const double split = left[1][1];  // row 1 of the left half is (1 − r, r, 0, …)
  if (!(split > 0.0 && split < 1.0)) return false;
  const int degree = int(m) - 1;
  if (!near(left, deCasteljauLeft(degree, split)) ||
      !near(project.functions[1].matrix, deCasteljauRight(degree, split)))
    return false;
  if (r) *r = split;
  return true;
}

void addControlPoint(Project& project, std::optional<Vec3> point) {
  const std::size_t m = pointCount(project);
  if (m + 1 > std::size_t(limits::kMaxControlPoints))
    throw ModelError(kPoints,
                     "a free-form IFS has at most " + std::to_string(limits::kMaxControlPoints) + " control points");
  auto& points = project.space->control_points;
  double r = 0.5;
  if (isBezierCurve(project, &r)) {
    // Degree elevation: p'_i = i/(n+1)·p_{i−1} + (1 − i/(n+1))·p_i, the same curve.
    const std::size_t n = m - 1;
    std::vector<Vec3> elevated(m + 1);
    for (std::size_t i = 0; i <= n + 1; ++i) {
      const double a = double(i) / double(n + 1);
      elevated[i] = (i > 0 ? a * points[i - 1] : Vec3{0.0}) + (i <= n ? (1.0 - a) * points[i] : Vec3{0.0});
    }
    points = elevated;
    project.functions[0].matrix = deCasteljauLeft(int(m), r);
    project.functions[1].matrix = deCasteljauRight(int(m), r);
    return;
  }
  Vec3 centroid{0.0};
  for (const Vec3& p : points) centroid += p / double(m);
  points.push_back(point.value_or(centroid));
  for (Function& f : project.functions) {
    if (f.kind != FunctionKind::Matrix) continue;
    std::vector<double> mean(m + 1, 0.0);
    for (auto& row : f.matrix) {
      for (std::size_t j = 0; j < m && j < row.size(); ++j) mean[j] += row[j] / double(m);
      row.push_back(0.0);
    }
    f.matrix.push_back(mean);
  }
}

void removeControlPoint(Project& project, std::size_t index) {
  const std::size_t m = pointCount(project);
  if (index >= m)
    throw ModelError(std::string(kPoints) + "[" + std::to_string(index) + "]", "the project has no such control point");
  if (m - 1 < std::size_t(limits::kMinControlPoints))
    throw ModelError(kPoints,
                     "a free-form IFS needs at least " + std::to_string(limits::kMinControlPoints) + " control points");
  auto& points = project.space->control_points;
  double r = 0.5;
  const bool bezier = isBezierCurve(project, &r);
  points.erase(points.begin() + std::ptrdiff_t(index));
  if (bezier) {
    project.functions[0].matrix = deCasteljauLeft(int(m) - 2, r);
    project.functions[1].matrix = deCasteljauRight(int(m) - 2, r);
    return;
  }
  for (Function& f : project.functions) {
    if (f.kind != FunctionKind::Matrix || f.matrix.size() != m) continue;
    f.matrix.erase(f.matrix.begin() + std::ptrdiff_t(index));
    for (std::size_t i = 0; i < f.matrix.size(); ++i) {
      auto& row = f.matrix[i];
      if (row.size() != m) continue;
      const double gone = row[index];
      row.erase(row.begin() + std::ptrdiff_t(index));
      if (std::abs(1.0 - gone) > 1e-12) {
        for (double& v : row) v /= 1.0 - gone;
      } else {
        row.assign(m - 1, 0.0);
        row[i] = 1.0;
      }
    }
  }
}

}  // namespace gridifs
