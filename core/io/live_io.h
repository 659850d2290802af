#pragma once
// Reading and writing a project's "audio" and "bindings" (internal to io/; docs/LIVE.md,
// schema/live_binding.h). Throws ModelError with a JSON path.
#include <nlohmann/json.hpp>

#include "model/project.h"

namespace gridifs::live_io {

/// The most bindings, and the most audio bands, a file may hold.
inline constexpr std::size_t kMaxBindings = 256;
inline constexpr std::size_t kMaxAudioBands = 64;

/// "audio" and "bindings" of the root object into `project` (checked once the whole project is
/// read, by checkBindings).
void readLive(const nlohmann::json& root, Project& project);

/// Adds "audio" and "bindings" to the root object when the project has them.
void writeLive(const Project& project, nlohmann::ordered_json& root);

}  // namespace gridifs::live_io
