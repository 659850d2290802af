#include "ui/views/grid_view.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "edit/node_picking.h"
#include "model/stack_evaluator.h"
#include "render/compiled_ifs.h"

namespace gridifs::ui {
namespace {

using glm::dvec2;

constexpr glm::vec3 kBackgroundTop{0.165f, 0.172f, 0.196f};
constexpr glm::vec3 kBackgroundBottom{0.105f, 0.110f, 0.125f};
constexpr glm::vec4 kNodeColor{0.80f, 0.83f, 0.88f, 1.0f};
constexpr glm::vec4 kSelectedColor{1.0f, 0.62f, 0.12f, 1.0f};
constexpr glm::vec4 kCenterColor{0.25f, 0.85f, 0.95f, 1.0f};
constexpr glm::vec4 kHandleColor{0.95f, 0.30f, 0.85f, 1.0f};
constexpr glm::vec4 kMorphColor{1.0f, 0.90f, 0.25f, 1.0f};
constexpr glm::vec4 kFinalLatticeColor{0.80f, 0.62f, 1.0f, 1.0f};  // violet, as the final function's row
constexpr double kPickRadius = 8.0;                                // logical pixels
constexpr double kDragThreshold = 3.0;

Vertex vertex(const Vec3& p, const glm::vec4& c, float size = 0.0f) {
  return {float(p.x), float(p.y), float(p.z), c.x, c.y, c.z, c.w, size};
}

void line(std::vector<Vertex>& out, const Vec3& a, const Vec3& b, const glm::vec4& c) {
  out.push_back(vertex(a, c));
  out.push_back(vertex(b, c));
}

void appendCube(std::vector<Vertex>& out, const glm::vec4& c) {
  for (int axis = 0; axis < 3; ++axis)
    for (int s1 = -1; s1 <= 1; s1 += 2)
      for (int s2 = -1; s2 <= 1; s2 += 2) {
        Vec3 a, b;
        a[axis] = -1.0;
        b[axis] = 1.0;
        a[(axis + 1) % 3] = b[(axis + 1) % 3] = s1;
        a[(axis + 2) % 3] = b[(axis + 2) % 3] = s2;
        line(out, a, b, c);
      }
}

void appendAxes(std::vector<Vertex>& out) {
  line(out, Vec3(0.0), Vec3(1.15, 0, 0), {0.85f, 0.30f, 0.30f, 0.9f});
  line(out, Vec3(0.0), Vec3(0, 1.15, 0), {0.35f, 0.80f, 0.35f, 0.9f});
  line(out, Vec3(0.0), Vec3(0, 0, 1.15), {0.35f, 0.55f, 0.95f, 0.9f});
}

/// Lines between neighbouring nodes; on very large grids only the outer shell, so that a
/// 128³ grid stays interactive (the interior is hidden in the views anyway).
void appendGridLines(const Grid& grid, const glm::vec4& color, std::vector<Vertex>& out) {
  const Index3 r = grid.resolution();
  const bool shellOnly = grid.nodeCount() > 30000;
  for (int k = 0; k < r[2]; ++k)
    for (int j = 0; j < r[1]; ++j)
      for (int i = 0; i < r[0]; ++i) {
        const Vec3& p = grid.node(i, j, k);
        const bool bi = i == 0 || i == r[0] - 1, bj = j == 0 || j == r[1] - 1, bk = k == 0 || k == r[2] - 1;
        if (i + 1 < r[0] && (!shellOnly || bj || bk)) line(out, p, grid.node(i + 1, j, k), color);
        if (j + 1 < r[1] && (!shellOnly || bi || bk)) line(out, p, grid.node(i, j + 1, k), color);
        if (k + 1 < r[2] && (!shellOnly || bi || bj)) line(out, p, grid.node(i, j, k + 1), color);
      }
}

void appendCircle(std::vector<Vertex>& out, const Vec3& center, double radius, const glm::dvec3& right,
                  const glm::dvec3& up, const glm::vec4& c) {
  constexpr int kSegments = 72;
  for (int s = 0; s < kSegments; ++s) {
    const double a0 = 2.0 * M_PI * s / kSegments, a1 = 2.0 * M_PI * (s + 1) / kSegments;
    line(out, center + radius * (std::cos(a0) * right + std::sin(a0) * up),
         center + radius * (std::cos(a1) * right + std::sin(a1) * up), c);
  }
}

void appendCross(std::vector<Vertex>& out, const Vec3& p, double size, const glm::vec4& c) {
  line(out, p - Vec3(size, 0, 0), p + Vec3(size, 0, 0), c);
  line(out, p - Vec3(0, size, 0), p + Vec3(0, size, 0), c);
  line(out, p - Vec3(0, 0, size), p + Vec3(0, 0, size), c);
}

glm::vec4 lineColor(const Vec3& functionColor, float alpha) {
  const glm::vec3 c = glm::mix(glm::vec3(functionColor), glm::vec3(0.9f), 0.35f);
  return {c, alpha};
}

/// Grid views draw lines nearly neutral so that selected (orange) nodes stand out.
glm::vec4 neutralLineColor(const Vec3& functionColor) {
  const glm::vec3 c = glm::mix(glm::vec3(functionColor), glm::vec3(0.62f, 0.66f, 0.74f), 0.72f);
  return {c, 0.9f};
}

/// Whether the function has a grid that the grid views show and edit (a matrix function acts
/// through control points, a set function through its set).
bool hasGrid(const Function& f) { return f.kind != FunctionKind::Matrix && !isSetKind(f.kind); }

/// The drawing of set function `f`'s set (volume/set_outline.h), kept by the state's cache.
const SetOutlineCache::Drawing& setDrawing(ModellerState& state, std::size_t f) {
  const Function& fn = state.document.project().functions[f];
  return state.setOutlines.get(fn.set, state.projectFolder(), FunctionRef(int(f)).path() + ".set");
}

Selection normalized(Selection s, const Index3& r) { return selectsNothing(s, r) ? Selection{} : s; }

Vec3 centroid(const std::vector<Vec3>& nodes, const std::vector<unsigned char>* mask) {
  Vec3 sum{0.0};
  std::size_t count = 0;
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if (!mask || (*mask)[n]) {
      sum += nodes[n];
      ++count;
    }
  return count ? sum / double(count) : Vec3(0.0);
}

}  // namespace

GridView::GridView(Content content, ViewAxis axis, std::string id) : content_(content), id_(std::move(id)) {
  camera_.axis = axis;
  if (axis != ViewAxis::User) camera_.orbit.projection = CameraProjection::Orthographic;
}

void GridView::setAxis(ViewAxis axis) {
  camera_.axis = axis;
  camera_.orbit.projection = axis != ViewAxis::User ? CameraProjection::Orthographic : CameraProjection::Perspective;
  framedOnce_ = false;
}

ViewCamera GridView::camera(const ModellerState& state) const {
  if (usesProjectCamera()) return ViewCamera{ViewAxis::User, state.document.project().camera};
  return camera_;
}

void GridView::pickableNodes(ModellerState& state, std::vector<Vec3>& out, std::vector<FunctionRef>& owner) {
  out.clear();
  owner.clear();
  if (content_ == Content::FunctionGrid) {
    if (hasGrid(state.function())) out = state.localGrid().nodes();
    return;
  }
  const auto& functions = state.document.project().functions;
  for (std::size_t f = 0; f < functions.size(); ++f) {
    if (isSetKind(functions[f].kind)) {
      // A set is picked (and dragged) by the points of its drawing.
      const LineSegments& lines = setDrawing(state, f).lines;
      for (std::size_t s = 0; s < lines.size(); s += 2) {
        out.push_back(lines[s]);
        owner.push_back(FunctionRef(int(f)));
      }
      continue;
    }
    if (functions[f].kind == FunctionKind::Matrix) continue;  // no grid to pick or place
    try {
      const auto grid = state.document.evaluatedGrid(f);
      out.insert(out.end(), grid->nodes().begin(), grid->nodes().end());
      owner.insert(owner.end(), grid->nodeCount(), FunctionRef(int(f)));
    } catch (const ModelError&) {
    }
  }
  // The final function's lattice last: where its nodes sit on a function's, that function wins.
  try {
    if (const auto grid = state.document.evaluatedFinal()) {
      out.insert(out.end(), grid->nodes().begin(), grid->nodes().end());
      owner.insert(owner.end(), grid->nodeCount(), FunctionRef::finalFunction());
    }
  } catch (const ModelError&) {
  }
}

GridView::Handle GridView::hitHandle(ModellerState& state, dvec2 mouse, int& pairIndex, Vec3& position) const {
  const Operation* op = state.op();
  if (!op || content_ != Content::FunctionGrid) return Handle::None;
  const glm::dmat4 vp = camera(state).viewProjection(size_.x, size_.y);
  double best = kPickRadius * state.uiScale + 2.0;
  Handle found = Handle::None;
  auto consider = [&](const Vec3& p, Handle h, int pair) {
    dvec2 px;
    if (!projectToPixel(vp, size_.x, size_.y, p, px)) return;
    const double d = glm::length(px - mouse);
    if (d < best) {
      best = d;
      found = h;
      pairIndex = pair;
      position = p;
    }
  };
  if (const auto* m = std::get_if<MagnetOp>(&op->params)) consider(m->point, Handle::MagnetPoint, -1);
  if (const auto* m = std::get_if<MorphOp>(&op->params))
    for (std::size_t i = 0; i < m->pairs.size(); ++i) {
      consider(m->pairs[i].from, Handle::MorphFrom, int(i));
      consider(m->pairs[i].to, Handle::MorphTo, int(i));
    }
  if (op->center.kind == Center::Kind::Point) consider(op->center.point, Handle::CenterPoint, -1);
  return found;
}

const std::vector<Vec3>& GridView::controlPoints(const ModellerState& state) const {
  static const std::vector<Vec3> kNone;
  const Project& project = state.document.project();
  // A free-form IFS has matrix functions only; every view of it shows the control points.
  return project.space ? project.space->control_points : kNone;
}

int GridView::hitControlPoint(const ModellerState& state, dvec2 mouse) const {
  const auto& points = controlPoints(state);
  if (points.empty()) return -1;
  const glm::dmat4 vp = camera(state).viewProjection(size_.x, size_.y);
  const auto hit = nearestNode(points, vp, size_.x, size_.y, mouse, kPickRadius * state.uiScale);
  return hit ? int(*hit) : -1;
}

void GridView::drawControlPoints(ModellerState& state, ImDrawList* draw, dvec2 mouse) {
  const auto& points = controlPoints(state);
  if (points.empty()) return;
  const glm::dmat4 vp = camera(state).viewProjection(size_.x, size_.y);
  const int ringed = drag_ == Drag::ControlPoint       ? controlPoint_
                     : hovered_ && drag_ == Drag::None ? hitControlPoint(state, mouse)
                                                       : -1;
  const float r = float(kPickRadius * state.uiScale);
  const std::string probeName =
      "control_point." + std::string(content_ == Content::Ifs ? "IFS" : viewAxisName(camera_.axis)) + ".";
  for (std::size_t j = 0; j < points.size(); ++j) {
    dvec2 px;
    if (!projectToPixel(vp, size_.x, size_.y, points[j], px)) continue;
    px += screenOrigin_;
    if (int(j) == ringed) {
      draw->AddCircle(ImVec2(float(px.x), float(px.y)), r, IM_COL32(255, 160, 40, 255), 0, 2.0f * state.uiScale);
      state.contextHelp = "Drag: move control point " + std::to_string(j) + " in the view's plane";
    }
    if (state.probe.enabled)  // where a test presses to drag this point
      state.probe.rects[probeName + std::to_string(j)] = ImVec4(float(px.x) - r, float(px.y) - r, 2 * r, 2 * r);
  }
}

void GridView::build(ModellerState& state, EditQueue& edits, glm::vec2 size, float framebufferScale) {
  visible_ = false;
  ImGuiIO& io = ImGui::GetIO();
  size_ = dvec2(std::max(size.x, 8.0f), std::max(size.y, 8.0f));
  framebufferScale_ = framebufferScale;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 extent(float(size_.x), float(size_.y));
  // The picture itself is copied into the framebuffer by present(); ImGui draws on top.
  screenOrigin_ = dvec2(origin.x, origin.y);
  visible_ = true;
  ImGui::InvisibleButton(
      id_.c_str(), extent,
      ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight | ImGuiButtonFlags_MouseButtonMiddle);
  hovered_ = ImGui::IsItemHovered();
  const dvec2 mouse(io.MousePos.x - origin.x, io.MousePos.y - origin.y);

  // The view's name in its corner, as in InterIFS' child windows.
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const std::string title = content_ == Content::Ifs ? std::string("IFS · ") + viewAxisName(camera_.axis) +
                                                           (usesProjectCamera() ? " (preview camera)" : "")
                                                     : std::string(viewAxisName(camera_.axis));
  draw->AddText(ImVec2(origin.x + 8, origin.y + 6), IM_COL32(220, 224, 232, 200), title.c_str());
  if (!state.gridError.empty() && content_ == Content::FunctionGrid)
    draw->AddText(ImVec2(origin.x + 8, origin.y + extent.y - ImGui::GetTextLineHeight() - 6),
                  IM_COL32(255, 110, 90, 255), "stack error: see the status bar");

  if (hovered_) {
    state.contextHelp =
        !controlPoints(state).empty()
            ? "Drag a control point: move it in the view's plane · right-drag: orbit/pan · wheel: zoom · "
              "F: frame"
        : content_ == Content::Ifs ? "Drag a grid or a set: move it · right-drag: orbit · middle/Shift+right: pan · "
                                     "wheel: zoom · F: frame"
                                   : "Click/drag: select nodes (Shift add, Ctrl remove) · drag a selected node: move · "
                                     "Alt+click: place center · right-drag: orbit/pan · wheel: zoom · F: frame";
    // The final function is edited like any function; say so, since it bends the whole picture.
    const bool finalLattice = state.document.project().final_function.has_value();
    if (content_ == Content::Ifs && finalLattice && controlPoints(state).empty())
      state.contextHelp =
          "Violet: the final function's lattice around the attractor, applied to every point before "
          "plotting; click one of its nodes to edit it · " +
          state.contextHelp;
    else if (content_ == Content::FunctionGrid && state.activeFunction.isFinal())
      state.contextHelp = "Final function: moving its nodes bends the whole attractor · " + state.contextHelp;
    if (io.MouseWheel != 0.0f && drag_ == Drag::None) zoom(state, edits, io.MouseWheel);
  }
  orbit_.settleWheel(edits, state.now);
  if (drag_ == Drag::None && hovered_) {
    for (int button = 0; button < 3; ++button)
      if (ImGui::IsMouseClicked(button)) {
        orbit_.settleWheel(edits, -1.0);
        dragButton_ = button;
        beginDrag(state, edits, mouse);
        break;
      }
  }
  if (drag_ != Drag::None) {
    if (ImGui::IsMouseDown(dragButton_))
      updateDrag(state, edits, mouse);
    else
      endDrag(state, edits, mouse);
  }
  drawControlPoints(state, draw, mouse);
  if (drag_ == Drag::Box && dragMoved_) {
    const ImVec2 a(origin.x + float(dragStart_.x), origin.y + float(dragStart_.y));
    const ImVec2 b(io.MousePos.x, io.MousePos.y);
    draw->AddRectFilled(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)), ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)),
                        IM_COL32(255, 160, 40, 40));
    draw->AddRect(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)), ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)),
                  IM_COL32(255, 160, 40, 200));
  }
}

