// The volume mode's controls in the preview's second toolbar row: the preview resolution, the
// density scale, the display (lit or X-ray), the transfer function's window and the computation's
// progress or why it failed. Density scale, display and transfer function are the project's
// render.volume, which `gridifs render --mode volume` draws the same way.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "edit/parameter_edit.h"
#include "schema/settings_tables.h"
#include "ui/base/widgets.h"
#include "ui/panels/setting_slider.h"
#include "ui/views/preview_modes.h"

namespace gridifs::ui {

void PreviewModes::drawVolumeControls(ModellerState& state, EditQueue& edits) {
  const float em = ImGui::GetFontSize();
  VolumeView& view = volume_.view;
  const Project& project = state.document.project();
  const VolumeRenderSettings settings = project.render.volume.value_or(VolumeRenderSettings{});
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
  char help[240];
  std::snprintf(help, sizeof help,
                "Preview resolution: voxels per side of the previewed volume (at most the project's volume "
                "resolution, %d; lower fills faster). The command line renders at %d³ (render.volume.resolution)",
                cap, settings.resolution);
  contextHelp(state, help);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(em * 8.0f);
  const SettingSpec& densityScale = volumeRenderTable().field("density_scale");
  double scale = settings.density_scale;
  const bool scaled =
      settingSliderWidget("##volumedensity", densityScale, scale, densityScale.sliderMin, densityScale.sliderMax);
  gestureItem(edits, densityScale.label, scaled,
              SetParameter{"render.volume.density_scale", scale, densityScale.label});
  state.probe.item("preview.volume.density");
  contextHelp(state, (std::string(densityScale.tooltip) + "; only the picture changes, not the volume").c_str());
  ImGui::SameLine();
  int display = settings.display == VolumeDisplay::Xray ? 1 : 0;
  static const char* displays[] = {"Lit", "X-ray"};
  ImGui::SetNextItemWidth(em * 4.5f);
  if (ImGui::Combo("##volumedisplay", &display, displays, 2))
    edits.commit(SetVolumeDisplay{display == 1 ? VolumeDisplay::Xray : VolumeDisplay::Lit});
  state.probe.item("preview.volume.display");
  contextHelp(state,
              "Lit: emission and absorption with one light and self-shadowing. X-ray: grey summed density, as in "
              "Sokolov & Gentil's figures");
  ImGui::SameLine();
  if (ImGui::Button(settings.transfer.empty() ? "Transfer..." : "Transfer*...")) transfer_.toggle();
  state.probe.item("preview.volume.transfer");
  contextHelp(state, "The transfer function: density to colour and opacity (saved in the project)");
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
  transfer_.draw(state, edits);
}

}  // namespace gridifs::ui
