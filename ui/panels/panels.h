#pragma once
// The modeller's panels, one per file: each draws from the Document (through the
// ModellerState) and emits edits; none holds geometry logic.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "schema/operation_table.h"
#include "ui/base/edit_queue.h"
#include "ui/base/modeller_state.h"

namespace gridifs::ui {

/// What the Functions panel keeps between frames: a display cache of the active function's
/// contractivity bound (Gröller & Wegenkittl 1994, §1.1).
struct FunctionsPanelState {
  struct {
    std::uint64_t revision = 0;
    int function = -1;  // of the IFS (the final function is outside the loop: no bound)
    double bound = 0.0;
    bool valid = false;
  } contractivity;
  std::string variationFilter;  // the Variations section's search text
};
/// functions_panel.cpp: the IFS's functions — add, duplicate, delete, reorder, mute, rename,
/// weight, color, palette index, resolution, placement (Gröller & Wegenkittl 1994, §4.5) — and
/// the final function below them: add, remove, mute, interpolation, resolution, placement.
void drawFunctionsPanel(ModellerState& state, EditQueue& edits, FunctionsPanelState& panel);
/// variations_panel.cpp: the flame variations of function `ref` (its Variations section): blend
/// weights and parameters as keyable sliders, a searchable list to add one, the post transform.
void drawVariationsSection(ModellerState& state, EditQueue& edits, FunctionsPanelState& panel, FunctionRef ref,
                           const Function& f);
/// operation_stack_panel.cpp: add operations (with the current selection) and reorder, mute,
/// delete and pick them in the active function's stack.
void drawOperationStackPanel(ModellerState& state, EditQueue& edits);
/// The height an Operations panel `panelWidth` wide needs for its add toolbar and the first rows
/// of the stack (call inside a frame: it measures with the current font and style).
float operationStackPanelMinHeight(float panelWidth);

/// What the Parameters panel keeps between frames.
struct OperationPanelState {
  /// An operation's expression fields keep what the artist typed, even when it does not parse
  /// yet (the op itself only ever holds valid expressions).
  struct {
    FunctionRef function;
    int op = -1;
    std::vector<std::string> text, base;
  } expressionEdit;
  bool morphAsDirection = false;  // morph vectors entered as start + direction
};
/// operation_panel.cpp: every parameter of the active operation, edited live.
void drawOperationPanel(ModellerState& state, EditQueue& edits, OperationPanelState& panel);

/// What the Selection panel keeps between frames: the index box being typed.
struct SelectionPanelState {
  SelectionBox boxEntry{{0, 2}, {0, 5}, {0, 5}, SelectionOp::Or};
};
/// selection_panel.cpp: index boxes with or/and/xor/minus, all/none/invert, the center for new ops.
void drawSelectionPanel(ModellerState& state, EditQueue& edits, SelectionPanelState& panel);
/// shading_panel.cpp: the shaded display's lights, ambient, specular, occlusion, fog and depth of
/// field, one undo step per slider drag.
void drawShadingPanel(ModellerState& state, EditQueue& edits);
/// camera_panel.cpp: the preview camera's projection, orbit, field of view and stereo pair.
void drawCameraPanel(ModellerState& state, EditQueue& edits);
/// field_layers_panel.cpp: the volume's fractal field layers (role, strength, field parameters,
/// the shape a field is blended with), one undo step per slider drag.
void drawFieldLayersPanel(ModellerState& state, EditQueue& edits);

/// What the Matrices window keeps between frames: the free-form preset it would apply next, the
/// control net a grid project would be mapped onto, and the joints a hand edit of a matrix broke
/// (the project as it was before the first such edit; not saved).
struct MatricesWindowState {
  int preset = 0, degree = 3;
  float split = 0.5f, roughness = 0.0f;
  int seed = 1;
  int netDegree = 2, netShape = 0;
  float netHeight = 0.5f;
  std::optional<Project> jointBaseline;
  std::vector<std::string> jointWarnings;
  std::uint64_t jointRevision = 0;  // of the document when jointWarnings were found
  std::string netMessage;           // why the last mapping onto a control net failed
};
/// matrices_window.cpp: the transition matrix, and a free-form IFS's control points and
/// matrices, with presets (Function › Matrices…).
void drawMatricesWindow(ModellerState& state, EditQueue& edits, MatricesWindowState& window);
/// help_window.cpp: the keyboard and mouse shortcuts.
void drawHelpWindow(ModellerState& state);

/// Adds an op of type `spec` (an addable entry of the operation table) after the active op with
/// the current selection and center (operation_stack_panel.cpp). Shared by the panel's toolbar
/// and the Operation menu.
void addOperation(ModellerState& state, EditQueue& edits, const OperationSpec& spec);
/// Deletes the active op (Delete key, menu, panel).
void deleteActiveOperation(ModellerState& state, EditQueue& edits);
/// Adds a new 6×6×6 function (functions_panel.cpp).
void addFunction(ModellerState& state, EditQueue& edits);
/// Adds a condensation or median function whose set is a ball of radius 0.3 at the origin
/// (functions_panel.cpp).
void addSetFunction(ModellerState& state, EditQueue& edits, FunctionKind kind);
/// Adds an undistorted final function and makes it active; removes it (functions_panel.cpp).
void addFinalFunction(ModellerState& state, EditQueue& edits);
void deleteFinalFunction(ModellerState& state, EditQueue& edits);

}  // namespace gridifs::ui
