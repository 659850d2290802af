#pragma once
// Evaluating a project's construction tree (Thollot, Zair, Tosan & Vandorpe 1997, §4.3): each
// inner node is one of the matrix combinations of construction/ifs_combination.h, looked up by
// name in one table. The tree's data lives with the project (model/construction_tree.h).
#include <cstddef>
#include <string>
#include <vector>

#include "construction/ifs_combination.h"
#include "model/construction_tree.h"
#include "model/project.h"

namespace gridifs {

/// The tree's value: the project of its root (functions, transitions, space; the rest is the
/// first leaf's). Throws ModelError at the JSON path of the node that fails: an unloaded file
/// leaf, or an operation whose operands cannot be combined (the sentence says why).
Project evaluateConstructionTree(const ConstructionTree& tree);

/// Makes `project`'s functions, transitions and space those of `evaluated` (the camera,
/// render settings, final function, time and tracks stay the project's).
void adoptEvaluation(Project& project, const Project& evaluated);

/// Re-evaluates `project`'s tree (when it has one) and adopts the result. Throws as
/// evaluateConstructionTree.
void reevaluateConstruction(Project& project);

/// The function set a part made of `project`'s functions `indices` holds (their transitions
/// restricted to them, the free-form space kept). Throws ModelError when `indices` is empty or
/// names a function the project lacks.
Project partOfFunctions(const Project& project, const std::vector<std::size_t>& indices);

}  // namespace gridifs
