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

/// How the flame's space sits in X. 2D genomes: X = scale · R(rotate) · (p − center), with y
/// negated because flame image rows go down with y while GridIFS's camera looks down −z with +y
/// up, and z = 0. 3D genomes first turn the point into the flame camera's space,
/// c = M(pitch, yaw) · (p − (0, 0, zpos)) (the camera of Apophysis 7X, JWildfire and Fractorium),
/// then map c's x and y as above onto X's x and z (image up is +z) and its depth onto y:
/// X = scale · (r_x, −(c_z − zCenter), −r_y), so that GridIFS's camera, level and looking along
/// +y, sees what the flame camera sees (the flame's eye is on the +c_z side).
struct FlameFrame {
  double centerX = 0.0, centerY = 0.0;
  double scale = 1.0;   // X units per flame unit
  double rotate = 0.0;  // degrees (the genome's `rotate`)
  bool threeD = false;
  double pitch = 0.0, yaw = 0.0;  // radians, the genome's cam_pitch and cam_yaw
  double zpos = 0.0;              // the genome's cam_zpos
  double zCenter = 0.0;           // camera-space depth at X's z = 0
  FlamePoint toX(FlamePoint p) const;
  FlamePoint fromX(FlamePoint x) const;
  /// The flame camera's space: M · (p − (0, 0, zpos)) (identity for 2D genomes).
  FlamePoint toCamera(FlamePoint p) const;
  FlamePoint fromCamera(FlamePoint c) const;
};

struct FlameImportOptions {
  /// Nodes per axis of the image plane for non-affine xforms (2..128). Along depth 2 (2D
  /// genomes, and 3D ones whose xforms are affine in z as the camera sees it) or
  /// clamp(R/2, 2, 32) (see gridResolution in the implementation).
  int resolution = 64;
  /// Sample every xform onto a grid (the sampled import of 3D genomes) instead of keeping a 2D
  /// genome's variations natively: for artists who want to sculpt the map's grid.
  bool sampleOntoGrids = false;
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

/// Whether `genome` is imported with native variations: a planar genome (no xform leaves the
/// plane z = 0) that is not GridIFS's own grid export (no gridifs_frame). Its xforms become
/// functions in the flame's own coordinates (X's plane z = 0 is the flame plane): a 2×2×2 grid
/// that is the pre-affine map, the variations by name and the post map. A flat camera looks at
/// the plane from below; a 3D one (cam_pitch, cam_yaw, cam_perspective, cam_zpos) becomes the
/// project camera that sees the same picture (io/flame_camera.h). Other genomes are sampled onto
/// grids in a frame that fits the attractor into X.
bool isNativeGenome(const FlameGenome& genome);

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
/// grid's cells (2D genomes: in the z = 0 plane, the map's z collapsed to 0)... exposed for
/// tests: evaluates the grid trilinearly.
double flameSamplingError(const Function& function, const FlameXform& map, const FlameFrame& frame);

}  // namespace gridifs
