#pragma once
// "render.shading" in the project file: reading with JSON-path errors and writing. Kept apart from
// project_io.cpp so that the shading contract lives in one place.
//
// Thread-safety: pure functions.
#include <nlohmann/json.hpp>
#include <string>

#include "model/shading_settings.h"

namespace gridifs {

/// Reads "render.shading" (every field optional, defaults from ShadingSettings) and validates it.
/// Throws ModelError with a JSON path under `path` ("render.shading.lights[0].direction").
ShadingSettings readShadingSettings(const nlohmann::json& object, const std::string& path);

/// The JSON object for `settings`; readShadingSettings(writeShadingSettings(s)) == s.
nlohmann::ordered_json writeShadingSettings(const ShadingSettings& settings);

}  // namespace gridifs
