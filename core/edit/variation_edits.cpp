#include "edit/variation_edits.h"

#include "base/errors.h"
#include "variations/flame_variations.h"

namespace gridifs {
namespace {

const FlameVariation& knownVariation(const std::string& name) {
  const FlameVariation* v = findFlameVariation(name);
  if (!v) throw ModelError("variations." + name, "\"" + name + "\" is not a flame variation");
  return *v;
}

}  // namespace

void AddVariation::apply(Project& project) const {
  knownVariation(name);
  Function& f = function.in(project);
  if (f.variations.count(name)) return;
  f.variations[name] = f.variations.empty() ? 1.0 : 0.5;
}

void RemoveVariation::apply(Project& project) const {
  const FlameVariation& v = knownVariation(name);
  Function& f = function.in(project);
  if (!f.variations.erase(name)) throw ModelError("variations." + name, "the function does not use variation " + name);
  for (const auto& [attribute, fallback] : v.params) f.variation_params.erase(attribute);
}

void SetPostTransform::apply(Project& project) const { function.in(project).post = post; }

}  // namespace gridifs
