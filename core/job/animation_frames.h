#pragma once
// Frames of an animation as image files: the numbered file names of a sequence and the render of
// one frame, as File › Render animation… runs them on its worker thread (headless: it lives in
// core so that it is tested, and used, without a window). One frame is the project
// at t = frame / fps (every keyframe track evaluated, schema/project_time.h) rendered in its display
// mode (z-buffer, flame or shaded) with its render settings.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "model/project.h"

namespace gridifs {

/// What is wrong with a sequence's output pattern (one printf integer conversion such as %04d,
/// a .png, .tif/.tiff or .exr extension), or nothing.
std::optional<std::string> checkFramePattern(const std::string& pattern);

/// A frame's file name is frameFileName (base/text_format.h) once the pattern passes.

/// Renders frame `frame` of `project` to `out` as `gridifs render --time frame/fps` writes it
/// (job/frame_output.h), atomically (a temporary file renamed over it). `progress` receives the
/// frame's fraction done and returns false to cancel (then RenderCancelled is thrown and nothing
/// is written). `projectFolder` resolves palette and condensation set files; `source` is the
/// project's file name, for the image's description.
/// Throws ModelError for a project that is invalid at that time, IoError when the file cannot be
/// written.
void renderAnimationFrame(const Project& project, long frame, const std::filesystem::path& out, int threads,
                          const std::filesystem::path& projectFolder, const std::string& source,
                          const std::function<bool(double)>& progress);

}  // namespace gridifs
