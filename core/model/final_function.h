#pragma once
// Adding and removing a project's final function: the map applied once more to every point
// before it is plotted (flam3's final xform; for a Bézier lattice, Sederberg & Parry 1986's
// free-form deformation, which Thollot et al. 1997, §5.5 apply to an attractor).
#include "model/project.h"

namespace gridifs {

/// What "Add final function" creates: an undistorted 6×6×6 lattice over X, named "final", that
/// keeps each point's colour. An undistorted lattice maps every point to itself, trilinear or
/// Bézier alike, so adding it leaves the picture as it was until the artist distorts it.
Function identityFinalFunction();

/// Removes the final function with the keyframe tracks on its parameters ("final.…").
void removeFinalFunction(Project& project);

}  // namespace gridifs
