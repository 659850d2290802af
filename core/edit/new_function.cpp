#include "edit/new_function.h"

#include <algorithm>

namespace gridifs {
namespace {

/// The palette index of the function added at `index`: spread over [0, 1] by quarters.
double newPaletteIndex(std::size_t index) { return index == 0 ? 0.0 : std::min(1.0, double(index) / 4.0); }

}  // namespace

std::string uniqueFunctionName(const Project& project, const std::string& base) {
  for (int n = 1;; ++n) {
    const std::string name = base + std::to_string(n);
    if (std::none_of(project.functions.begin(), project.functions.end(),
                     [&](const Function& f) { return f.name == name; }))
      return name;
  }
}

Vec3 newFunctionColor(std::size_t index) {
  static const Vec3 palette[] = {{1.0, 0.6, 0.2},   {0.3, 0.7, 1.0},  {0.5, 0.95, 0.4},  {0.95, 0.35, 0.55},
                                 {0.95, 0.85, 0.3}, {0.6, 0.45, 1.0}, {0.3, 0.95, 0.85}, {1.0, 0.45, 0.3}};
  return palette[index % (sizeof palette / sizeof palette[0])];
}

Function newGridFunction(const Project& project) {
  const std::size_t index = project.functions.size();
  Function f;
  f.name = uniqueFunctionName(project, "f");
  f.placement.scale = Vec3(0.5);
  f.color = newFunctionColor(index);
  f.palette_index = newPaletteIndex(index);
  if (project.space) {
    const std::size_t m = project.space->control_points.size();
    f.kind = FunctionKind::Matrix;
    f.matrix.assign(m, std::vector<double>(m, 0.5 / double(m)));
    for (std::size_t i = 0; i < m; ++i) f.matrix[i][i] += 0.5;
  }
  return f;
}

Function newSetFunction(const Project& project, FunctionKind kind) {
  const std::size_t index = project.functions.size();
  Function f;
  f.kind = kind;
  f.name = uniqueFunctionName(project, kind == FunctionKind::Median ? "median" : "cond");
  f.set.shape = SetShape::Sphere;
  f.set.center = Vec3{0.0};
  f.set.radius = 0.3;
  f.set.size = Vec3{0.6};
  f.set.major = 0.25;
  f.set.minor = 0.08;
  f.color = newFunctionColor(index);
  f.palette_index = newPaletteIndex(index);
  return f;
}

}  // namespace gridifs
