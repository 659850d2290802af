#pragma once
// The preview's display modes (z-buffer | flame | shaded over the same chaos game |
// the deterministic mesh F^n(A) | the ray-marched measure attractor), owned by PreviewView: a second toolbar row with
// the mode switch and the mode's controls, and what the preview texture shows in each mode.
#include <imgui.h>

#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "render/shaded_image.h"
#include "ui/base/edit_queue.h"
#include "ui/base/modeller_state.h"
#include "ui/gl/gl_resources.h"
#include "ui/gl/view_renderer.h"
#include "ui/views/flame_display.h"
#include "ui/views/mesh_preview.h"
#include "ui/views/palette_editor.h"
#include "ui/views/transfer_editor.h"
#include "ui/views/volume_preview.h"

namespace gridifs::ui {

/// The palettes the picker offers: our built-ins, then flam3's collection when installed, each
/// with a precomputed swatch strip. Built lazily on the UI thread.
struct PaletteCatalog {
  struct Entry {
    std::string reference, label;
    std::vector<ImU32> swatch;  // kSwatchSteps colors across c in [0, 1]
  };
  static constexpr int kSwatchSteps = 48;
  std::vector<Entry> entries;
  std::string flam3Error;  // why flam3's collection is missing ("" when loaded)
  bool loaded = false;
  void load();
  /// The entry of a reference, or null (a "file:" palette or an unknown one).
  const Entry* find(const std::string& reference) const;
};

class PreviewModes {
 public:
  /// The mode switch and the current mode's controls (a row under the preview toolbar).
  void buildToolbar(ModellerState& state, EditQueue& edits);
  /// After the renderer fetch (`fetched`: `image` changed): uploads what the current mode shows
  /// into `texture`. Returns true when the texture changed (the view must be redrawn).
  bool updateTexture(ModellerState& state, const RenderImage& image, bool fetched, StreamTexture& texture);
  /// In mesh mode, builds (on the worker) and draws F^n(A) into `target`; `force` redraws.
  /// Returns false when the current mode is not the mesh.
  bool drawMesh(ModellerState& state, RenderTarget& target, int width, int height, bool visible);
  /// In volume mode, uploads the newest partial volume and ray-marches it into `target`.
  /// Returns false when the current mode is not the volume.
  /// `moving`: the camera is being dragged (a coarser picture keeps the orbit fluid).
  bool drawVolume(ModellerState& state, RenderTarget& target, ViewRenderer& renderer, int width, int height,
                  bool visible, bool moving);
  /// A message to show over the preview image ("" when none): why the volume cannot be shown.
  std::string overlayMessage(const ModellerState& state) const;
  /// Whether a develop or a mesh build is under way (the window keeps animating).
  bool busy() const;
  /// State for the GUI tests' probe file.
  nlohmann::json probeJson() const;

 private:
  void syncFromProject(ModellerState& state);
  void drawFlameControls(ModellerState& state, EditQueue& edits);                      // flame_controls.cpp
  void drawTonePopup(ModellerState& state, EditQueue& edits, const FlameSettings& f);  // flame_controls.cpp
  void drawMeshControls(ModellerState& state);
  void drawVolumeControls(ModellerState& state, EditQueue& edits);  // volume_controls.cpp
  /// Records the preview mode the artist chose in the project (view.preview_mode, no undo step).
  void recordPreviewMode(ModellerState& state, EditQueue& edits);
  PreviewMode recordedMode_ = PreviewMode::ZBuffer;
  bool recordedKnown_ = false;
  const Document* recordedDocument_ = nullptr;
  std::uint64_t recordedOpen_ = 0;

  FlameDisplay flame_;
  MeshPreview mesh_;
  VolumePreview volume_;
  TransferEditor transfer_;
  // What the volume target shows, to redraw only on change.
  std::uint64_t volumeRevision_ = 0;  // Document::revision(): any edit redraws (light, background, palette)
  glm::ivec2 volumeSize_{0, 0};
  bool volumeDirty_ = true;
  PaletteCatalog palettes_;
  PaletteEditor paletteEditor_;
  std::string paletteError_;
  std::string checkedPalette_;
  PreviewMode shownMode_ = PreviewMode::ZBuffer;
  DisplayMode projectMode_ = DisplayMode::ZBuffer;
  bool synced_ = false;
  // What the mesh target shows, to redraw only on change.
  Camera drawnCamera_;
  glm::ivec2 drawnSize_{0, 0};
  Vec3 drawnBackground_{-1.0};
  bool meshDirty_ = true;
  // The shaded display: what was last developed, to re-develop only on change.
  ShadedImage shaded_;
  ShadingSettings developedShading_;
  Camera developedCamera_;
  Vec3 developedBackground_{-1.0};
  std::uint64_t shadedDevelops_ = 0;
  std::string shadedError_;
};

}  // namespace gridifs::ui