void GridView::zoom(ModellerState& state, EditQueue& edits, float wheel) {
  if (usesProjectCamera())
    orbit_.zoomProject(state.document.project().camera, edits, wheel, state.now);
  else
    camera_.orbit = OrbitController::zoomed(camera_.orbit, wheel, 0.02);
}

void GridView::beginDrag(ModellerState& state, EditQueue& edits, dvec2 mouse) {
  const ImGuiIO& io = ImGui::GetIO();
  drag_ = Drag::None;
  dragStart_ = dragLast_ = mouse;
  dragMoved_ = false;
  if (dragButton_ == 2 || (dragButton_ == 1 && (io.KeyShift || camera_.axis != ViewAxis::User))) {
    drag_ = Drag::Pan;
    orbit_.begin(OrbitController::Motion::Pan, camera(state).orbit, mouse);
    return;
  }
  if (dragButton_ == 1) {
    drag_ = Drag::Orbit;
    orbit_.begin(OrbitController::Motion::Orbit, camera(state).orbit, mouse);
    return;
  }
  const ViewCamera cam = camera(state);
  const glm::dmat4 vp = cam.viewProjection(size_.x, size_.y);
  std::vector<Vec3> nodes;
  std::vector<FunctionRef> owner;
  pickableNodes(state, nodes, owner);
  const double radius = kPickRadius * state.uiScale;

  // A free-form IFS's control points are dragged like nodes (Thollot et al. 1997, §5: the
  // attractor follows its control points as a Bézier curve or patch does).
  if (!io.KeyAlt && !io.KeyCtrl) {
    if (const int j = hitControlPoint(state, mouse); j >= 0) {
      controlPoint_ = j;
      anchor_ = controlPoints(state)[std::size_t(j)];
      drag_ = Drag::ControlPoint;
      return;
    }
  }

  if (content_ == Content::Ifs) {
    const auto hit = nearestNode(nodes, vp, size_.x, size_.y, mouse, radius);
    if (!hit) return;
    const FunctionRef f = owner[*hit];
    state.activate(f);
    const Function& picked = f.in(state.document.project());
    if (isSetKind(picked.kind) && picked.set.shape == SetShape::Vdb) return;  // picked, not moved
    dragFunctionRef_ = f;
    dragFunction_ = f.in(state.document.project());
    anchor_ = nodes[*hit];
    drag_ = Drag::Placement;
    return;
  }

  dragFunctionRef_ = state.activeFunction;
  dragFunction_ = state.function();
  if (io.KeyAlt) {  // place the point center of transformation (Gröller & Wegenkittl 1994, §4.3)
    const Vec3 p =
        cam.orbit.target + cam.dragDelta(mouse.x - size_.x * 0.5, mouse.y - size_.y * 0.5, cam.orbit.target, size_.y);
    state.pointCenter = p;
    if (const Operation* op = state.op(); op && op->center.kind == Center::Kind::Point) {
      edits.commit(PlaceCenter{state.activeFunction, state.activeOp, p});
    }
    state.info("Center point placed at (" + std::to_string(p.x).substr(0, 6) + ", " + std::to_string(p.y).substr(0, 6) +
               ", " + std::to_string(p.z).substr(0, 6) + ")");
    return;
  }
  int pair = -1;
  Vec3 position;
  if (Handle h = hitHandle(state, mouse, pair, position); h != Handle::None) {
    handle_ = h;
    handlePair_ = pair;
    handleStart_ = position;
    drag_ = Drag::Handle;
    return;
  }
  if (const auto hit = nearestNode(nodes, vp, size_.x, size_.y, mouse, radius)) {
    pressedNode_ = *hit;
    const Index3 res = state.function().resolution;
    pressedWasSelected_ = state.selectionMask()[*hit] != 0;
    if (io.KeyCtrl) {
      state.selection() = normalized(applyPick(state.selection(), {*hit}, res, PickMode::Remove), res);
      return;
    }
    if (!pressedWasSelected_)
      state.selection() =
          normalized(applyPick(state.selection(), {*hit}, res, io.KeyShift ? PickMode::Add : PickMode::Replace), res);
    anchor_ = nodes[*hit];
    drag_ = Drag::Nodes;
    return;
  }
  drag_ = Drag::Box;
}

