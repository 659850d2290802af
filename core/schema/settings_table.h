#pragma once
// The one description of a settings group ("render", "render.flame", "render.shading", ...): each
// field is a FieldSchema (schema/field_schema.h) whose owner is the group: its JSON key, type,
// valid range, slider range, number format, label and tooltip. Project reading and writing
// (io/settings_json), validation (validateSettings), keyframe tracks (model/project_parameter)
// and the panels' sliders (ui/panels/setting_slider) are loops over or look-ups in these tables, so a
// new setting is one member with its default plus one table entry (schema/settings_tables.cpp).
//
// A field's default is the member initializer of its group struct: reading starts from a
// default-constructed group and overwrites the keys a file has.
//
// Thread-safety: the tables are built once (thread-safe statics) and never change.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "base/errors.h"
#include "base/types.h"
#include "schema/field_schema.h"

namespace gridifs {

/// How a setting is stored, written and edited: a FieldType (schema/field_schema.h).
using SettingType = FieldType;
/// What a table's author writes for one setting (schema/field_schema.h).
using SettingInfo = FieldInfo;
/// One setting: a FieldSchema whose owner is the settings group.
using SettingSpec = FieldSchema;

/// Builds the SettingSpec of `Member` (a pointer to a data member of a settings group). A Text
/// field without a maxLength may be a name long.
template <auto Member>
SettingSpec setting(SettingInfo info) {
  if (info.maxLength == 0) info.maxLength = limits::kMaxNameLength;
  return fieldSchema<Member>(info);
}

/// How reading words a value of the wrong type or out of range. Groups that had readers of their
/// own before the tables keep those readers' words, so what a bad file is told stays the same.
enum class SettingWords {
  Standard,      // io/json_read: "expected a number, found a string"; ranges checked while reading
  FiniteOnly,    // numbers: "expected a number", "expected a finite number", any finite magnitude,
                 // ranges left to validation; booleans: "expected true or false"
  IntegerRange,  // integers, counts and seeds: any bad value (wrong type, fraction, out of range)
                 // is "expected an integer between MIN and MAX"
};

/// The fields of one settings group, in the order they are read, validated and written (fields
/// with omitDefault last), plus its rules across fields.
struct SettingTable {
  std::vector<SettingSpec> fields;
  /// Rules across fields or beyond ranges (an aperture needs a focus distance). Throws ModelError
  /// with a path under `path`.
  void (*rules)(const void* group, const std::string& path) = nullptr;
  SettingWords words = SettingWords::Standard;
  /// The field whose key is `key`; throws std::logic_error when there is none (a programming error).
  const SettingSpec& field(std::string_view key) const;
};

/// A table whose fields are members of `Group`: the type keeps a table and its group together.
template <class Group>
struct SettingTableOf : SettingTable {};

/// Checks every field against its range, then the table's rules. Throws ModelError whose path is
/// `path` + "." + the key ("render.flame.gamma", "render.shading.fog.color[1]").
void validateSettingFields(const SettingTable& table, const void* group, const std::string& path);
template <class Group>
void validateSettings(const SettingTableOf<Group>& table, const Group& group, const std::string& path) {
  validateSettingFields(table, &group, path);
}

/// Whether `v` is finite and in `field`'s valid range (above `min` when the range is open there).
bool settingInRange(const FieldInfo& field, double v);

/// "expected a number between MIN and MAX, found V": what the file readers, the parameter paths
/// and validation say of a number outside a field's range.
std::string numberRangeMessage(const FieldInfo& field, double v);
/// "expected an integer between MIN and MAX": the same for a whole number.
std::string integerRangeMessage(const FieldInfo& field);

/// Whether a writer puts `field` of `group` in the file: always, unless it is omitDefault and at
/// its default (and its writtenAtDefault rule, if any, does not hold).
bool settingWritten(const SettingSpec& field, const void* group);

/// "path.key", or "key" when `path` is empty.
std::string settingPath(const std::string& path, std::string_view key);

}  // namespace gridifs
