#pragma once
// Reading and writing the animation fields of a project's JSON (used by the project reader and
// writer; the JSON library stays private to the io module).
#include <nlohmann/json.hpp>

#include "model/project.h"

namespace gridifs {

/// Reads "time", "animation" and "tracks" from a project's root object into `project`.
/// Throws ModelError with JSON paths (`tracks["camera.yaw"][1].t`).
void readAnimation(const nlohmann::json& root, Project& project);

/// Writes the fields readAnimation reads; nothing for a project that was never animated, so
/// files without them save unchanged.
void writeAnimation(const Project& project, nlohmann::ordered_json& root);

}  // namespace gridifs
