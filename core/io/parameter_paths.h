#pragma once
// Every number a project's file holds, by its parameter path ("functions[0].ops[1].k",
// "camera.target[2]"): the paths keyframe tracks, scripts and live bindings address
// (schema/project_parameter.h).
#include <string>
#include <vector>

#include "model/project.h"

namespace gridifs {

/// The parameter paths of `project` in the file's order, without "version" (the format's number,
/// not the project's) and without the keys of its tracks.
std::vector<std::string> parameterPaths(const Project& project);

}  // namespace gridifs
