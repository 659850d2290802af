#pragma once
// Shared by `gridifs render` and `gridifs export-points`: loading and compiling a project for
// the chaos game, option overrides, output-path checks and atomic output files.
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/text_format.h"
#include "job/prepared_render.h"
#include "model/flame_settings.h"
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
  /// Told the fraction of the chaos game done, in [0, 1], as it runs; returning false stops the
  /// render as Ctrl-C would. With one, the caller handles Ctrl-C itself (the Python module's
  /// `progress=`, which also checks the interpreter's signals).
  std::function<bool(double)> observer;
};

/// Options of the flame display; empty optionals keep the project's settings.
struct FlameOptions {
  std::optional<std::string> mode, palette, densityDisplay;
  std::optional<int> bitDepth, supersample;
  std::optional<double> hue, filterRadius, estimatorRadius, estimatorMinimum, estimatorCurve;
  bool transparent = false;
  /// Directional motion blur (Draves & Reckase 2003, §9), resolved from --motion-fade or the
  /// project's animation.motion_fade by renderFrame.
  double motionFade = 0.0;
  std::optional<double> motionFadeOption;

  /// Whether any option of the flame display's own is given.
  bool anyFlameSetting() const {
    return palette || densityDisplay || supersample || hue || filterRadius || estimatorRadius || estimatorMinimum ||
           estimatorCurve;
  }
  /// `settings` with the given options, checked against the settings' ranges (CliError, exit 2).
  FlameSettings applied(FlameSettings settings) const;
};

/// Parses a sample count such as "20000000" or "2e7". Throws CliError(2) naming the option.
std::int64_t parseSamples(const std::string& text, std::int64_t maximum);

/// The options of core's render preparation (job/prepared_render.h) from the command line's:
/// the project's folder for relative files, --threads, --width, --height, --seed, --samples (at
/// most `maxSamples`), --quality and the volume to draw, checked with the option's own words
/// (CliError(2)). `time`: the moment to prepare.
RenderJobOptions renderJobOptions(const std::filesystem::path& file, const RenderOverrides& overrides,
                                  std::int64_t maxSamples, std::optional<double> time);

/// Core's prepareRender (or, with `points`, preparePoints) for `loaded`, read from `file`, at
/// options.time; a RenderJobError becomes CliError(2) naming the file. With `warn`, prints on
/// stderr which functions may not be contractive (once per sequence, not once per frame).
PreparedRender prepareForVerb(const Project& loaded, const std::filesystem::path& file, const RenderJobOptions& options,
                              std::int64_t maxSamples, bool warn, bool points = false);

/// Prints on stderr which functions of `prepared` may not be contractive, their grids taken from
/// `evaluation` (the cache it was compiled with).
void warnIfNotContractive(const PreparedRender& prepared, const EvaluationCache& evaluation,
                          const std::filesystem::path& file);

/// Loads `file` and prepares its points at its own time with `overrides` (export-points).
PreparedRender preparePointsOf(const std::filesystem::path& file, const RenderOverrides& overrides,
                               std::int64_t maxSamples);

/// One image of `loaded` as `gridifs render` makes it in the project's display mode, written to
/// `out` (.png, .exr, .tif). Throws CliError as render does.
int renderImageOf(const Project& loaded, const std::string& file, const std::string& out,
                  const RenderOverrides& overrides, bool quiet);

/// renderImageOf with the display options of `gridifs render` (--mode, the flame options,
/// --motion-blur and --motion-fade), checked as the verb checks them.
int renderImageOf(const Project& loaded, const std::string& file, const std::string& out,
                  const RenderOverrides& overrides, const FlameOptions& flame, std::optional<int> motionBlur,
                  bool quiet);

/// Refuses an output path whose extension is not in `allowed` or whose folder does not exist or is
/// not writable (CliError(2), one sentence naming the path).
void checkOutputPath(const std::filesystem::path& out, const std::vector<std::string>& allowed,
                     const std::string& what);

}  // namespace gridifs::cli
