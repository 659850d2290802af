#pragma once
// The slider of one number in a settings table (model/settings_tables.h): its range, format,
// logarithmic flag, label (the undo step and the probe id) and tooltip all come from the table,
// so the Tone popup and the Shading panel draw what reading and validation accept.
#include <string>

#include "edit/settings_edits.h"
#include "model/settings_table.h"
#include "ui/base/edit_queue.h"
#include "ui/base/modeller_state.h"

namespace gridifs::ui {

/// The clamped ImGui slider of `spec` over [min, max] (a Number, Integer or Count field); `id` is
/// the widget's label ("##ambient" to hide it). Returns whether `value` changed.
bool settingSliderWidget(const char* id, const SettingSpec& spec, double& value, double min, double max);

/// Where the slider stands and what it edits.
struct SettingSliderPlace {
  const char* id = nullptr;     // the widget's label; nullptr: the table's label, shown beside it
  std::string probe;            // the probe prefix: "flame" records "flame.Brightness"
  double min = 0.0, max = 0.0;  // the slider's range when min < max; else the table's
};

/// A slider that edits one number field of a settings group as one gesture (one undo step named
/// by the table's label; its tooltip on hover). `value` is the field's current value; `group`
/// (and `light`, for a light's field) says which group of the project the edit changes.
void settingSlider(ModellerState& state, EditQueue& edits, const SettingSpec& spec, double value, SettingGroup group,
                   const SettingSliderPlace& place, std::size_t light = 0);

/// The same for field `key` of `group`'s table, read from `current`.
template <class Group>
void settingSlider(ModellerState& state, EditQueue& edits, SettingGroup group, const char* key, const Group& current,
                   const SettingSliderPlace& place) {
  const SettingSpec& spec = settingTable(group).field(key);
  settingSlider(state, edits, spec, spec.number(&current), group, place);
}

}  // namespace gridifs::ui
