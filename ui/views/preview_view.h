#pragma once
// The preview window (Gröller & Wegenkittl 1994, §4.2 "the rendered result"): the renderer's
// z-buffer image, streamed while it fills, orbiting with the IFS user view; pause/resume,
// sample budget, depth cueing and background.
#include <imgui.h>

#include <glm/vec2.hpp>
#include <string>

#include "ui/base/edit_queue.h"
#include "ui/base/modeller_state.h"
#include "ui/gl/gl_resources.h"
#include "ui/gl/view_renderer.h"
#include "ui/views/orbit_controller.h"
#include "ui/views/preview_modes.h"
#include "ui/views/preview_renderer.h"

namespace gridifs::ui {

class PreviewView {
 public:
  /// The window's contents: toolbar and image; mouse orbits/pans/zooms the project camera.
  void build(ModellerState& state, EditQueue& edits, float framebufferScale);
  /// After the edits: hands a new snapshot to the workers when the project changed.
  void publish(ModellerState& state);
  /// Merges the workers' buffers and draws them into the view's texture.
  void render(ModellerState& state, ViewRenderer& renderer);
  /// Copies the preview into the window's framebuffer (see GridView::present).
  void present(int framebufferHeight) const;
  void hide() { visible_ = false; }
  bool busy() const { return renderer_.busy() || modes_.busy(); }
  bool dragging() const { return orbit_.motion() != OrbitController::Motion::None; }
  const RenderImage& image() const { return image_; }
  std::uint64_t restarts() const { return renderer_.restarts(); }
  /// Picks the preview's renderer (auto | gpu | cpu); an error sentence when gpu cannot be had.
  std::string useDevice(const std::string& device) { return renderer_.useDevice(device); }
  /// The display modes (z-buffer, flame, mesh: ui/views/preview_modes.h).
  const PreviewModes& modes() const { return modes_; }

 private:
  PreviewRenderer renderer_;
  PreviewModes modes_;
  RenderImage image_;
  StreamTexture texture_;
  RenderTarget target_;
  glm::dvec2 size_{64.0, 64.0};
  glm::dvec2 screenOrigin_{0.0};
  bool visible_ = false, needsDraw_ = true;
  Vec3 drawnBackground_{-1.0};
  double lastFetch_ = -1.0;
  float framebufferScale_ = 1.0f;
  std::string error_;  // why the chaos game stopped, over the image
  /// Pause, restart, sample budget, depth cue and background.
  void buildToolbar(ModellerState& state, EditQueue& edits);
  /// The image's place above the timeline, with the renderer's and the mode's messages over it;
  /// returns whether the mouse is over it.
  bool buildImage(ModellerState& state);
  /// Wheel zoom, and the start of an orbit, a pan or a key-light turn, then the drag under way.
  void handleMouse(ModellerState& state, EditQueue& edits, bool hovered);
  /// Alt+drag in the shaded and volume modes: the key light turns with the mouse (one undo step).
  void dragKeyLight(EditQueue& edits, glm::dvec2 mouse);
  /// Drag: orbit or pan the project camera (one undo step).
  void dragCamera(EditQueue& edits, glm::dvec2 mouse);
  /// The key light's direction as a small dial in the image's corner (Alt+drag turns it).
  void drawProjectionOutline(ModellerState& state, ImVec2 origin) const;
  void drawLightGizmo(ModellerState& state, ImVec2 origin) const;

  OrbitController orbit_;   // the project camera, orbited, panned and zoomed from this view
  bool lightDrag_ = false;  // Alt+drag in the shaded mode turns the key light instead
  Vec3 dragLight_{0.0};
  int dragButton_ = 0;
  bool dragMoved_ = false;
  glm::dvec2 dragStart_{0.0};
};

}  // namespace gridifs::ui
