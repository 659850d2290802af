#pragma once
// One grid view (Gröller & Wegenkittl 1994, §4.2): the active function's grid from the top, side, front or an
// orbiting user view, or the IFS view with every function placed in the common initial grid and
// the final function's lattice around them.
// build() runs while the UI is built (input → edits); render() draws into the view's target
// after the edits are applied (the fixed frame order of ui/shell/modeller_app.cpp).
#include <cstdint>
#include <glm/vec2.hpp>
#include <map>
#include <string>
#include <vector>

#include "edit/view_camera.h"
#include "ui/base/edit_queue.h"
#include "ui/base/modeller_state.h"
#include "ui/gl/gl_resources.h"
#include "ui/gl/view_renderer.h"
#include "ui/views/orbit_controller.h"

struct ImDrawList;

namespace gridifs::ui {

class GridView {
 public:
  enum class Content { FunctionGrid, Ifs };
  GridView(Content content, ViewAxis axis, std::string id);

  /// Shows the view at the cursor with `size` (logical pixels) and handles its mouse input.
  void build(ModellerState& state, EditQueue& edits, glm::vec2 size, float framebufferScale);
  /// Draws the scene for the current document into the view's texture, when anything it
  /// shows changed since the last frame (idle views cost nothing while the preview fills).
  void render(ModellerState& state, ViewRenderer& renderer);
  /// Copies the view's texture to its place in the window's framebuffer (before ImGui draws
  /// its overlays on top). `framebufferHeight` flips to OpenGL's bottom-up rows.
  void present(int framebufferHeight) const;
  /// Fits the content into the view (F).
  void frame(ModellerState& state, EditQueue& edits);

  /// Window coordinates of the pickable nodes (for the test probe); empty when hidden.
  std::vector<glm::dvec2> screenNodes(ModellerState& state);

  /// Called before the UI is built: a view that build() does not reach this frame (hidden by
  /// the maximized view, or a collapsed window) is neither drawn nor copied.
  void hide() {
    visible_ = false;
    hovered_ = false;
  }

  bool hovered() const { return hovered_; }
  ViewAxis axis() const { return camera_.axis; }
  void setAxis(ViewAxis axis);
  Content content() const { return content_; }
  const std::string& id() const { return id_; }

 private:
  enum class Drag { None, Orbit, Pan, Box, Nodes, Handle, Placement, ControlPoint };
  enum class Handle { None, MagnetPoint, MorphFrom, MorphTo, CenterPoint };

  ViewCamera camera(const ModellerState& state) const;
  /// The nodes that picking works on (local grid or every placed grid).
  void pickableNodes(ModellerState& state, std::vector<Vec3>& out, std::vector<FunctionRef>& owner);
  Handle hitHandle(ModellerState& state, glm::dvec2 mouse, int& pairIndex, Vec3& position) const;
  /// The control points this view shows and picks (a free-form IFS's), empty for a grid IFS.
  const std::vector<Vec3>& controlPoints(const ModellerState& state) const;
  /// The control point under `mouse` (view pixels), or -1.
  int hitControlPoint(const ModellerState& state, glm::dvec2 mouse) const;
  /// Rings the hovered or dragged control point and records every control point's place for the probe.
  void drawControlPoints(ModellerState& state, ImDrawList* draw, glm::dvec2 mouse);
  void beginDrag(ModellerState& state, EditQueue& edits, glm::dvec2 mouse);
  void updateDrag(ModellerState& state, EditQueue& edits, glm::dvec2 mouse);
  void endDrag(ModellerState& state, EditQueue& edits, glm::dvec2 mouse);
  void zoom(ModellerState& state, EditQueue& edits, float wheel);
  void buildFunctionScene(ModellerState& state);
  void buildIfsScene(ModellerState& state);
  /// Function `function`'s image of X's lattice lines (a function with variations), cached until
  /// the geometry changes.
  const std::vector<Vec3>& variationImage(ModellerState& state, std::size_t function);
  bool usesProjectCamera() const { return content_ == Content::Ifs && camera_.axis == ViewAxis::User; }

  /// Everything a view's picture depends on; equal keys mean the texture is still valid.
  struct Key {
    std::uint64_t revision = 0;  // Document::revisions().geometry
    FunctionRef function;
    int op = -1;
    Selection selection;
    Camera camera;
    ViewAxis axis = ViewAxis::User;
    glm::dvec2 size{0.0};
    float scale = 0.0f;
    Vec3 point{0.0};
    int centerKind = -1;
    bool operator==(const Key&) const = default;
  };
  Key key_;
  bool visible_ = false;
  glm::dvec2 screenOrigin_{0.0};  // window coordinates of the view's top-left corner

  Content content_;
  ViewCamera camera_;
  std::string id_;
  RenderTarget target_;
  ViewScene scene_;
  std::map<std::size_t, std::vector<Vec3>> variationImages_;
  std::uint64_t variationImageRevision_ = 0;
  glm::dvec2 size_{1.0, 1.0};  // logical pixels
  float framebufferScale_ = 1.0f;
  bool hovered_ = false;
  bool framedOnce_ = false;

  // The drag in progress.
  Drag drag_ = Drag::None;
  int dragButton_ = 0;
  glm::dvec2 dragStart_{0.0}, dragLast_{0.0};
  bool dragMoved_ = false;
  Handle handle_ = Handle::None;
  int handlePair_ = -1;
  Vec3 handleStart_{0.0}, anchor_{0.0};
  Function dragFunction_;        // the function as it was when a node/handle/placement drag began
  FunctionRef dragFunctionRef_;  // and which one it is
  std::size_t pressedNode_ = 0;
  int controlPoint_ = -1;  // the control point being dragged
  bool pressedWasSelected_ = false;
  OrbitController orbit_;  // orbit, pan and zoom of the user view's project camera or the view's own
};

}  // namespace gridifs::ui
