#pragma once
// How named edits (edit/project_edit.h) find what they change: a function by index or
// FunctionRef, an operation of a function, a light of the shading. Each throws ModelError naming
// the missing part ("functions[4]: the project has no such function"), so an edit that refers
// to something the project no longer has is refused instead of writing out of bounds.
//
// Thread-safety: pure functions of their arguments.
#include "model/function_ref.h"
#include "model/project.h"

namespace gridifs {

/// Function `index` of the IFS (a negative index is no function, unlike FunctionRef's).
Function& functionAt(Project& project, int index);
/// Operation `index` of `function`'s stack.
Operation& operationAt(Project& project, FunctionRef function, int index);
/// Light `index` of render.shading.lights.
ShadingLight& lightAt(Project& project, std::size_t index);

}  // namespace gridifs
