#pragma once
// The vocabulary of named edits: every change the modeller makes to a project, as a plain value
// that says what it does (SetFunctionWeight{ref, 0.5}) instead of a function that does it. The
// Document applies one as an undo step or a gesture update (edit/document.h); tests build the same
// values the panels do. Each alternative has apply(Project&) and label() (its undo step's name);
// the rules for new functions and operations are in edit/new_function.h and edit/operation_edits.h.
//
// Thread-safety: plain values; applyEdit touches only the project given. applyEdit throws
// ModelError when the edit names something the project does not have (a function, operation,
// light, cell or setting); the project may then be half changed, which is why the Document
// applies edits to a copy.
#include <string>
#include <variant>

#include "edit/binding_edits.h"
#include "edit/construction_edits.h"
#include "edit/field_layer_edits.h"
#include "edit/function_edits.h"
#include "edit/key_edits.h"
#include "edit/matrix_edits.h"
#include "edit/operation_edits.h"
#include "edit/parameter_edit.h"
#include "edit/set_edits.h"
#include "edit/settings_edits.h"
#include "edit/shading_edits.h"
#include "edit/variation_edits.h"
#include "edit/volume_render_edits.h"

namespace gridifs {

/// Replaces the whole project (an import, a combination with another IFS, recovered work), as
/// one undo step that brings the old project back.
struct ReplaceProject {
  Project project;
  void apply(Project& target) const;
  std::string label() const { return "Replace project"; }
};

using ProjectEdit = std::variant<
    // the function list and each function (edit/function_edits.h)
    AddFunction, DuplicateFunction, RemoveFunction, MoveFunction, AddFinalFunction, RemoveFinalFunction, RenameFunction,
    SetFunctionMuted, SetFunctionResolution, SetPlacement, MovePlacement, SetInterpolation, SetFunctionColor,
    AddSymmetry,
    // condensation and median sets (edit/set_edits.h)
    SetCondensationSet, SetSetShape, SetSetFile, SetSetFill, SetSetGrid, SetMedianAxis,
    // flame variations (edit/variation_edits.h)
    AddVariation, RemoveVariation, SetPostTransform,
    // the operation stack and node drags (edit/operation_edits.h)
    AddOperation, RemoveOperation, MoveOperation, DuplicateOperation, SetOperationMuted, SetOperation,
    SetOperationSelection, PlaceCenter, MoveNodes,
    // settings, camera, time (edit/settings_edits.h) and shading (edit/shading_edits.h)
    SetDisplayMode, SetSampleBudget, SetBackground, SetPalette, SetDensityEstimation, ResetFlameSettings,
    SetDensityDisplay, SetQuality, SetPaletteKeys, SetCamera, SetTime, SetAnimation, AddLight, RemoveLight,
    SetLightDirection, SetLightColor, SetLightShadows, SetFogColor, SetAperture,
    // the volume's field layers (edit/field_layer_edits.h)
    AddFieldLayer, RemoveFieldLayer, SetFieldLayer,
    // keyframes (edit/key_edits.h)
    SetKeys, RemoveKeys,
    // transitions and free-form IFS (edit/matrix_edits.h)
    SetTransitionPreset, RemoveTransitions, SetMatrixEntry, MoveControlPoint, ApplyFreeFormPreset, BackToGridIfs,
    AddControlPoint, RemoveControlPoint, MapOntoControlNet,
    // the volume ray march and the stored preview mode (edit/volume_render_edits.h)
    SetVolumeDisplay, SetTransferFunction, SetPreviewMode,
    // the construction tree (edit/construction_edits.h)
    AddConstructionLeaf, GroupConstructionNodes, SetConstructionOp, RemoveConstructionNode, ReloadConstructionLeaves,
    // any number by its parameter path (edit/parameter_edit.h)
    SetParameter,
    // live bindings and recorded takes (edit/binding_edits.h)
    AddBinding, RemoveBinding, RecordTake,
    // the whole project
    ReplaceProject>;

/// Applies `edit` to `project`. Throws ModelError as described above.
void applyEdit(Project& project, const ProjectEdit& edit);

/// The name of `edit`'s undo step ("Function weight", "Add Twist").
std::string editLabel(const ProjectEdit& edit);

}  // namespace gridifs
