#pragma once
// "render.volume" (the volume ray march's settings) and "view" (the modeller's preview mode) in
// the project file: reading with JSON-path errors and writing. Kept apart from project_io.cpp so
// that this contract lives in one place.
//
// Thread-safety: pure functions.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "model/project.h"

namespace gridifs::volume_render_io {

/// Reads "render.volume" under `path`. Throws ModelError with a JSON path
/// ("render.volume.transfer[1].opacity: expected a number between 0 and 1, found 2").
VolumeRenderSettings readVolumeRender(const nlohmann::json& object, const std::string& path);
nlohmann::ordered_json writeVolumeRender(const VolumeRenderSettings& settings);

/// "view.preview_mode" of the root object, if present. Throws ModelError.
std::optional<StoredPreviewMode> readPreviewMode(const nlohmann::json& root);
/// Adds "view" to the root object when the project has a stored preview mode.
void writeView(const Project& project, nlohmann::ordered_json& root);

const char* previewModeName(StoredPreviewMode mode);
const char* volumeDisplayName(VolumeDisplay display);

}  // namespace gridifs::volume_render_io
