#pragma once
// Named edits of "render.volume" (the volume ray march: density scale, display, transfer
// function, resolution) and of "view" (the preview mode the project opens in), and the rule
// that picks the preview mode a project opens in. See edit/project_edit.h.
#include <string>
#include <vector>

#include "model/project.h"

namespace gridifs {

/// σ: extinction per world unit at opacity 1 (clamped to the file's range).
struct SetVolumeDensityScale {
  double scale = 24.0;
  void apply(Project& project) const;
  std::string label() const { return "Volume density scale"; }
};

/// "lit" or "xray".
struct SetVolumeDisplay {
  VolumeDisplay display = VolumeDisplay::Lit;
  void apply(Project& project) const;
  std::string label() const { return display == VolumeDisplay::Xray ? "X-ray volume display" : "Lit volume display"; }
};

/// The whole transfer function (density → colour and opacity); empty: opacity = density and the
/// functions' colours. Throws ModelError for stops out of range or out of order, or too many.
struct SetTransferFunction {
  std::vector<TransferStop> stops;
  void apply(Project& project) const;
  std::string label() const { return "Volume transfer function"; }
};

/// N of the N³ volume `gridifs render --mode volume` computes (16..512).
struct SetVolumeRenderResolution {
  int resolution = 128;
  void apply(Project& project) const;
  std::string label() const { return "Volume render resolution"; }
};

/// "view.preview_mode": the modeller applies it without an undo step when the artist switches the
/// preview mode (a view choice, not a change of the IFS), so that the project reopens that way.
struct SetPreviewMode {
  StoredPreviewMode mode = StoredPreviewMode::ZBuffer;
  void apply(Project& project) const { project.preview_mode = mode; }
  std::string label() const { return "Preview mode"; }
};

/// The preview mode a project opens in: its stored view.preview_mode; else Volume when every
/// function is a median or condensation function (sets, not points: the point modes cannot show
/// it); else the render.mode display.
StoredPreviewMode previewModeOnOpen(const Project& project);

/// A transfer function to start editing from: opacity rising with density, white.
std::vector<TransferStop> defaultTransferStops();

}  // namespace gridifs
