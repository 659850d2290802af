#pragma once
// Named edits of "render.volume" (the volume ray march: display and transfer function; its
// numbers are set by SetParameter, edit/parameter_edit.h) and of "view" (the preview mode the project opens in), and
// the rule that picks the preview mode a project opens in. See edit/project_edit.h.
#include <string>
#include <vector>

#include "model/project.h"

namespace gridifs {

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
