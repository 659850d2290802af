// The main menu and the keyboard shortcuts (Gröller & Wegenkittl 1994, §4.2: "all
// functions can be activated by a menu").
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "edit/node_picking.h"
#include "ui/dialogs/export_dialog.h"
#include "ui/panels/panels.h"
#include "ui/panels/timeline_panel.h"
#include "ui/shell/app_commands.h"
#include "ui/shell/symmetry_menu.h"

namespace gridifs::ui {
namespace {

void selectAll(ModellerState& s) {
  const Index3 r = s.function().resolution;
  s.selection() = {SelectionBox{{0, r[0] - 1}, {0, r[1] - 1}, {0, r[2] - 1}, SelectionOp::Or}};
}

void invertSelection(ModellerState& s) {
  const auto& mask = s.selectionMask();
  std::vector<unsigned char> inverted(mask.size());
  for (std::size_t n = 0; n < mask.size(); ++n) inverted[n] = mask[n] ? 0 : 1;
  Selection result = boxesFromMask(inverted, s.function().resolution);
  if (int(result.size()) <= limits::kMaxSelectionBoxes) s.selection() = result;
}

void toggleView(ModellerState& s, int view) { s.maximizedGridView = s.maximizedGridView == view ? -1 : view; }

}  // namespace

float drawMenuBar(AppCommands& app) {
  ModellerState& s = app.state;
  Document& d = s.document;
  float height = 0.0f;
  if (!ImGui::BeginMainMenuBar()) return height;
  height = ImGui::GetWindowSize().y;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("New", "Ctrl+N")) app.files.requestNew();
    if (ImGui::MenuItem("New random world...")) s.exploreRandom = true;
    s.probe.item("menu.new_random");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Draw random worlds worth looking at in the Explore window; click one to adopt it");
    if (ImGui::BeginMenu("Examples", !app.files.examples().empty())) {
      for (const auto& file : app.files.examples())
        if (ImGui::MenuItem(file.stem().string().c_str())) app.files.requestOpenExample(file);
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Open...", "Ctrl+O")) app.files.requestOpenDialog();
    if (ImGui::BeginMenu("Open Recent", !app.files.recent().empty())) {
      for (const auto& file : app.files.recent())
        if (ImGui::MenuItem(file.filename().string().c_str())) app.files.requestOpen(file);
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Import flame...")) app.files.requestImportFlameDialog();
    s.probe.item("menu.import_flame");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Open a flame genome (.flame from flam3, Apophysis, JWildfire, Fractorium) as a new project");
    ImGui::Separator();
    if (ImGui::MenuItem("Save", "Ctrl+S")) app.files.save();
    if (ImGui::MenuItem("Save As...", "Ctrl+Shift+S")) app.files.saveAsDialog();
    ImGui::Separator();
    if (app.exporter) {
      app.exporter->drawMenuItems(s);  // Export mesh..., Export points...
      ImGui::Separator();
    }
    if (ImGui::MenuItem("Combine...")) s.showCombine = true;
    s.probe.item("menu.combine");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Combine the open project with a second one: union, concatenation, product or shuffle");
    ImGui::Separator();
    if (ImGui::MenuItem("Render animation...")) s.showRenderAnimation = true;
    s.probe.item("menu.render_animation");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Render the timeline's frames to numbered image files");
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) app.files.requestQuit();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    const std::string undo = d.canUndo() ? "Undo " + d.undoLabel() : "Undo";
    const std::string redo = d.canRedo() ? "Redo " + d.redoLabel() : "Redo";
    if (ImGui::MenuItem(undo.c_str(), "Ctrl+Z", false, d.canUndo())) app.edits.undo();
    if (ImGui::MenuItem(redo.c_str(), "Ctrl+Shift+Z", false, d.canRedo())) app.edits.redo();
    ImGui::Separator();
    if (ImGui::MenuItem("Delete operation", "Delete", false, s.op() != nullptr)) deleteActiveOperation(s, app.edits);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Function")) {
    if (ImGui::MenuItem(s.document.project().space ? "Add matrix function" : "Add 6x6x6 grid"))
      addFunction(s, app.edits);
    if (!s.document.project().space) {
      if (ImGui::MenuItem("Add condensation function")) addSetFunction(s, app.edits, FunctionKind::Condensation);
      if (ImGui::MenuItem("Add median function")) addSetFunction(s, app.edits, FunctionKind::Median);
    }
    if (ImGui::MenuItem("Matrices...", "M", s.showMatrices)) s.showMatrices = !s.showMatrices;
    if (ImGui::MenuItem("Construction tree...", "T", s.showConstruction)) s.showConstruction = !s.showConstruction;
    s.probe.item("menu.construction");
    drawSymmetryMenu(s, app.edits);  // ui/shell/symmetry_menu.cpp
    ImGui::Separator();
    const bool haveFinal = d.project().final_function.has_value();
    if (ImGui::MenuItem(haveFinal ? "Remove final function" : "Add final function")) {
      if (haveFinal)
        deleteFinalFunction(s, app.edits);
      else
        addFinalFunction(s, app.edits);
    }
    ImGui::Separator();
    const auto& functions = d.project().functions;
    for (int i = 0; i < int(functions.size()); ++i)
      if (ImGui::MenuItem(functions[std::size_t(i)].name.c_str(), nullptr, s.activeFunction == FunctionRef(i)))
        s.activate(FunctionRef(i));
    if (haveFinal && ImGui::MenuItem("Final function", nullptr, s.activeFunction.isFinal()))
      s.activate(FunctionRef::finalFunction());
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Operation")) {
    for (const OperationSpec& spec : operationTable())
      if (spec.addable && ImGui::MenuItem(spec.title)) addOperation(s, app.edits, spec);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Select")) {
    if (ImGui::MenuItem("All nodes", "Ctrl+A")) selectAll(s);
    if (ImGui::MenuItem("None", "Esc")) s.selection().clear();
    if (ImGui::MenuItem("Invert", "Ctrl+I")) invertSelection(s);
    ImGui::EndMenu();
  }
  const bool viewMenu = ImGui::BeginMenu("View");
  s.probe.item("menu.view");
  if (viewMenu) {
    if (ImGui::MenuItem("Frame", "F")) app.frameViews();
    if (ImGui::MenuItem("Explore...", "E")) s.showExplore = true;
    s.probe.item("menu.explore");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Variants of the open project, random worlds and breeding, as live thumbnails");
    if (ImGui::MenuItem("Camera", nullptr, s.showCamera)) s.showCamera = !s.showCamera;
    s.probe.item("menu.camera");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The camera's projection, orbit, field of view and stereo pair");
    if (ImGui::MenuItem("Live", nullptr, s.showLive)) s.showLive = !s.showLive;
    s.probe.item("menu.live");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("The bindings that sound, OSC and MIDI drive, their values, and what came in");
    ImGui::Separator();
    static const char* names[] = {"Top", "Side", "Front", "User"};
    static const char* keys[] = {"1", "2", "3", "4"};
    if (ImGui::MenuItem("All four grid views", nullptr, s.maximizedGridView < 0)) s.maximizedGridView = -1;
    for (int v = 0; v < 4; ++v)
      if (ImGui::MenuItem(names[v], keys[v], s.maximizedGridView == v)) toggleView(s, v);
    ImGui::Separator();
    if (ImGui::BeginMenu("Preview mode")) {
      if (ImGui::MenuItem("Z-buffer (nearest point)", nullptr, s.previewMode == PreviewMode::ZBuffer))
        s.previewMode = PreviewMode::ZBuffer;
      if (ImGui::MenuItem("Flame (log density)", nullptr, s.previewMode == PreviewMode::Flame))
        s.previewMode = PreviewMode::Flame;
      if (ImGui::MenuItem("Shaded (lights, shadows, occlusion)", nullptr, s.previewMode == PreviewMode::Shaded))
        s.previewMode = PreviewMode::Shaded;
      if (ImGui::MenuItem("Mesh F^n(A) (deterministic)", nullptr, s.previewMode == PreviewMode::Mesh))
        s.previewMode = PreviewMode::Mesh;
      if (ImGui::MenuItem("Volume (measure attractor, ray-marched)", nullptr, s.previewMode == PreviewMode::Volume))
        s.previewMode = PreviewMode::Volume;
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem(s.previewPaused ? "Resume preview" : "Pause preview", "Space"))
      s.previewPaused = !s.previewPaused;
    if (ImGui::MenuItem(s.playback.playing ? "Pause animation" : "Play animation", "Alt+A"))
      togglePlayback(s, app.edits);
    ImGui::Separator();
    if (ImGui::MenuItem("Reset layout")) app.resetLayout();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("Shortcuts", "F1", s.showHelp)) s.showHelp = !s.showHelp;
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
  return height;
}

