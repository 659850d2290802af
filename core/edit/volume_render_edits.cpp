#include "edit/volume_render_edits.h"

#include <algorithm>

#include "base/errors.h"
#include "model/function_kind.h"

namespace gridifs {
namespace {

VolumeRenderSettings& volumeRender(Project& project) {
  if (!project.render.volume) project.render.volume = VolumeRenderSettings{};
  return *project.render.volume;
}

}  // namespace

void SetVolumeDensityScale::apply(Project& project) const {
  volumeRender(project).density_scale = std::clamp(scale, kMinVolumeDensityScale, kMaxVolumeDensityScale);
}

void SetVolumeDisplay::apply(Project& project) const { volumeRender(project).display = display; }

void SetTransferFunction::apply(Project& project) const {
  if (stops.size() > std::size_t(kMaxTransferStops))
    throw ModelError("render.volume.transfer", "more than " + std::to_string(kMaxTransferStops) + " stops");
  for (std::size_t i = 0; i < stops.size(); ++i) {
    const std::string path = "render.volume.transfer[" + std::to_string(i) + "]";
    const TransferStop& s = stops[i];
    if (!(s.density >= 0.0 && s.density <= 1.0))
      throw ModelError(path + ".density", "expected a number between 0 and 1");
    if (!(s.opacity >= 0.0 && s.opacity <= 1.0))
      throw ModelError(path + ".opacity", "expected a number between 0 and 1");
    for (int c = 0; c < 3; ++c)
      if (!(s.color[c] >= 0.0 && s.color[c] <= 1000.0))
        throw ModelError(path + ".color", "expected 3 numbers between 0 and 1000");
    if (i > 0 && !(s.density > stops[i - 1].density))
      throw ModelError(path + ".density", "the stops must be sorted by increasing density");
  }
  volumeRender(project).transfer = stops;
}

void SetVolumeRenderResolution::apply(Project& project) const {
  if (resolution < kMinVolumeResolution || resolution > kMaxVolumeResolution)
    throw ModelError("render.volume.resolution", "expected an integer between " + std::to_string(kMinVolumeResolution) +
                                                     " and " + std::to_string(kMaxVolumeResolution));
  volumeRender(project).resolution = resolution;
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