void GridView::updateDrag(ModellerState& state, EditQueue& edits, dvec2 mouse) {
  const dvec2 delta = mouse - dragStart_;
  const bool firstMove = !dragMoved_ && glm::length(delta) > kDragThreshold;
  if (firstMove) dragMoved_ = true;
  if (!dragMoved_ || mouse == dragLast_) return;
  dragLast_ = mouse;
  const FunctionRef f = dragFunctionRef_;
  switch (drag_) {
    case Drag::Orbit:
    case Drag::Pan: {
      if (usesProjectCamera())
        orbit_.dragProject(edits, mouse, camera_.axis, size_.y, firstMove);
      else
        camera_.orbit = orbit_.dragged(mouse, camera_.axis, size_.y);
      break;
    }
    case Drag::Box:
      break;
    case Drag::Nodes: {
      if (firstMove) edits.begin("Move nodes");
      const Vec3 d = camera(state).dragDelta(delta.x, delta.y, anchor_, size_.y);
      // Successive drags extend one trailing `nodes` op instead of stacking many.
      edits.update(MoveNodes{f, dragFunction_, state.selectionMask(), d});
      state.activeOp = nodeMoveOperation(dragFunction_);
      break;
    }
    case Drag::Handle: {
      if (firstMove) edits.begin("Drag handle");
      const Vec3 p = handleStart_ + camera(state).dragDelta(delta.x, delta.y, handleStart_, size_.y);
      Function fn = dragFunction_;
      if (state.activeOp < 0 || state.activeOp >= int(fn.ops.size())) break;
      Operation& op = fn.ops[std::size_t(state.activeOp)];
      if (handle_ == Handle::MagnetPoint) {
        if (auto* m = std::get_if<MagnetOp>(&op.params)) m->point = p;
      } else if (handle_ == Handle::MorphFrom || handle_ == Handle::MorphTo) {
        if (auto* m = std::get_if<MorphOp>(&op.params); m && handlePair_ < int(m->pairs.size()))
          (handle_ == Handle::MorphFrom ? m->pairs[std::size_t(handlePair_)].from
                                        : m->pairs[std::size_t(handlePair_)].to) = p;
      } else if (handle_ == Handle::CenterPoint) {
        op.center.point = p;
        state.pointCenter = p;
      }
      edits.update(SetOperation{f, state.activeOp, op});
      break;
    }
    case Drag::Placement: {
      const Vec3 d = camera(state).dragDelta(delta.x, delta.y, anchor_, size_.y);
      if (isSetKind(dragFunction_.kind)) {
        // A primitive moves its centre, a mesh its placement; a VDB set stays where its file puts it.
        const SetShape shape = dragFunction_.set.shape;
        if (shape == SetShape::Vdb) break;
        if (firstMove) edits.begin("Move set");
        CondensationSet set = dragFunction_.set;
        (shape == SetShape::Mesh || shape == SetShape::Image ? set.placement.translate : set.center) += d;
        edits.update(SetCondensationSet{f, set});
        break;
      }
      if (firstMove) edits.begin("Move placement");
      const Vec3 t = dragFunction_.placement.translate + d;
      edits.update(MovePlacement{f, t});
      break;
    }
    case Drag::ControlPoint: {
      if (firstMove) edits.begin("Move control point");
      const Vec3 p = anchor_ + camera(state).dragDelta(delta.x, delta.y, anchor_, size_.y);
      const std::size_t j = std::size_t(controlPoint_);
      edits.update(MoveControlPoint{j, p});
      break;
    }
    case Drag::None:
      break;
  }
}

