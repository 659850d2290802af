#pragma once
// Function > Add symmetry (Draves & Reckase 2003, §7): n-way rotational or dihedral symmetry about
// the preview's view axis, added as functions (core/flame_symmetry.h) in one undo step.
#include "ui/base/edit_queue.h"
#include "ui/base/modeller_state.h"

namespace gridifs::ui {

/// The "Add symmetry" submenu; call inside an open menu.
void drawSymmetryMenu(ModellerState& state, EditQueue& edits);

}  // namespace gridifs::ui
