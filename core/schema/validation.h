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

/// The camera's and the render settings' ranges, the same the project reader accepts.
void validateCamera(const Camera& camera, const std::string& path);
void validateRenderSettings(const RenderSettings& settings, const std::string& path);
/// Checks counts and ranges: at most 3 lights, non-zero finite light directions, colours in
/// [0, 1], non-negative intensities, radii and strengths, an aperture only with a focus distance.
/// Throws ModelError whose path is `path` + "." + the field (e.g. "render.shading.lights[3]").
void validateShadingSettings(const ShadingSettings& settings, const std::string& path);
/// Checks a condensation set's numbers against its shape's table (condensationSetTable), a file
/// set's path, a VDB set's grid name and a placed set's placement (no zero scale). Throws
/// ModelError with a path below `path`.
void checkCondensationSet(const CondensationSet& set, const std::string& path);

/// "render.volume": its fields' ranges, at most kMaxTransferStops stops, sorted by density.
void validateVolumeRender(const VolumeRenderSettings& settings, const std::string& path);

/// Checks limits and the semantic rules. Throws ModelError with a JSON path
/// (`functions[2].ops[0].k`).
void validateProject(const Project& project);

/// The same checks for an edit of `previousValid`, a project that passed them: a function whose
/// operations equal those at the same place in `previousValid` is not parsed or solved again, so
/// a slider drag on one function re-validates that function only. Same result and errors as
/// validateProject(project).
void validateProjectChange(const Project& project, const Project& previousValid);

}  // namespace gridifs
