#pragma once
// The editor of one operation in the Parameters panel: a local copy of the operation that widgets
// edit, handed to the Document as one undo step per gesture (IsItemActivated to
// IsItemDeactivatedAfterEdit). operation_panel.cpp draws the scalar parameters of the operation
// table; operation_param_editors.cpp draws the structured ones (expressions, calculator
// variables, morph vectors, node moves).
#include <string>

#include "schema/operation_table.h"
#include "ui/base/edit_queue.h"
#include "ui/base/modeller_state.h"
#include "ui/panels/panels.h"

namespace gridifs::ui {

struct OpEditor {
  ModellerState& state;
  OperationPanelState& panel;
  EditQueue& edits;
  FunctionRef function;  // the edited function (the final one included)
  int index;
  Operation op;  // the local copy widgets edit

  /// The gesture of the item just submitted: `changed` hands the local copy to the Document.
  void item(const std::string& label, bool changed);
  /// One finished edit (a button), one undo step.
  void commit(const std::string& label);
};

/// The widget of one Number, Integer, Seed, Vector or Choice parameter; true when it changed.
/// Also draws the field parameters of the volume's field layers (field_layers_panel.cpp).
bool scalarWidget(const ParamSpec& s, OpParams& params);

/// The Expression parameters of an operation, drawn together: what the artist types stays in the
/// field; only text that passes the operation's rules reaches the Document.
void drawExpressionParams(OpEditor& e, const OperationSpec& spec);
/// A CalculatorVars parameter: three sliders with editable ranges.
void drawCalculatorVars(OpEditor& e, const OperationSpec& spec, const ParamSpec& param);
/// A MorphPairs parameter: start and end (or direction) of each vector, add and remove.
void drawMorphPairs(OpEditor& e, const OperationSpec& spec, const ParamSpec& param);
/// A NodeMoves parameter: the list of moved nodes (moves are made by dragging in a grid view).
void drawNodeMoves(OpEditor& e, const ParamSpec& param);

}  // namespace gridifs::ui
