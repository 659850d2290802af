#pragma once
// One path from a project to a render. `gridifs render` and `gridifs export-points`, the
// modeller's preview, File › Render animation and File › Export points all prepare their render
// here, so a project renders the same way everywhere: the same tracks, the same condensation sets
// read from files beside the project, the same palette and lights.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "base/errors.h"
#include "edit/document.h"
#include "model/project.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "tone/palette.h"
#include "volume/density_volume.h"

namespace gridifs {

/// A project that cannot be rendered as asked. path() is the JSON path of the cause
/// ("render.samples", "render.flame.palette", "functions[2].set", ...), message() says why.
class RenderJobError : public ModelError {
 public:
  using ModelError::ModelError;
  explicit RenderJobError(const ModelError& e) : ModelError(e.path(), e.message()) {}
};

/// What to render of a project; empty optionals keep the project's render settings.
struct RenderJobOptions {
  /// The project at this time, its tracks evaluated; none: the project as given (the modeller's
  /// document is already at its time).
  std::optional<double> time;
  int threads = 0;  // 0: every core
  std::optional<int> width, height;
  std::optional<std::int64_t> samples;
  std::optional<std::uint64_t> seed;
  /// The folder that relative file paths start from: condensation sets (meshes, VDB grids) and
  /// palette files. Empty: the working folder.
  std::filesystem::path folder;
  /// Condensation sets read from files are voxelized at this resolution³ before sampling.
  int setResolution = 256;
  /// auto, gpu or cpu (the caller opens the renderer).
  std::string device = "auto";
  /// The evaluated grids to compile with (a cache that outlives the call, keyed by each
  /// function's content, so one serves every time sample); none: evaluated afresh.
  const EvaluationCache* evaluation = nullptr;
  /// A project with median functions draws the points of this volume (a page of the book of
  /// drawings) instead of computing its own density volume.
  std::shared_ptr<const DensityVolume> volume;
  /// Applied to the project at its time before anything is prepared: the command line's --mode,
  /// --quality and flame options, which win over what the tracks say.
  std::function<void(Project&)> adjust;
  /// The interactive preview: low priority threads, colour sums in every mode so that switching
  /// to the flame display needs no restart, the flame histogram at the preview's own pixels, and
  /// the default palette while the project's cannot be read (the palette picker says why).
  bool preview = false;
};

/// A render ready to run: give `ifs` and `job` to a renderer, snapshot with `display`.
struct PreparedRender {
  Project project;                         // at the asked time, tracks evaluated
  std::shared_ptr<const CompiledIfs> ifs;  // condensation sets sampled from their files
  RenderJob output;                        // the output image's job: size, samples, seed, threads
  RenderJob job;                           // the display mode's renderer job (flame, shaded or z-buffer)
  DisplaySettings display;                 // how the renderer's buffers become a picture
  std::shared_ptr<const Palette> palette;  // the flame display's palette (null in other modes)
  /// options.device, except "cpu" for the shaded display: its shadow maps and depth of field are
  /// filled by the CPU chaos game.
  std::string device;
};

/// The project at `time` as every render sees it: its tracks evaluated (schema/project_time.h), and
/// the numbers bound to its sound (live/live_drive.h) at their value then, the sound read from
/// `folder` (empty: the working folder) and analysed once per process. Live sources (OSC, MIDI)
/// have no value outside the modeller: their numbers keep their tracks' values. Throws
/// RenderJobError.
Project renderProjectAt(const Project& project, double time, const std::filesystem::path& folder = {});

/// The samples one frame of `project` renders with `options` (at options.time, adjusted): what a
/// progress bar over a sequence needs before the first frame is prepared. Throws RenderJobError.
std::int64_t frameSampleCount(const Project& project, const RenderJobOptions& options);

/// The output image's job from the project's render settings and the options' overrides; not
/// yet validated.
RenderJob outputRenderJob(const Project& project, const RenderJobOptions& options);

/// Compiles `project`'s IFS for the chaos game with the evaluated grids of `evaluation` (a
/// Document's cache, or a fresh one); condensation sets read from files are found in `folder`
/// (empty: the working folder) and voxelized at `setResolution`³. Throws RenderJobError.
std::shared_ptr<const CompiledIfs> compileRenderIfs(const Project& project, const EvaluationCache& evaluation,
                                                    const std::filesystem::path& folder, int setResolution = 256);

/// The IFS the chaos game runs for `project`: compileRenderIfs with options.folder and
/// options.setResolution; for a project with median functions, or when `volume` is given, the
/// points of a density volume instead (`volume`, or the project's own computed from its "volume"
/// settings on options.threads). Throws RenderJobError.
std::shared_ptr<const CompiledIfs> compileChaosIfs(const Project& project, const EvaluationCache& evaluation,
                                                   const RenderJobOptions& options,
                                                   std::shared_ptr<const DensityVolume> volume = nullptr);

/// The palette of the flame display, resolved beside the project. Throws RenderJobError naming
/// render.flame.palette; with `preview`, falls back to the default palette instead.
std::shared_ptr<const Palette> renderPalette(const Project& project, const std::filesystem::path& folder,
                                             bool preview = false);

/// The renderer job of the project's display mode for `output`: flameRenderJob with `palette`,
/// shadedRenderJob with the lights, or `output` itself for the z-buffer (see RenderJobOptions::
/// preview for the preview's differences). Throws RenderJobError.
RenderJob displayRenderJob(const Project& project, const RenderJob& output, const CompiledIfs& ifs,
                           std::shared_ptr<const Palette> palette, bool preview = false);

/// The display settings of the project's mode (the shaded display develops colour itself: no
/// depth cueing in its buffers).
DisplaySettings renderDisplaySettings(const Project& project);

/// Checks that the output job of `project` with `options` (its size and samples; the project as
/// given) is one a render takes, as preparePoints does first: a dialog's fast inline check before
/// its work starts. Throws RenderJobError.
void checkRenderOutput(const Project& project, const RenderJobOptions& options);

/// The points a render would plot, without a display: the project at options.time (adjusted), its
/// output job (validated) and the chaos game's IFS (compileChaosIfs); job is the output job and
/// there is no palette. What `gridifs export-points` and File › Export points write. Throws
/// RenderJobError naming the JSON path of the cause.
PreparedRender preparePoints(const Project& project, const RenderJobOptions& options);

/// All of the above, validated; for a project with median functions the compiled IFS draws the
/// points of its density volume, as the command line's render does. Throws RenderJobError naming
/// the JSON path of the cause.
PreparedRender prepareRender(const Project& project, const RenderJobOptions& options);

/// The jobs of a frame developed from accumulations made elsewhere (merged render parts): the
/// project as given, its output job, and the display job whose buffers the parts hold (a flame's
/// supersampled one; the shaded display's lights are in the parts already). No IFS and no palette
/// (the colour sums hold it). Throws RenderJobError.
PreparedRender prepareDevelop(const Project& project, const RenderJobOptions& options);

}  // namespace gridifs
