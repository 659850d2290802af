#pragma once
// The project at a moment of its animation: every keyframe track evaluated and written to its
// parameter, and the modeller's rule that keys the animated parameters an edit changes. Tracks
// reach their parameters through typed accessors (schema/project_parameter.h), resolved once per
// call, so neither an edit nor a time change goes through the project file's JSON.
//
// Thread-safety: pure functions of their arguments.
#include "model/project.h"

namespace gridifs {

/// Checks that every track names a number of the project file (`functions[0].ops[1].k`).
/// Throws ModelError naming the track (`tracks["functions[9].weight"]: names no parameter of
/// this project (was it deleted?)`).
void checkTrackPaths(const Project& project);

/// The project at time t: every track evaluated at t and written to its parameter, `time` set
/// to t. The result is validated like a loaded project: a key whose value a parameter does not
/// accept is reported with that parameter's path, the file reader's words and the time.
/// Throws ModelError (a track that names no number, as checkTrackPaths; an invalid result).
Project projectAtTime(const Project& project, double t);

/// The modeller's keyframing rule for an edit that turned `before` into `next`: a tracked
/// parameter whose value the edit changed gets a key at next.time holding its new value (a key
/// already there keeps its interpolation), then every tracked parameter takes its track's value
/// at next.time, so what panels show is always the animation at the current time. Returns `next`
/// unchanged when it has no tracks. Throws ModelError like projectAtTime.
Project keyEditedParameters(const Project& before, Project next);

}  // namespace gridifs
