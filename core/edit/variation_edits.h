#pragma once
// Named edits of a function's flame variations (Draves & Reckase 2003, §3: f(p) = post(Σ w_i V_i(g(p))),
// model/function_variations.h): add one, change its weight or a parameter, remove it, set the post map.
//
// Thread-safety: plain values; apply() touches only the project given. apply() throws ModelError
// when the function is not in the project, the variation is not a flame variation, or (removal)
// the function does not use it.
#include <optional>
#include <string>

#include "model/function_ref.h"
#include "model/project.h"

namespace gridifs {

/// Sets the weight of variation `name` (adding it when the function does not use it yet).
struct SetVariationWeight {
  FunctionRef function;
  std::string name;
  double weight = 1.0;
  void apply(Project& project) const;
  std::string label() const { return "Variation weight"; }
};

/// Adds variation `name`: with weight 1 to a function without variations (f becomes V(g(p))),
/// else with weight 0.5, so that the shape it adds shows at once.
struct AddVariation {
  FunctionRef function;
  std::string name;
  void apply(Project& project) const;
  std::string label() const { return "Add variation " + name; }
};

/// Removes variation `name` and the parameters only it reads.
struct RemoveVariation {
  FunctionRef function;
  std::string name;
  void apply(Project& project) const;
  std::string label() const { return "Remove variation " + name; }
};

/// Sets a variation parameter by its flam3 attribute name (`rings2_val`).
struct SetVariationParameter {
  FunctionRef function;
  std::string attribute;
  double value = 0.0;
  void apply(Project& project) const;
  std::string label() const { return "Variation parameter"; }
};

/// Sets (or, with none, removes) the post map applied after the variations.
struct SetPostTransform {
  FunctionRef function;
  std::optional<PostTransform> post;
  void apply(Project& project) const;
  std::string label() const { return post ? "Post transform" : "Remove post transform"; }
};

}  // namespace gridifs
