#pragma once
// Reading and writing the volume fields of a .gridifs file (internal to io/): a condensation or
// median function's "set" and "rotate", and the project's "volume" block (Sokolov & Gentil).
// Throws ModelError with a JSON path.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "model/project.h"

namespace gridifs::volume_io {

/// "set" and "rotate" of a function whose kind is condensation or median; such a function may
/// carry none of the grid fields (resolution, placement, ops).
void readSetFunctionFields(const nlohmann::json& f, const std::string& path, Function& fn);

/// The object of a condensation or median function (name, kind, weight, rotate, set, color,
/// palette_index, color_speed, muted).
nlohmann::ordered_json writeSetFunction(const Function& fn);

/// "volume" of the root object, if present.
std::optional<VolumeSettings> readVolume(const nlohmann::json& root);

/// Adds "volume" to the root object when the project has one.
void writeVolume(const Project& project, nlohmann::ordered_json& root);

}  // namespace gridifs::volume_io
