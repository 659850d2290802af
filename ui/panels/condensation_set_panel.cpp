// The set editor of a condensation or median function: Barnsley's constant condensation map
// onto its set, or Sokolov & Gentil's condensation function M(·, C) (§3.2) with the rotated
// median of §4.1. Every drag is one undo step; every change bumps the geometry revision, so the
// preview restarts and the views redraw the set.
#include "ui/panels/condensation_set_panel.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

#include "schema/settings_tables.h"
#include "ui/base/widgets.h"
#include "ui/panels/key_button.h"
#include "ui/panels/setting_slider.h"

namespace gridifs::ui {
namespace {

namespace fs = std::filesystem;

struct ShapeChoice {
  SetShape shape;
  const char* label;
  const char* help;
};
const ShapeChoice kShapes[] = {
    {SetShape::Sphere, "Sphere", "A ball: centre and radius"},
    {SetShape::Box, "Box", "An axis-aligned box: centre and full edge lengths"},
    {SetShape::Torus, "Torus", "A ring: centre, major and minor radius, axis of revolution"},
    {SetShape::Mesh, "Mesh file", "An OBJ, PLY, STL or OFF mesh, filled or as its surface, placed in X"},
    {SetShape::Vdb, "VDB file", "The voxels of a VDB float grid at or above a threshold"},
    {SetShape::Image, "Drawing", "A PNG, JPEG or EXR drawing: its dark pixels as a thin slab on z = 0, placed in X"},
};

const char* shapeLabel(SetShape shape) {
  for (const ShapeChoice& c : kShapes)
    if (c.shape == shape) return c.label;
  return "?";
}

/// One undo step per drag of the widget just drawn: the whole set is replaced.
void setGesture(EditQueue& edits, const char* label, bool changed, FunctionRef ref, const CondensationSet& set) {
  gestureItem(edits, label, changed, SetCondensationSet{ref, set});
}

/// The key button of the set's number `key` (functions[i].set.KEY): every number of a set is
/// keyable (the rotated median's too), as the paper's morphing sequences animate them.
void setKey(ModellerState& state, EditQueue& edits, FunctionRef ref, const std::string& key, const double* values,
            int components = 1) {
  keyButton(state, edits, ref.path() + ".set." + key, values, components);
}

/// The drag of the set's number `key` on `set`, a copy of the project's, from the shape's table
/// (condensationSetTable), so it offers what reading and validation accept.
bool setDrag(CondensationSet& set, const char* key) {
  return settingDrag(condensationSetTable(set.shape).field(key), &set);
}

/// The table's help for the set's number `key`.
const char* setHelp(const CondensationSet& set, const char* key) {
  return condensationSetTable(set.shape).field(key).tooltip;
}

/// `chosen` as the project will store it: relative to the project's folder where the project
/// has a file, else as chosen.
std::string storedPath(const ModellerState& state, const fs::path& chosen) {
  if (state.document.path().empty()) return chosen.string();
  std::error_code ec;
  const fs::path folder = fs::absolute(state.projectFolder(), ec);
  const fs::path relative = fs::absolute(chosen, ec).lexically_normal().lexically_relative(folder.lexically_normal());
  return relative.empty() ? chosen.string() : relative.generic_string();
}

void drawPrimitive(ModellerState& state, EditQueue& edits, FunctionRef ref, const CondensationSet& current) {
  CondensationSet set = current;
  setKey(state, edits, ref, "center", &current.center.x, 3);
  bool changed = setDrag(set, "center");
  state.probe.frame("set.center");
  setGesture(edits, "Move set", changed, ref, set);
  contextHelp(state, setHelp(set, "center"));
  switch (set.shape) {
    case SetShape::Sphere:
      setKey(state, edits, ref, "radius", &current.radius);
      changed = setDrag(set, "radius");
      state.probe.frame("set.radius");
      setGesture(edits, "Sphere radius", changed, ref, set);
      contextHelp(state, setHelp(set, "radius"));
      break;
    case SetShape::Box:
      setKey(state, edits, ref, "size", &current.size.x, 3);
      changed = setDrag(set, "size");
      state.probe.frame("set.size");
      setGesture(edits, "Box size", changed, ref, set);
      contextHelp(state, setHelp(set, "size"));
      break;
    case SetShape::Torus:
      setKey(state, edits, ref, "major", &current.major);
      changed = setDrag(set, "major");
      state.probe.frame("set.major");
      setGesture(edits, "Torus major radius", changed, ref, set);
      contextHelp(state, setHelp(set, "major"));
      setKey(state, edits, ref, "minor", &current.minor);
      changed = setDrag(set, "minor");
      state.probe.frame("set.minor");
      setGesture(edits, "Torus minor radius", changed, ref, set);
      contextHelp(state, setHelp(set, "minor"));
      setKey(state, edits, ref, "axis", &current.axis.x, 3);
      changed = setDrag(set, "axis");
      if (glm::length(set.axis) < 1e-6) set.axis = current.axis;  // a zero axis has no plane of revolution
      setGesture(edits, "Torus axis", changed, ref, set);
      contextHelp(state, setHelp(set, "axis"));
      break;
    case SetShape::Mesh:
    case SetShape::Vdb:
    case SetShape::Image:
      break;
  }
}

/// A drawing's threshold, thickness and inversion (Sokolov & Gentil's sketches as sets).
void drawImageFields(ModellerState& state, EditQueue& edits, FunctionRef ref, const CondensationSet& current) {
  CondensationSet set = current;
  setKey(state, edits, ref, "threshold", &current.threshold);
  bool changed = setDrag(set, "threshold");
  state.probe.frame("set.threshold");
  setGesture(edits, "Drawing threshold", changed, ref, set);
  contextHelp(state, setHelp(set, "threshold"));
  setKey(state, edits, ref, "thickness", &current.thickness);
  changed = setDrag(set, "thickness");
  state.probe.frame("set.thickness");
  setGesture(edits, "Drawing thickness", changed, ref, set);
  contextHelp(state, setHelp(set, "thickness"));
  set = current;
  if (ImGui::Checkbox("Invert", &set.invert))
    edits.commit(set.invert ? "Invert drawing" : "Drawing not inverted", SetCondensationSet{ref, set});
  state.probe.frame("set.invert");
  contextHelp(state, setHelp(set, "invert"));
}

}  // namespace

void CondensationSetPanel::drawFile(ModellerState& state, EditQueue& edits, FunctionRef ref,
                                    const CondensationSet& current) {
  const bool mesh = current.shape == SetShape::Mesh;
  const bool image = current.shape == SetShape::Image;
  // The file name: typed (committed on Enter or when the field loses focus) or browsed.
  if (!editingPath_) pathText_ = current.path;
  ImGui::InputText("File", &pathText_);
  state.probe.frame("set.path");
  editingPath_ = ImGui::IsItemActive();
  if (ImGui::IsItemDeactivatedAfterEdit() && pathText_ != current.path) {
    edits.commit(mesh ? "Set mesh file" : image ? "Set drawing file" : "Set VDB file", SetSetFile{ref, pathText_});
  }
  contextHelp(state, "The file's path, relative to the project file's folder");
  if (ImGui::Button("Browse...")) browse(state, current, current.shape);
  state.probe.item("set.browse");
  contextHelp(state, mesh    ? "Pick an OBJ, PLY, STL or OFF mesh"
                     : image ? "Pick a PNG, JPEG or EXR drawing"
                             : "Pick an OpenVDB file");

  CondensationSet set = current;
  if (image) drawImageFields(state, edits, ref, current);
  if (mesh || image) {
    if (mesh) {
      int fill = set.fill == SetFill::Surface ? 1 : 0;
      static const char* fills[] = {"Solid", "Surface"};
      if (ImGui::Combo("Fill", &fill, fills, 2)) {
        edits.commit(SetSetFill{ref, fill ? SetFill::Surface : SetFill::Solid});
      }
      state.probe.frame("set.fill");
      contextHelp(state, "Solid: the volume the mesh encloses (it must be closed); surface: a shell around its faces");
    }
    if (ImGui::CollapsingHeader("Placement", ImGuiTreeNodeFlags_DefaultOpen)) {
      setKey(state, edits, ref, "placement.translate", &current.placement.translate.x, 3);
      bool changed = dragVec3("Translate", set.placement.translate, 0.005);
      state.probe.frame("set.translate");
      setGesture(edits, "Move set mesh", changed, ref, set);
      setKey(state, edits, ref, "placement.rotate", &current.placement.rotate.x, 3);
      changed = dragVec3("Rotate", set.placement.rotate, 0.5, -360.0, 360.0, "%.1f°");
      setGesture(edits, "Rotate set mesh", changed, ref, set);
      setKey(state, edits, ref, "placement.scale", &current.placement.scale.x, 3);
      changed = dragVec3("Scale", set.placement.scale, 0.005, -20.0, 20.0);
      for (int d = 0; d < 3; ++d)
        if (set.placement.scale[d] == 0.0) set.placement.scale[d] = current.placement.scale[d];  // never flat
      setGesture(edits, "Scale set mesh", changed, ref, set);
      contextHelp(state, "The mesh's own coordinates are scaled, then rotated, then moved into X");
    }
  } else {
    std::string grid = set.grid;
    const bool typed = ImGui::InputText("Grid", &grid);
    state.probe.frame("set.grid");
    gestureItem(edits, "VDB grid name", typed && !grid.empty(), SetSetGrid{ref, grid});
    contextHelp(state, "The name of the float grid in the file");
    setKey(state, edits, ref, "threshold", &current.threshold);
    const bool changed = setDrag(set, "threshold");
    state.probe.frame("set.threshold");
    setGesture(edits, "VDB threshold", changed, ref, set);
    contextHelp(state, setHelp(set, "threshold"));
  }
}

void CondensationSetPanel::browse(ModellerState& state, const CondensationSet& set, SetShape shape) {
  const bool mesh = shape == SetShape::Mesh;
  const bool image = shape == SetShape::Image;
  browsing_ = state.activeFunction;
  browsingFor_ = shape;
  const fs::path folder = state.projectFolder();
  const fs::path start = set.path.empty() ? folder : (folder / set.path).parent_path();
  std::error_code ec;
  browser_.open(FileBrowser::Mode::Open, fs::is_directory(start, ec) ? start : folder, {},
                mesh    ? std::vector<std::string>{".obj", ".ply", ".stl", ".off"}
                : image ? std::vector<std::string>{".png", ".jpg", ".jpeg", ".exr"}
                        : std::vector<std::string>{".vdb"},
                mesh    ? "Condensation mesh"
                : image ? "Condensation drawing"
                        : "Condensation VDB");
}

void CondensationSetPanel::draw(ModellerState& state, EditQueue& edits) {
  state.clampIndices();
  const FunctionRef ref = state.activeFunction;
  const Function& f = state.function();
  if (!isSetKind(f.kind)) return;
  const CondensationSet& set = f.set;
  const bool median = f.kind == FunctionKind::Median;
  ImGui::TextColored(ImVec4(float(f.color.x), float(f.color.y), float(f.color.z), 1.0f), "%s", f.name.c_str());
  ImGui::SameLine();
  ImGui::TextDisabled(median ? "median: f_C = M(·, C)" : "condensation: onto C");
  ImGui::PushItemWidth(-ImGui::CalcTextSize("Threshold_").x);

  if (ImGui::BeginCombo("Set", shapeLabel(set.shape))) {
    for (const ShapeChoice& c : kShapes) {
      if (ImGui::Selectable(c.label, c.shape == set.shape) && c.shape != set.shape) {
        const SetShape shape = c.shape;
        // A file set needs its file first: the browser picks it, and the shape and the file
        // become one undo step (a mesh path is no VDB path, and the other way round).
        const bool fileSet = shape == SetShape::Mesh || shape == SetShape::Vdb || shape == SetShape::Image;
        auto kindOfPath = [](const std::string& p) {
          const std::string ext = fs::path(p).extension().string();
          if (ext == ".vdb") return SetShape::Vdb;
          if (ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".exr") return SetShape::Image;
          return SetShape::Mesh;
        };
        const bool pathFits = !set.path.empty() && kindOfPath(set.path) == shape;
        if (fileSet && !pathFits)
          browse(state, set, shape);
        else
          edits.commit(SetSetShape{ref, shape, std::nullopt});
      }
      state.probe.item(std::string("set.shape.") + setShapeName(c.shape));
      contextHelp(state, c.help);
    }
    ImGui::EndCombo();
  }
  state.probe.frame("set.shape");
  contextHelp(state, "What the set is: a primitive, a mesh file or a VDB file");

  // The drawing the views show, made (and so checked) by the core voxelizer: its sentence is the
  // message when the set cannot be used.
  const SetOutlineCache::Drawing& drawing = state.setOutlines.get(set, state.projectFolder(), ref.path() + ".set");
  message_ = drawing.error;
  if (!drawing.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.6f, 0.3f, 1.0f));
    ImGui::TextWrapped("%s", drawing.error.c_str());
    ImGui::PopStyleColor();
    state.probe.item("set.message");
    ImGui::TextDisabled("The preview keeps its last picture; Ctrl+Z returns to the last good set.");
  }

  if (set.shape == SetShape::Mesh || set.shape == SetShape::Vdb || set.shape == SetShape::Image)
    drawFile(state, edits, ref, set);
  else
    drawPrimitive(state, edits, ref, set);

  if (median) {
    const FieldInfo& rotateField = medianRotateField();
    const std::string rotatePath = ref.path() + "." + rotateField.key;
    keyButton(state, edits, rotatePath, &f.rotate);
    double rotate = f.rotate;
    const bool changed =
        dragDouble(rotateField.label, rotate, rotateField.speed, rotateField.min, rotateField.max, rotateField.format);
    state.probe.frame("set.rotate");
    gestureItem(edits, "Median rotation", changed, SetParameter{rotatePath, rotate, "Median rotation"});
    contextHelp(state, rotateField.tooltip);
    const FieldInfo& axisField = medianRotateAxisField();
    keyButton(state, edits, ref.path() + "." + axisField.key, &f.rotate_axis.x, 3);
    Vec3 axis = f.rotate_axis;
    // The drag stays within a unit's reach; the axis's length does not matter.
    bool axisChanged = dragVec3(axisField.label, axis, axisField.speed, -1.0, 1.0);
    if (glm::length(axis) < 1e-6) axisChanged = false;  // a zero axis turns nothing
    state.probe.frame("set.rotate_axis");
    gestureItem(edits, "Median rotation axis", axisChanged, SetMedianAxis{ref, axis});
    contextHelp(state, axisField.tooltip);
  }
  ImGui::PopItemWidth();

  if (auto chosen = browser_.draw(state.probe)) {
    const std::string path = storedPath(state, *chosen);
    const FunctionRef target = browsing_;
    const SetShape shape = browsingFor_;
    const bool newShape = browsing_.in(state.document.project()).set.shape != shape;
    const std::string label = newShape                   ? std::string("Set shape: ") + setShapeName(shape)
                              : shape == SetShape::Mesh  ? "Set mesh file"
                              : shape == SetShape::Image ? "Set drawing file"
                                                         : "Set VDB file";
    edits.commit(label, SetSetShape{target, shape, path});
  }
}

}  // namespace gridifs::ui