void GridView::endDrag(ModellerState& state, EditQueue& edits, dvec2 mouse) {
  const ImGuiIO& io = ImGui::GetIO();
  const Drag drag = std::exchange(drag_, Drag::None);
  orbit_.end();
  if (content_ == Content::FunctionGrid) {
    const Index3 res = state.function().resolution;
    if (drag == Drag::Box) {
      if (dragMoved_) {
        std::vector<Vec3> nodes;
        std::vector<FunctionRef> owner;
        pickableNodes(state, nodes, owner);
        const auto picked =
            nodesInRect(nodes, camera(state).viewProjection(size_.x, size_.y), size_.x, size_.y, dragStart_, mouse);
        const PickMode mode = io.KeyShift ? PickMode::Add : io.KeyCtrl ? PickMode::Remove : PickMode::Replace;
        state.selection() = normalized(applyPick(state.selection(), picked, res, mode), res);
        state.info(std::to_string(picked.size()) + " node" + (picked.size() == 1 ? "" : "s") + " picked");
      } else if (!io.KeyShift && !io.KeyCtrl) {
        state.selection().clear();
      }
      return;
    }
    if (drag == Drag::Nodes && !dragMoved_) {
      if (pressedWasSelected_ && !io.KeyShift)
        state.selection() = normalized(applyPick(state.selection(), {pressedNode_}, res, PickMode::Replace), res);
      return;
    }
  }
  const bool projectGesture = drag == Drag::Nodes || drag == Drag::Handle || drag == Drag::Placement ||
                              drag == Drag::ControlPoint ||
                              ((drag == Drag::Orbit || drag == Drag::Pan) && usesProjectCamera());
  if (projectGesture && dragMoved_) edits.end();
}

