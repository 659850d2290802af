#pragma once
// The modeller's panels, one per file: each draws from the Document (through the
// ModellerState) and emits edits; none holds geometry logic.
#include "model/operation_table.h"
#include "ui/edit_queue.h"
#include "ui/modeller_state.h"

namespace gridifs::ui {

/// functions_panel.cpp: the IFS's functions — add, duplicate, delete, reorder, mute, rename,
/// weight, color, palette index, resolution, placement (Gröller & Wegenkittl 1994, §4.5) — and
/// the final function below them: add, remove, mute, interpolation, resolution, placement.
void drawFunctionsPanel(ModellerState& state, EditQueue& edits);
/// variations_panel.cpp: the flame variations of function `ref` (its Variations section): blend
/// weights and parameters as keyable sliders, a searchable list to add one, the post transform.
void drawVariationsSection(ModellerState& state, EditQueue& edits, FunctionRef ref, const Function& f);
/// operation_stack_panel.cpp: add operations (with the current selection) and reorder, mute,
/// delete and pick them in the active function's stack.
void drawOperationStackPanel(ModellerState& state, EditQueue& edits);
/// The height an Operations panel `panelWidth` wide needs for its add toolbar and the first rows
/// of the stack (call inside a frame: it measures with the current font and style).
float operationStackPanelMinHeight(float panelWidth);
/// operation_panel.cpp: every parameter of the active operation, edited live.
void drawOperationPanel(ModellerState& state, EditQueue& edits);
/// selection_panel.cpp: index boxes with or/and/xor/minus, all/none/invert, the center for new ops.
void drawSelectionPanel(ModellerState& state, EditQueue& edits);
/// shading_panel.cpp: the shaded display's lights, ambient, specular, occlusion, fog and depth of
/// field, one undo step per slider drag.
void drawShadingPanel(ModellerState& state, EditQueue& edits);
/// matrices_window.cpp: the transition matrix, and a free-form IFS's control points and
/// matrices, with presets (Function › Matrices…).
void drawMatricesWindow(ModellerState& state, EditQueue& edits);
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
