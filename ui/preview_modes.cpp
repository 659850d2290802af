#include "ui/preview_modes.h"

#include <algorithm>
#include <cstdio>

#include "ui/widgets.h"

namespace gridifs::ui {
namespace {

const char* modeName(PreviewMode mode) {
  switch (mode) {
    case PreviewMode::Flame:
      return "flame";
    case PreviewMode::Mesh:
      return "mesh";
    case PreviewMode::Shaded:
      return "shaded";
    default:
      return "zbuffer";
  }
}

}  // namespace

void PreviewModes::syncFromProject(ModellerState& state) {
  // The z-buffer/flame choice is the project's render.mode (what `gridifs render` draws), so
  // undo, open and the menu all agree with the toolbar; the mesh mode is a view of the UI only.
  const DisplayMode pm = state.document.project().render.mode;
  if (!synced_ || pm != projectMode_) {
    if (state.previewMode != PreviewMode::Mesh)
      state.previewMode = pm == DisplayMode::Flame    ? PreviewMode::Flame
                          : pm == DisplayMode::Shaded ? PreviewMode::Shaded
                                                      : PreviewMode::ZBuffer;
    projectMode_ = pm;
    synced_ = true;
  }
}

void PreviewModes::buildToolbar(ModellerState& state, EditQueue& edits) {
  syncFromProject(state);
  auto modeButton = [&](const char* label, PreviewMode mode, const char* probeName, const char* help) {
    if (ImGui::RadioButton(label, state.previewMode == mode)) state.previewMode = mode;
    state.probe.item(probeName);
    contextHelp(state, help);
  };
  modeButton("Z-buffer", PreviewMode::ZBuffer, "preview.mode.zbuffer",
             "Nearest surface of the attractor, depth-cued (Gröller & Wegenkittl 1994, §3.1)");
  ImGui::SameLine();
  modeButton("Flame", PreviewMode::Flame, "preview.mode.flame",
             "Log density colored by structure (Draves & Reckase 2003, §4-8); same chaos game, no restart");
  ImGui::SameLine();
  modeButton("Shaded", PreviewMode::Shaded, "preview.mode.shaded",
             "The nearest surface lit by up to 3 lights, with shadows, ambient occlusion, fog and depth of field "
             "(settings in the Shading panel; Alt+drag moves the key light)");
  ImGui::SameLine();
  modeButton("Mesh F^n(A)", PreviewMode::Mesh, "preview.mode.mesh",
             "The deterministic algorithm (Gröller & Wegenkittl 1994, §3.2): n levels of the IFS applied to a cube or sphere");
  // Menu (View > Preview mode) and toolbar both land here: z-buffer/flame become one undo step
  // on render.mode.
  if (state.previewMode != PreviewMode::Mesh) {
    const DisplayMode want = state.previewMode == PreviewMode::Flame    ? DisplayMode::Flame
                             : state.previewMode == PreviewMode::Shaded ? DisplayMode::Shaded
                                                                        : DisplayMode::ZBuffer;
    if (want != state.document.project().render.mode) {
      edits.commit(want == DisplayMode::Flame    ? "Flame display"
                   : want == DisplayMode::Shaded ? "Shaded display"
                                                 : "Z-buffer display",
                   [want](Project& p) { p.render.mode = want; });
      projectMode_ = want;
    }
  }
  if (state.previewMode == PreviewMode::Flame) {
    ImGui::SameLine(0.0f, ImGui::GetFontSize());
    drawFlameControls(state, edits);
  } else if (state.previewMode == PreviewMode::Mesh) {
    ImGui::SameLine(0.0f, ImGui::GetFontSize());
    drawMeshControls(state);
  }
}

void PreviewModes::drawMeshControls(ModellerState& state) {
  const float em = ImGui::GetFontSize();
  int depth = mesh_.depth;
  ImGui::SetNextItemWidth(em * 6.5f);
  if (ImGui::SliderInt("##meshdepth", &depth, 0, std::max(mesh_.maxDepth(), 0), "n = %d", ImGuiSliderFlags_AlwaysClamp))
    mesh_.depth = depth;
  state.probe.item("preview.mesh.depth");
  char help[160];
  std::snprintf(help, sizeof help,
                "Depth n of F^n(A): N^n copies of the base (at most %d here, within %.1fM faces and the memory budget)",
                mesh_.maxDepth(), double(kMaxPreviewFaces) / 1e6);
  contextHelp(state, help);
  ImGui::SameLine();
  int base = mesh_.sphere ? 1 : 0;
  static const char* bases[] = {"Cube", "Sphere"};
  ImGui::SetNextItemWidth(em * 5.5f);
  if (ImGui::Combo("##meshbase", &base, bases, 2)) mesh_.sphere = base == 1;
  state.probe.item("preview.mesh.base");
  contextHelp(state, "The initial shape A: the cube X = [-1, 1]^3 or the unit sphere");
  ImGui::SameLine();
  if (!mesh_.error().empty()) {
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s", mesh_.error().c_str());
  } else if (mesh_.building()) {
    ImGui::ProgressBar(float(mesh_.progress()), ImVec2(em * 6.0f, 0), "building");
  } else if (mesh_.hasMesh()) {
    ImGui::TextDisabled("%.3gk faces", double(mesh_.faces()) / 1e3);
    char built[96];
    std::snprintf(built, sizeof built, "F^%d(A): %llu faces, built in %.0f ms", mesh_.shownDepth(),
                  static_cast<unsigned long long>(mesh_.faces()), mesh_.buildMs());
    contextHelp(state, built);
  }
}

bool PreviewModes::updateTexture(ModellerState& state, const RenderImage& image, bool fetched, StreamTexture& texture) {
  const bool modeChanged = state.previewMode != shownMode_;
  shownMode_ = state.previewMode;
  switch (state.previewMode) {
    case PreviewMode::Mesh:
      if (modeChanged) meshDirty_ = true;
      return false;
    case PreviewMode::Shaded: {
      // Developing is a pass over the z-buffer (core/render/shaded_image.h): light, occlusion and
      // fog changes re-develop the same buffers without a restart.
      const Project& p = state.document.project();
      const bool settingsChanged = !(p.render.shading == developedShading_) || !(p.camera == developedCamera_) ||
                                   !(p.render.background == developedBackground_);
      if ((fetched || modeChanged || settingsChanged) && image.width > 0) {
        try {
          developShaded(image, p.render.shading, p.camera, p.render.background, state.renderThreads, shaded_,
                        ShadedChannels::Display);
          shadedError_.clear();
        } catch (const std::exception& e) {
          shadedError_ = e.what();
          return false;
        }
        developedShading_ = p.render.shading;
        developedCamera_ = p.camera;
        developedBackground_ = p.render.background;
        ++shadedDevelops_;
        texture.upload(shaded_.width, shaded_.height, shaded_.rgba.data());
        return true;
      }
      return modeChanged;
    }
    case PreviewMode::Flame:
      if (modeChanged) flame_.invalidate();
      return flame_.update(state.document, state.now, image, fetched,
                           [&](int w, int h, const std::uint8_t* rgba) { texture.upload(w, h, rgba); });
    default:
      if ((fetched || modeChanged) && image.width > 0) {
        texture.upload(image.width, image.height, image.rgba.data());
        return true;
      }
      return modeChanged;
  }
}

bool PreviewModes::drawMesh(ModellerState& state, RenderTarget& target, int width, int height, bool visible) {
  if (state.previewMode != PreviewMode::Mesh) return false;
  mesh_.update(state.document);
  if (mesh_.upload()) meshDirty_ = true;
  const Project& p = state.document.project();
  const glm::ivec2 size(width, height);
  if (!visible) return true;
  if (!meshDirty_ && size == drawnSize_ && p.camera == drawnCamera_ && p.render.background == drawnBackground_)
    return true;
  target.resize(width, height);
  mesh_.draw(target, p.camera, glm::vec3(p.render.background));
  drawnSize_ = size;
  drawnCamera_ = p.camera;
  drawnBackground_ = p.render.background;
  meshDirty_ = false;
  return true;
}

bool PreviewModes::busy() const {
  if (shownMode_ == PreviewMode::Flame) return flame_.developer().busy();
  if (shownMode_ == PreviewMode::Mesh) return mesh_.building();
  return false;
}

nlohmann::json PreviewModes::probeJson() const {
  return {{"mode", modeName(shownMode_)},
          {"flame_developed", flame_.developed()},
          {"flame_ms", flame_.developer().lastMs()},
          {"flame_busy", flame_.developer().busy()},
          {"flame_error", flame_.developer().error()},
          {"palette_error", paletteError_},
          {"mesh_faces", mesh_.faces()},
          {"mesh_depth", mesh_.shownDepth()},
          {"mesh_max_depth", mesh_.maxDepth()},
          {"mesh_building", mesh_.building()},
          {"mesh_error", mesh_.error()},
          {"shaded_develops", shadedDevelops_},
          {"shaded_error", shadedError_}};
}

}  // namespace gridifs::ui