std::vector<dvec2> GridView::screenNodes(ModellerState& state) {
  std::vector<dvec2> out;
  if (!visible_) return out;
  std::vector<Vec3> nodes;
  std::vector<FunctionRef> owner;
  pickableNodes(state, nodes, owner);
  const glm::dmat4 vp = camera(state).viewProjection(size_.x, size_.y);
  for (const Vec3& p : nodes) {
    dvec2 px(-1.0);
    if (projectToPixel(vp, size_.x, size_.y, p, px)) px += screenOrigin_;
    out.push_back(px);
  }
  return out;
}

void GridView::frame(ModellerState& state, EditQueue& edits) {
  Vec3 lo(-1.0), hi(1.0);
  std::vector<Vec3> nodes;
  std::vector<FunctionRef> owner;
  pickableNodes(state, nodes, owner);
  const auto& points = controlPoints(state);  // a free-form IFS has no grid nodes: frame its control points
  nodes.insert(nodes.end(), points.begin(), points.end());
  if (!nodes.empty()) {
    lo = hi = nodes.front();
    for (const Vec3& p : nodes) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    if (content_ == Content::Ifs) {  // the common initial grid stays in view
      lo = glm::min(lo, Vec3(-1.0));
      hi = glm::max(hi, Vec3(1.0));
    }
  }
  if (usesProjectCamera()) {
    ViewCamera vc{ViewAxis::User, state.document.project().camera};
    vc.frame(lo, hi, size_.x, size_.y);
    const Camera cam = vc.orbit;
    edits.commit("Frame preview camera", SetCamera{cam});
  } else {
    camera_.frame(lo, hi, size_.x, size_.y);
  }
}

