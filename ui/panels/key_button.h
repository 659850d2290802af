#pragma once
// The key button beside a numeric parameter: sets or removes a keyframe at the current time.
#include <string>
#include <vector>

#include "edit/key_edits.h"
#include "ui/base/edit_queue.h"
#include "ui/base/modeller_state.h"

namespace gridifs::ui {

/// How a parameter stands on the timeline at the current time.
enum class KeyState { None, Animated, KeyHere };  // not animated; animated, between keys; a key now

/// The state of the parameter at `path` (a vector of `components` numbers names its components
/// `path[0]`, `path[1]`, …): KeyHere only when every component has a key at the current time.
KeyState keyStateOf(const Project& project, const std::string& path, int components);
KeyState keyStateOf(const Project& project, const std::vector<KeyedNumber>& numbers);

/// A small diamond drawn before the parameter's widget (call it, then the widget): filled on a
/// key, hollow when animated between keys, faint when not animated. A click sets a key at the
/// current time holding `values` (one per component), or removes the key there; one undo step.
/// Editing an animated parameter also keys it (the Document's rule, schema/project_time.h).
void keyButton(ModellerState& state, EditQueue& edits, const std::string& path, const double* values,
               int components = 1);

/// One button for several numbers keyed together (the camera: yaw, pitch, distance, target);
/// `id` names it in the probe ("key.<id>").
void keyButton(ModellerState& state, EditQueue& edits, const std::string& id, const std::vector<KeyedNumber>& numbers);

}  // namespace gridifs::ui