namespace {

template <class Pressed>
void handleKey(AppCommands& app, const ImGuiIO& io, bool ctrl, bool shift, bool alt, Pressed pressed) {
  ModellerState& s = app.state;
  // Ctrl shortcuts work everywhere except undo/redo while typing (the field has its own).
  if (ctrl) {
    if (pressed(GLFW_KEY_N)) app.files.requestNew();
    if (pressed(GLFW_KEY_O)) app.files.requestOpenDialog();
    if (pressed(GLFW_KEY_S)) {
      if (shift)
        app.files.saveAsDialog();
      else
        app.files.save();
    }
    if (pressed(GLFW_KEY_Q)) app.files.requestQuit();
    if (!io.WantTextInput) {
      if (pressed(GLFW_KEY_Z)) {
        if (shift)
          app.edits.redo();
        else
          app.edits.undo();
      }
      if (pressed(GLFW_KEY_Y)) app.edits.redo();
      if (pressed(GLFW_KEY_A)) selectAll(s);
      if (pressed(GLFW_KEY_I)) invertSelection(s);
    }
    return;
  }
  if (io.WantTextInput) return;
  // The timeline: Blender's Alt+A plays (Space already pauses the preview), arrows step frames.
  if (alt && pressed(GLFW_KEY_A)) togglePlayback(s, app.edits);
  if (pressed(GLFW_KEY_LEFT)) {
    if (shift)
      jumpToEnd(s, app.edits, false);
    else
      stepFrames(s, app.edits, -1);
  }
  if (pressed(GLFW_KEY_RIGHT)) {
    if (shift)
      jumpToEnd(s, app.edits, true);
    else
      stepFrames(s, app.edits, 1);
  }
  if (pressed(GLFW_KEY_DELETE)) deleteActiveOperation(s, app.edits);
  if (pressed(GLFW_KEY_F)) app.frameViews();
  if (pressed(GLFW_KEY_ESCAPE)) s.selection().clear();
  if (pressed(GLFW_KEY_SPACE)) s.previewPaused = !s.previewPaused;
  if (pressed(GLFW_KEY_F1)) s.showHelp = !s.showHelp;
  if (pressed(GLFW_KEY_M)) s.showMatrices = !s.showMatrices;
  if (pressed(GLFW_KEY_T)) s.showConstruction = !s.showConstruction;
  if (pressed(GLFW_KEY_E)) s.showExplore = true;
  for (int v = 0; v < 4; ++v)
    if (pressed(GLFW_KEY_1 + v) || pressed(GLFW_KEY_KP_1 + v)) toggleView(s, v);
}

}  // namespace

void handleShortcuts(AppCommands& app) {
  const ImGuiIO& io = ImGui::GetIO();
  ModellerState& s = app.state;
  const auto presses = std::move(s.keyPresses);
  s.keyPresses.clear();
  if (app.files.modalOpen()) return;
  for (const ModellerState::KeyPress& press : presses) {
    const bool ctrl = press.mods & GLFW_MOD_CONTROL, shift = press.mods & GLFW_MOD_SHIFT,
               alt = press.mods & GLFW_MOD_ALT;
    handleKey(app, io, ctrl, shift, alt, [&](int key) { return press.key == key; });
  }
}

}  // namespace gridifs::ui
