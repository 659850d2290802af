#pragma once
// Shared by `gridifs render` and `gridifs export-points`: loading and compiling a project for
// the chaos game, option overrides, output-path checks and atomic output files.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/text_format.h"
#include "render/chaos_renderer.h"
#include "volume/density_volume.h"

namespace gridifs::cli {

/// Command-line overrides of the project's render settings.
struct RenderOverrides {
  std::optional<int> width, height, threads;
  std::optional<std::string> samples;  // parsed by parseSamples (accepts 2e7)
  std::optional<double> quality;       // --quality: samples per output pixel (render only)
  std::optional<std::uint64_t> seed;
  std::optional<std::string> device;  // --device auto|gpu|cpu (app/render_device_option.h)
  std::optional<double> time;         // --time: the project at this time (default: its stored time)
  /// For a project with median functions: draw the points of this volume (a page of the book of
  /// drawings) instead of computing the project's density volume.
  std::shared_ptr<const DensityVolume> volume;
};

struct RenderSetup {
  Project project;
  std::shared_ptr<const CompiledIfs> ifs;
  RenderJob job;
};

/// Parses a sample count such as "20000000" or "2e7". Throws CliError(2) naming the option.
std::int64_t parseSamples(const std::string& text, std::int64_t maximum);

/// Loads `file`, applies `overrides`, validates the job and compiles the IFS; warns on stderr when
/// a function may not be contractive. Bad input → CliError(2) naming the file.
RenderSetup prepareRender(const std::filesystem::path& file, const RenderOverrides& overrides, std::int64_t maxSamples);

/// prepareRender for a project already loaded from `file` (a frame of a sequence): the project at
/// overrides.time with its tracks evaluated, then the same checks and compilation. `warn` prints
/// the contractivity warnings (once per sequence, not once per frame).
RenderSetup prepareRenderOf(const Project& loaded, const std::filesystem::path& file, const RenderOverrides& overrides,
                            std::int64_t maxSamples, bool warn = true);

/// One image of `loaded` as `gridifs render` makes it in the project's display mode, written to
/// `out` (.png, .exr, .tif). Throws CliError as render does.
int renderImageOf(const Project& loaded, const std::string& file, const std::string& out,
                  const RenderOverrides& overrides, bool quiet);

/// Refuses an output path whose extension is not in `allowed` or whose folder does not exist or is
/// not writable (CliError(2), one sentence naming the path).
void checkOutputPath(const std::filesystem::path& out, const std::vector<std::string>& allowed,
                     const std::string& what);

}  // namespace gridifs::cli