void GridView::buildFunctionScene(ModellerState& state) {
  const Grid& grid = state.localGrid();
  const Function& fn = state.function();
  const auto& mask = state.selectionMask();
  appendCube(scene_.lines, {0.5f, 0.52f, 0.58f, 0.35f});
  appendAxes(scene_.lines);
  appendGridLines(grid, neutralLineColor(fn.color), scene_.lines);
  const bool many = grid.nodeCount() > 30000;
  const float nodeSize = grid.nodeCount() > 2000 ? 4.0f : 6.5f;
  for (std::size_t n = 0; n < grid.nodeCount(); ++n) {
    if (mask[n])
      scene_.points.push_back(vertex(grid.nodes()[n], kSelectedColor, nodeSize + 2.5f));
    else if (!many)
      scene_.points.push_back(vertex(grid.nodes()[n], kNodeColor, nodeSize));
  }
  const ViewCamera cam = camera(state);
  const double unit = cam.worldPerPixel(cam.orbit.target, size_.y);  // world size of one pixel
  // The center of transformation of the active op (or the one new ops get).
  const Operation* op = state.op();
  const Center::Kind kind = op ? op->center.kind : state.newOpCenter;
  Vec3 center;
  if (kind == Center::Kind::Point)
    center = op ? op->center.point : state.pointCenter;
  else if (kind == Center::Kind::Selection && state.hasSelection())
    center = centroid(grid.nodes(), &mask);
  else
    center = centroid(grid.nodes(), nullptr);
  const bool absoluteOp =
      op && (std::holds_alternative<MagnetOp>(op->params) || std::holds_alternative<MorphOp>(op->params));
  if (!absoluteOp) {
    appendCross(scene_.overlayLines, center, 9.0 * unit * state.uiScale, kCenterColor);
    scene_.overlayPoints.push_back(vertex(center, kCenterColor, kind == Center::Kind::Point ? 9.0f : 5.0f));
  }
  if (op) {
    if (const auto* m = std::get_if<MagnetOp>(&op->params)) {
      appendCircle(scene_.overlayLines, m->point, m->dmax, cam.right(), cam.up(),
                   {kHandleColor.x, kHandleColor.y, kHandleColor.z, 0.8f});
      scene_.overlayPoints.push_back(vertex(m->point, kHandleColor, 11.0f));
    }
    if (const auto* m = std::get_if<MorphOp>(&op->params))
      for (const MorphPair& pair : m->pairs) {
        line(scene_.overlayLines, pair.from, pair.to, kMorphColor);
        // An arrow head: two short strokes in the view plane.
        const glm::dvec3 dir = pair.to - pair.from;
        if (glm::length(dir) > 1e-9) {
          const glm::dvec3 d = glm::normalize(dir) * (10.0 * unit);
          const glm::dvec3 side = glm::normalize(glm::cross(d, glm::cross(cam.right(), cam.up()))) * (5.0 * unit);
          if (std::isfinite(side.x)) {
            line(scene_.overlayLines, pair.to, pair.to - d + side, kMorphColor);
            line(scene_.overlayLines, pair.to, pair.to - d - side, kMorphColor);
          }
        }
        scene_.overlayPoints.push_back(vertex(pair.from, {0.95f, 0.95f, 0.95f, 1.0f}, 8.0f));
        scene_.overlayPoints.push_back(vertex(pair.to, kMorphColor, 10.0f));
      }
  }
}

