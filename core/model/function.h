#pragma once
// One function of the IFS: a grid resolution, an op stack and a placement.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "model/condensation_set.h"
#include "model/function_kind.h"
#include "model/function_variations.h"
#include "model/operation.h"
#include "model/placement.h"

namespace gridifs {

struct Function {
  std::string name = "f1";
  Index3 resolution{6, 6, 6};
  std::vector<Operation> ops;
  Placement placement;
  double weight = 1.0;         // selection probability ∝ weight
  Vec3 color{1.0, 1.0, 1.0};   // RGB in [0, 1]
  double palette_index = 0.0;  // structural color coordinate c_i in [0, 1] (Draves & Reckase 2003, §5)
  double color_speed = 0.5;    // c = mix(c, c_i, color_speed); 0.5 is (c + c_i)/2 of Draves & Reckase 2003
  bool muted = false;
  /// "sampling_error": set when the grid samples a map given in closed form (a flame xform on
  /// import): the largest distance, in X units, between the grid and that map at cell centres.
  std::optional<double> sampling_error;
  /// "kind": Matrix functions ignore every grid field above and act through `matrix`.
  FunctionKind kind = FunctionKind::Grid;
  /// "matrix" of a Matrix function: m×m, rows summing to 1; λ ← λ·matrix (Thollot et al. 1997, §3.1).
  std::vector<std::vector<double>> matrix;
  /// "set" of a Condensation or Median function (Sokolov & Gentil, §3.1–3.2); unused by the others.
  CondensationSet set;
  /// "rotate" of a Median function: degrees per unit of distance between the sets' centres, about z
  /// (Sokolov & Gentil, §4.1: the rotated median).
  double rotate = 0.0;
  /// "rotate_axis" of a Median function: the axis of that rotation (need not be unit length).
  Vec3 rotate_axis{0.0, 0.0, 1.0};
  /// "variations": the flame variations' weights by name (f(p) = post(Σ w_i V_i(g(p))), see
  /// model/function_variations.h); empty: f = g. Grid functions only.
  std::map<std::string, double> variations;
  /// "variation_params": the variations' parameters by flam3's attribute names (`rings2_val`).
  std::map<std::string, double> variation_params;
  /// "post": the affine map after the variations (Draves & Reckase 2003, §3.1).
  std::optional<PostTransform> post;
  /// Whether f differs from its grid map g (variations or a post transform).
  bool hasVariationStage() const { return !variations.empty() || post.has_value(); }
  /// "interpolation": how the final function's lattice maps points (ignored in the loop).
  LatticeInterpolation interpolation = LatticeInterpolation::Trilinear;
  bool operator==(const Function&) const = default;
};

}  // namespace gridifs
