#pragma once
// Named edits of a function's flame variations (Draves & Reckase 2003, §3: f(p) = post(Σ w_i V_i(g(p))),
// model/function_variations.h): add one, remove it, set the post map. Its weights and parameters are
// numbers set by SetParameter (edit/parameter_edit.h).
//
// Thread-safety: plain values; apply() touches only the project given. apply() throws ModelError
// when the function is not in the project, the variation is not a flame variation, or (removal)
// the function does not use it.
#include <optional>
#include <string>

#include "model/function_ref.h"
#include "model/project.h"

namespace gridifs {

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

/// Sets (or, with none, removes) the post map applied after the variations.
struct SetPostTransform {
  FunctionRef function;
  std::optional<PostTransform> post;
  void apply(Project& project) const;
  std::string label() const { return post ? "Post transform" : "Remove post transform"; }
};

}  // namespace gridifs
