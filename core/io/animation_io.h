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

/// The modeller's keyframing rule for an edit that turned `before` into `next`: a tracked
/// parameter whose value the edit changed gets a key at next.time holding its new value (a key
/// already there keeps its interpolation), then every tracked parameter takes its track's value
/// at next.time, so what panels show is always the animation at the current time. Returns `next`
/// unchanged when it has no tracks. Throws ModelError like projectAtTime.
Project keyEditedParameters(const Project& before, Project next);

}  // namespace gridifs
