#pragma once
// The semantic rules of a project that JSON types alone cannot catch: ranges of in-memory edits,
// weights, calculator syntax, singular morphs, bend axes and the size limits. Reading a file
// (io/project_io.h) and every Document edit run the same checks, so that a saved project can
// always be read back.
//
// Thread-safety: pure functions of their arguments.
#include <string>

#include "model/project.h"

namespace gridifs {

/// Checks the ranges of "render.flame" for an in-memory FlameSettings (edits from the GUI), so
/// that saving never writes settings that reading would refuse. Throws ModelError whose path is
/// `path` + "." + the field.
void validateFlameSettings(const FlameSettings& settings, const std::string& path);

/// Checks limits and the semantic rules. Throws ModelError with a JSON path
/// (`functions[2].ops[0].k`).
void validateProject(const Project& project);

}  // namespace gridifs
