#include "edit/edit_refs.h"

#include "base/errors.h"

namespace gridifs {

Function& functionAt(Project& project, int index) {
  if (index < 0 || std::size_t(index) >= project.functions.size())
    throw ModelError("functions[" + std::to_string(index) + "]", "the project has no such function");
  return project.functions[std::size_t(index)];
}

Operation& operationAt(Project& project, FunctionRef function, int index) {
  Function& f = function.in(project);
  if (index < 0 || std::size_t(index) >= f.ops.size())
    throw ModelError(function.path() + ".ops[" + std::to_string(index) + "]", "the function has no such operation");
  return f.ops[std::size_t(index)];
}

ShadingLight& lightAt(Project& project, std::size_t index) {
  auto& lights = project.render.shading.lights;
  if (index >= lights.size())
    throw ModelError("render.shading.lights[" + std::to_string(index) + "]", "the shading has no such light");
  return lights[index];
}

}  // namespace gridifs
