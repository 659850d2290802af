#pragma once
// `gridifs render FILE --mode volume -o OUT.(png|exr)`: the density volume computed as
// `gridifs volume` computes it, drawn by the modeller's Volume preview ray march
// (render/volume_raymarch.h) from the project's render.volume settings.
#include <optional>
#include <string>

#include "app/render_setup.h"

namespace gridifs::cli {

/// Renders and writes the image; timings on stderr unless `quiet`. CliError(2) for bad input
/// (nothing written), CliError(1) for an empty volume or an unwritable file.
int runVolumeRender(const std::string& file, const std::string& out, const RenderOverrides& overrides,
                    std::optional<int> resolution, bool quiet);

/// runVolumeRender for a project already loaded from `file` (the Python module's projects).
int runVolumeRenderOf(const Project& loaded, const std::string& file, const std::string& out,
                      const RenderOverrides& overrides, std::optional<int> resolution, bool quiet);

}  // namespace gridifs::cli
