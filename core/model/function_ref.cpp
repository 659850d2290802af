#include "model/function_ref.h"

#include "base/errors.h"

namespace gridifs {

bool FunctionRef::existsIn(const Project& project) const {
  return isFinal() ? project.final_function.has_value() : std::size_t(index_) < project.functions.size();
}

const Function& FunctionRef::in(const Project& project) const {
  if (!existsIn(project)) throw ModelError(path(), "the project has no such function");
  return isFinal() ? *project.final_function : project.functions[std::size_t(index_)];
}

Function& FunctionRef::in(Project& project) const {
  return const_cast<Function&>(in(static_cast<const Project&>(project)));
}

std::string FunctionRef::path() const {
  return isFinal() ? std::string("final") : "functions[" + std::to_string(index_) + "]";
}

}  // namespace gridifs
