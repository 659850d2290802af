#pragma once
// The project file's time, timeline and keyframe tracks ("time", "animation", "tracks"), and
// the project as it stands at a moment of its animation.
#include "model/project.h"

namespace gridifs {

/// Checks that every track names a number in the project's JSON (`functions[0].ops[1].k`).
/// Throws ModelError naming the track.
void checkTrackPaths(const Project& project);

/// The project at time t: every track evaluated at t and written to its parameter, `time` set
/// to t. The result is validated like a loaded project (a key whose value a parameter does not
/// accept is reported with that parameter's path and the time).
Project projectAtTime(const Project& project, double t);

}  // namespace gridifs
