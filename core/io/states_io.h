#pragma once
// Reading and writing a project's "states" (internal to io/): the IFS matrix with states of
// Thollot, Zair, Tosan & Vandorpe 1997, §3.2 (model/ifs_states.h). Entries name functions by index
// or by name; they are written as indices. Throws ModelError with a JSON path.
#include <nlohmann/json.hpp>
#include <optional>

#include "model/project.h"

namespace gridifs::states_io {

/// The most states a file may declare.
inline constexpr std::size_t kMaxFileStates = 256;

/// "states" of the root object, if present; function names resolve against `functions`.
std::optional<IfsStates> readStates(const nlohmann::json& root, const std::vector<Function>& functions);

/// Adds "states" to the root object when the project has them.
void writeStates(const Project& project, nlohmann::ordered_json& root);

}  // namespace gridifs::states_io
