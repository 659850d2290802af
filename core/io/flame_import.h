#pragma once
// A flame genome (flame_genome.h) as a GridIFS project: each xform becomes a grid function whose
// nodes sample the xform's whole map (pre-affine, weighted variations, post; Draves & Reckase
// §3, §3.1) over a square domain of the flame plane that holds the genome's view and (most of)
// its attractor, mapped onto X. Pure functions: thread-safe.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/flame_genome.h"
#include "model/project.h"

namespace gridifs {

/// How the flame plane sits in X: X = scale · R(rotate) · (p − center), with y negated because
/// flame image rows go down with y while GridIFS's camera looks down −z with +y up. z is 0.
struct FlameFrame {
  double centerX = 0.0, centerY = 0.0;
  double scale = 1.0;   // X units per flame unit
  double rotate = 0.0;  // degrees (the genome's `rotate`)
  FlamePoint toX(FlamePoint p) const;
  FlamePoint fromX(FlamePoint x) const;
};

struct FlameImportOptions {
  int resolution = 64;  // nodes per axis in x and y for non-affine xforms (2..128)
  /// The palette reference to store when the genome carries its own colors (the caller saves
  /// FlameImport::palette there), e.g. "file:name.palette.json".
  std::string inlinePaletteReference;
};

struct FlameImport {
  Project project;
  FlameFrame frame;
  /// The genome's own palette (inline colors), to be saved where options.inlinePaletteReference says.
  std::optional<Palette> palette;
  std::vector<std::string> warnings;
};

/// The attribute exported flames carry so that importing them again restores the same frame
/// ("centerX centerY scale"); other programs ignore it.
inline constexpr const char* kFlameFrameAttribute = "gridifs_frame";

/// Converts `genome`. Throws FlameError when a map cannot be sampled (no finite node) or the
/// options are out of range.
FlameImport importFlameGenome(const FlameGenome& genome, const FlameImportOptions& options);

/// What the modeller's File › Import flame… needs: the project of genome `genome` (index or
/// name; empty: the first) of `file`, its warnings and a short description ("NAME (genome 1 of
/// 3)"). A genome with its own palette gets it written to `paletteFolder` (created when missing)
/// as NAME.palette.json and referenced by absolute path. Throws FlameError (bad file),
/// IoError (unreadable file, unwritable palette).
struct FlameFileImport {
  Project project;
  std::vector<std::string> warnings;
  std::string description;
};
FlameFileImport importFlameFile(const std::filesystem::path& file, const std::string& genome,
                                const std::filesystem::path& paletteFolder);

/// The largest distance (X units) between `function`'s grid and `map` at the centres of the
/// grid's cells in the z = 0 plane... exposed for tests: evaluates the grid trilinearly.
double flameSamplingError(const Function& function, const FlameXform& map, const FlameFrame& frame);

}  // namespace gridifs
