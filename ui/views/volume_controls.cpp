// The volume mode's controls in the preview's second toolbar row: the preview resolution, the
// density scale and the computation's progress or why it failed.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ui/views/preview_modes.h"
#include "ui/base/widgets.h"

namespace gridifs::ui {

void PreviewModes::drawVolumeControls(ModellerState& state) {
  const float em = ImGui::GetFontSize();
  VolumeView& view = volume_.view;
  const Project& project = state.document.project();
  const int cap = VolumePreview::effectiveResolution(project, kMaxVolumeResolution);
  char current[32];
  std::snprintf(current, sizeof current, "%d³", VolumePreview::effectiveResolution(project, view.resolution));
  ImGui::SetNextItemWidth(em * 5.0f);
  if (ImGui::BeginCombo("##volumeresolution", current)) {
    for (int r : kVolumePreviewResolutions) {
      if (r > cap) break;
      char label[32];
      std::snprintf(label, sizeof label, "%d³", r);
      if (ImGui::Selectable(label, r == view.resolution)) view.resolution = r;
    }
    ImGui::EndCombo();
  }
  state.probe.item("preview.volume.resolution");
  char help[200];
  std::snprintf(help, sizeof help,
                "Preview resolution: voxels per side of the previewed volume (at most the project's volume "
                "resolution, %d; lower fills faster)",
                cap);
  contextHelp(state, help);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(em * 8.0f);
  float scale = view.densityScale;
  if (ImGui::SliderFloat("##volumedensity", &scale, 0.5f, 500.0f, "density %.3g", ImGuiSliderFlags_Logarithmic))
    view.densityScale = std::clamp(scale, 0.5f, 500.0f);
  state.probe.item("preview.volume.density");
  contextHelp(state,
              "Density scale: how much light the densest voxels absorb per unit of length (higher: thicker, "
              "darker shadows); only the picture changes, not the volume");
  ImGui::SameLine();
  if (!volume_.error().empty()) {
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "cannot show the volume");
    contextHelp(state, volume_.error().c_str());
  } else if (volume_.computing()) {
    const double f = volume_.total() > 0 ? double(volume_.done()) / double(volume_.total()) : 0.0;
    ImGui::ProgressBar(float(std::clamp(f, 0.0, 1.0)), ImVec2(em * 6.0f, 0), "computing");
    contextHelp(state, "The measure attractor is being computed; the picture fills as it goes");
  } else if (volume_.resolution() > 0) {
    ImGui::TextDisabled("%d³ voxels", volume_.resolution());
  }
}

}  // namespace gridifs::ui
