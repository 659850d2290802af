#include "ui/views/preview_modes.h"

#include <algorithm>
#include <cstdio>

#include "ui/base/widgets.h"

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
    case PreviewMode::Volume:
      return "volume";
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
    if (state.previewMode != PreviewMode::Mesh && state.previewMode != PreviewMode::Volume)
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
  modeButton(
      "Mesh F^n(A)", PreviewMode::Mesh, "preview.mode.mesh",
      "The deterministic algorithm (Gröller & Wegenkittl 1994, §3.2): n levels of the IFS applied to a cube or sphere");
  ImGui::SameLine();
  modeButton("Volume", PreviewMode::Volume, "preview.mode.volume",
             "The measure attractor (Sokolov & Gentil, §3.4) as a density volume, ray-marched with one light and "
             "self-shadowing; it fills while the iteration runs and starts again on every edit");
  // Menu (View > Preview mode) and toolbar both land here: z-buffer/flame become one undo step
  // on render.mode.
  if (state.previewMode != PreviewMode::Mesh && state.previewMode != PreviewMode::Volume) {
    const DisplayMode want = state.previewMode == PreviewMode::Flame    ? DisplayMode::Flame
                             : state.previewMode == PreviewMode::Shaded ? DisplayMode::Shaded
                                                                        : DisplayMode::ZBuffer;
    if (want != state.document.project().render.mode) {
      edits.commit(SetDisplayMode{want});
      projectMode_ = want;
    }
  }
  recordPreviewMode(state, edits);
  // The mode's controls on a row of their own under the switch, kept (empty) in the modes without
  // controls: the image below keeps its size when the mode changes, so the chaos game does not
  // restart, and five modes and their controls do not fit one row of a narrow preview.
  if (state.previewMode == PreviewMode::Flame)
    drawFlameControls(state, edits);
  else if (state.previewMode == PreviewMode::Mesh)
    drawMeshControls(state);
  else if (state.previewMode == PreviewMode::Volume)
    drawVolumeControls(state, edits);
  else
    ImGui::Dummy(ImVec2(1.0f, ImGui::GetFrameHeight()));
}

void PreviewModes::recordPreviewMode(ModellerState& state, EditQueue& edits) {
  // The mode a project was opened in (or a menu's undo of render.mode put it in) is the
  // baseline; a switch from it is the artist's choice, stored in view.preview_mode without an
  // undo step (a way of looking, not a change of the IFS; it still makes the project unsaved).
  if (!recordedKnown_ || state.documentOpens != recordedOpen_) {
    recordedKnown_ = true;
    recordedOpen_ = state.documentOpens;
    recordedMode_ = state.previewMode;
    return;
  }
  if (state.previewMode == recordedMode_) return;
  recordedMode_ = state.previewMode;
  const StoredPreviewMode stored = state.previewMode == PreviewMode::Flame    ? StoredPreviewMode::Flame
                                   : state.previewMode == PreviewMode::Shaded ? StoredPreviewMode::Shaded
                                   : state.previewMode == PreviewMode::Mesh   ? StoredPreviewMode::Mesh
                                   : state.previewMode == PreviewMode::Volume ? StoredPreviewMode::Volume
                                                                              : StoredPreviewMode::ZBuffer;
  if (state.document.project().preview_mode == stored) return;
  Document* document = &state.document;
  edits.after([document, stored] { document->applyUnrecorded(SetPreviewMode{stored}); });
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
    case PreviewMode::Volume:
      if (modeChanged) volumeDirty_ = true;
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

bool PreviewModes::drawVolume(ModellerState& state, RenderTarget& target, ViewRenderer& renderer, int width, int height,
                              bool visible, bool moving) {
  if (state.previewMode != PreviewMode::Volume) {
    state.volumeStatus.clear();
    volume_.suspend();
    return false;
  }
  volume_.update(state.document, state.renderThreads);
  if (volume_.upload()) volumeDirty_ = true;
  char status[96];
  if (!volume_.error().empty())
    std::snprintf(status, sizeof status, "volume: failed");
  else if (volume_.setIteration())
    std::snprintf(status, sizeof status, "volume %lld/%lld iterations", static_cast<long long>(volume_.done()),
                  static_cast<long long>(volume_.total()));
  else
    std::snprintf(status, sizeof status, "volume %.3gM/%.3gM points", double(volume_.done()) / 1e6,
                  double(volume_.total()) / 1e6);
  state.volumeStatus = status;
  const Project& p = state.document.project();
  const glm::ivec2 size(width, height);
  if (!visible) return true;
  // An N³ volume has no detail finer than a few pixels per voxel: the ray march runs at most
  // 8 pixels per voxel across (4 while the camera moves) and is scaled up, which keeps the
  // picture responsive and costs nothing visible.
  const int side = std::max({width, height, 1});
  const int cap = std::max(volume_.resolution(), kVolumePreviewResolutions[0]) * (moving ? 4 : 8);
  const double scale = std::min(1.0, double(cap) / double(side));
  const int lw = std::max(1, int(std::lround(width * scale))), lh = std::max(1, int(std::lround(height * scale)));
  volume_.requestImage(p, lw, lh);
  if (!volumeDirty_ && size == volumeSize_ && state.document.revision() == volumeRevision_) return true;
  target.resize(width, height);
  if (volume_.texture() && volume_.error().empty())
    renderer.drawImage(target, volume_.texture(), volume_.imageWidth(), volume_.imageHeight(),
                       glm::vec3(p.render.background));
  else
    renderer.drawImage(target, 0, 0, 0, glm::vec3(p.render.background));
  volumeSize_ = size;
  volumeRevision_ = state.document.revision();
  volumeDirty_ = false;
  return true;
}

std::string PreviewModes::overlayMessage(const ModellerState& state) const {
  if (state.previewMode == PreviewMode::Volume && !volume_.error().empty()) return "Volume: " + volume_.error();
  return {};
}

bool PreviewModes::busy() const {
  if (shownMode_ == PreviewMode::Flame) return flame_.developer().busy();
  if (shownMode_ == PreviewMode::Mesh) return mesh_.building();
  if (shownMode_ == PreviewMode::Volume) return volume_.busy();
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
          {"shaded_error", shadedError_},
          {"volume_computing", volume_.computing()},
          {"volume_finished", volume_.finished()},
          {"volume_picture_final", volume_.pictureFinal()},
          {"volume_images", volume_.images()},
          {"volume_image_width", volume_.imageWidth()},
          {"volume_image_height", volume_.imageHeight()},
          {"volume_done", volume_.done()},
          {"volume_total", volume_.total()},
          {"volume_resolution", volume_.resolution()},
          {"volume_restarts", volume_.restarts()},
          {"volume_uploads", volume_.uploads()},
          {"volume_error", volume_.error()}};
}

}  // namespace gridifs::ui
