#include "model/function_variations.h"

#include <cmath>

#include "base/errors.h"
#include "base/types.h"
#include "model/stack_evaluator.h"
#include "variations/flame_variations.h"

namespace gridifs {

std::array<std::array<double, 4>, 3> PostTransform::affine() const {
  if (matrix) return *matrix;
  std::array<std::array<double, 4>, 3> m{};
  const Vec3 origin = applyPlacement(placement, Vec3(0.0));
  for (int column = 0; column < 3; ++column) {
    Vec3 axis(0.0);
    axis[column] = 1.0;
    const Vec3 image = applyPlacement(placement, axis) - origin;
    for (int row = 0; row < 3; ++row) m[std::size_t(row)][std::size_t(column)] = image[row];
  }
  for (int row = 0; row < 3; ++row) m[std::size_t(row)][3] = origin[row];
  return m;
}

void validateFunctionVariations(const std::map<std::string, double>& variations,
                                const std::map<std::string, double>& params) {
  for (const auto& [name, weight] : variations) {
    if (!findFlameVariation(name)) throw ModelError("variations." + name, "\"" + name + "\" is not a flame variation");
    if (!std::isfinite(weight) || std::abs(weight) > limits::kMaxCoordinate)
      throw ModelError("variations." + name,
                       "the weight of variation " + name + " is not a finite number of magnitude at most 1e6");
  }
  for (const auto& [attribute, value] : params) {
    int variation = -1, parameter = -1;
    if (!findVariationParameter(attribute, variation, parameter))
      throw ModelError("variation_params." + attribute,
                       "\"" + attribute + "\" is not a parameter of any flame variation");
    if (!std::isfinite(value) || std::abs(value) > limits::kMaxCoordinate)
      throw ModelError("variation_params." + attribute,
                       "variation parameter " + attribute + " is not a finite number of magnitude at most 1e6");
  }
}

}  // namespace gridifs
