#include "edit/volume_render_edits.h"

#include <algorithm>

#include "base/errors.h"
#include "model/function_kind.h"
#include "schema/validation.h"

namespace gridifs {
namespace {

VolumeRenderSettings& volumeRender(Project& project) {
  if (!project.render.volume) project.render.volume = VolumeRenderSettings{};
  return *project.render.volume;
}

}  // namespace

void SetVolumeDisplay::apply(Project& project) const { volumeRender(project).display = display; }

void SetTransferFunction::apply(Project& project) const {
  VolumeRenderSettings next = project.render.volume.value_or(VolumeRenderSettings{});
  next.transfer = stops;
  validateVolumeRender(next, "render.volume");
  project.render.volume = std::move(next);
}

StoredPreviewMode previewModeOnOpen(const Project& project) {
  if (project.preview_mode) return *project.preview_mode;
  const bool allSets = !project.functions.empty() && std::all_of(project.functions.begin(), project.functions.end(),
                                                                 [](const Function& f) { return isSetKind(f.kind); });
  if (allSets) return StoredPreviewMode::Volume;
  switch (project.render.mode) {
    case DisplayMode::Flame:
      return StoredPreviewMode::Flame;
    case DisplayMode::Shaded:
      return StoredPreviewMode::Shaded;
    case DisplayMode::ZBuffer:
      break;
  }
  return StoredPreviewMode::ZBuffer;
}

std::vector<TransferStop> defaultTransferStops() { return {{0.0, Vec3(1.0), 0.0}, {1.0, Vec3(1.0), 1.0}}; }

}  // namespace gridifs