const std::vector<Vec3>& GridView::variationImage(ModellerState& state, std::size_t function) {
  const std::uint64_t revision = state.document.revisions().geometry;
  if (revision != variationImageRevision_) {
    variationImages_.clear();
    variationImageRevision_ = revision;
  }
  auto [it, added] = variationImages_.try_emplace(function);
  if (added) {
    try {
      const Project& project = state.document.project();
      it->second = functionImageSamples(project.functions[function], *state.document.evaluatedGrid(function));
    } catch (const ModelError&) {
      it->second.clear();
    }
  }
  return it->second;
}

void GridView::buildIfsScene(ModellerState& state) {
  appendCube(scene_.lines, {0.62f, 0.65f, 0.72f, 0.55f});
  appendAxes(scene_.lines);
  const auto& functions = state.document.project().functions;
  if (const auto& space = state.document.project().space) {
    // A free-form IFS (Thollot et al. 1997, §3.1): its control polygon, and each matrix's image
    // of it (the rows of T·P), which is where that function puts the whole shape.
    const auto& cp = space->control_points;
    for (std::size_t j = 0; j + 1 < cp.size(); ++j) line(scene_.lines, cp[j], cp[j + 1], {0.85f, 0.85f, 0.9f, 0.7f});
    for (std::size_t f = 0; f < functions.size(); ++f) {
      const Function& fn = functions[f];
      if (fn.kind != FunctionKind::Matrix || fn.matrix.size() != cp.size()) continue;
      std::vector<Vec3> image;
      for (const auto& row : fn.matrix) {
        Vec3 q{0.0};
        for (std::size_t j = 0; j < cp.size() && j < row.size(); ++j) q += row[j] * cp[j];
        image.push_back(q);
      }
      const bool active = state.activeFunction == FunctionRef(int(f));
      const glm::vec4 color = lineColor(fn.color, fn.muted ? 0.2f : active ? 0.95f : 0.5f);
      for (std::size_t j = 0; j + 1 < image.size(); ++j) line(scene_.lines, image[j], image[j + 1], color);
      if (active)
        for (const Vec3& q : image) scene_.points.push_back(vertex(q, {glm::vec3(fn.color), 1.0f}, 4.5f));
    }
    for (const Vec3& p : cp) scene_.points.push_back(vertex(p, {0.95f, 0.95f, 0.95f, 1.0f}, 7.0f));
  }
  for (std::size_t f = 0; f < functions.size(); ++f) {
    if (isSetKind(functions[f].kind)) {
      // Condensation sets in their function's colour: primitives as wireframes, meshes as their
      // placed edges, VDB sets as voxel outlines.
      const bool active = state.activeFunction == FunctionRef(int(f));
      const glm::vec4 color = lineColor(functions[f].color, functions[f].muted ? 0.2f : active ? 0.95f : 0.5f);
      const LineSegments& lines = setDrawing(state, f).lines;
      for (std::size_t s = 0; s + 1 < lines.size(); s += 2) line(scene_.lines, lines[s], lines[s + 1], color);
      continue;
    }
    if (functions[f].kind == FunctionKind::Matrix) continue;  // drawn above, through the control points
    std::shared_ptr<const Grid> grid;
    try {
      grid = state.document.evaluatedGrid(f);
    } catch (const ModelError&) {
      continue;
    }
    const bool active = state.activeFunction == FunctionRef(int(f));
    const float alpha = functions[f].muted ? 0.2f : active ? 0.95f : 0.45f;
    if (functions[f].hasVariationStage()) {
      // Flame variations (Draves & Reckase 2003, §3): the grid is only g; draw it faintly and the
      // function's image of X's lattice lines, so the artist sees what the variations do.
      appendGridLines(*grid, lineColor(functions[f].color, 0.25f * alpha), scene_.lines);
      const glm::vec4 color = lineColor(functions[f].color, alpha);
      for (const Vec3& q : variationImage(state, f)) scene_.points.push_back(vertex(q, color, active ? 3.0f : 2.0f));
      continue;
    }
    appendGridLines(*grid, lineColor(functions[f].color, alpha), scene_.lines);
    if (active && grid->nodeCount() <= 30000)
      for (const Vec3& p : grid->nodes())
        scene_.points.push_back(vertex(p, {glm::vec3(functions[f].color), 1.0f}, 4.5f));
  }
  // The final function: its control lattice around the attractor, in its own colour, with its
  // nodes always shown (they are what bends the picture, Sederberg & Parry 1986).
  std::shared_ptr<const Grid> lattice;
  try {
    lattice = state.document.evaluatedFinal();
  } catch (const ModelError&) {
  }
  if (lattice) {
    const bool active = state.activeFunction.isFinal();
    const bool muted = state.document.project().final_function->muted;
    const float alpha = muted ? 0.2f : active ? 0.95f : 0.4f;  // the functions stay the main content
    appendGridLines(*lattice, {glm::vec3(kFinalLatticeColor), alpha}, scene_.lines);
    if (lattice->nodeCount() <= 30000)
      for (const Vec3& p : lattice->nodes())
        scene_.points.push_back(vertex(p, {glm::vec3(kFinalLatticeColor), alpha}, active ? 5.5f : 3.5f));
  }
}

