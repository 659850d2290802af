#pragma once
// The slider of one number in a settings table (schema/settings_tables.h): its range, format,
// logarithmic flag, label (the undo step and the probe id) and tooltip all come from the table,
// so the Tone popup and the Shading panel draw what reading and validation accept.
#include <string>

#include "schema/settings_table.h"
#include "ui/base/edit_queue.h"
#include "ui/base/modeller_state.h"

namespace gridifs::ui {

/// The clamped ImGui slider of `spec` over [min, max] (a Number, Integer or Count field), or a
/// drag over the field's valid range when min ≥ max; `id` is the widget's label ("##ambient" to
/// hide it). Returns whether `value` changed.
bool settingSliderWidget(const char* id, const SettingSpec& spec, double& value, double min, double max);

/// A drag of `spec`'s field of `owner` (a Number or a Vector) over the table's slider range, or
/// its valid range when the table gives none, with the table's label, speed and format; for
/// panels that edit a local copy and commit it whole. Returns whether the value changed.
bool settingDrag(const SettingSpec& spec, void* owner);

/// Where the slider stands and what it edits.
struct SettingSliderPlace {
  const char* id = nullptr;     // the widget's label; nullptr: the table's label, shown beside it
  std::string probe;            // the probe prefix: "flame" records "flame.Brightness"
  double min = 0.0, max = 0.0;  // the slider's range when min < max; else the table's
};

/// A slider that edits one number field of a settings group as one gesture: a SetParameter of
/// `group` + "." + the field's key ("render.shading.lights[1]" + ".intensity"), one undo step
/// named by the table's label, its tooltip on hover. `value` is the field's current value.
void settingSlider(ModellerState& state, EditQueue& edits, const SettingSpec& spec, double value,
                   const std::string& group, const SettingSliderPlace& place);

/// The same for field `key` of `table`, read from `current`, the group at path `group`.
template <class Group>
void settingSlider(ModellerState& state, EditQueue& edits, const SettingTableOf<Group>& table, const std::string& group,
                   const char* key, const Group& current, const SettingSliderPlace& place) {
  const SettingSpec& spec = table.field(key);
  settingSlider(state, edits, spec, spec.number(&current), group, place);
}

}  // namespace gridifs::ui