void GridView::render(ModellerState& state, ViewRenderer& renderer) {
  if (!visible_) return;
  target_.resize(int(std::lround(size_.x * framebufferScale_)), int(std::lround(size_.y * framebufferScale_)));
  if (!framedOnce_ && !usesProjectCamera()) {
    // Start with the common initial grid and everything the view shows in the picture.
    std::vector<Vec3> nodes;
    std::vector<FunctionRef> owner;
    pickableNodes(state, nodes, owner);
    const auto& points = controlPoints(state);
    nodes.insert(nodes.end(), points.begin(), points.end());
    Vec3 lo(-1.0), hi(1.0);
    for (const Vec3& p : nodes) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    camera_.frame(lo, hi, size_.x, size_.y);
    framedOnce_ = true;
  }
  const ViewCamera cam = camera(state);
  Key key;
  key.revision = state.document.revisions().geometry;  // the views draw the functions only
  key.function = state.activeFunction;
  key.camera = cam.orbit;
  key.axis = cam.axis;
  key.size = size_;
  key.scale = framebufferScale_ * state.uiScale;
  if (content_ == Content::FunctionGrid) {
    key.op = state.activeOp;
    key.selection = state.selection();
    key.point = state.pointCenter;
    key.centerKind = int(state.newOpCenter);
  }
  if (key == key_) return;
  key_ = key;
  scene_.clear();
  // A matrix function has no grid: its views show the control points and the matrices' images.
  if (content_ == Content::FunctionGrid && hasGrid(state.function()))
    buildFunctionScene(state);
  else
    buildIfsScene(state);
  const glm::dmat4 vp = camera(state).viewProjection(size_.x, size_.y);
  renderer.drawScene(target_, glm::mat4(vp), scene_, framebufferScale_ * state.uiScale, kBackgroundTop,
                     kBackgroundBottom);
}

void GridView::present(int framebufferHeight) const {
  if (!visible_) return;
  const int x = int(std::lround(screenOrigin_.x * framebufferScale_));
  const int top = int(std::lround(screenOrigin_.y * framebufferScale_));
  const int y = framebufferHeight - top - target_.height();
  target_.blitTo(x, y);
}

}  // namespace gridifs::ui
