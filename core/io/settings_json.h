#pragma once
// A settings group (schema/settings_table.h) in the project file: reading loops over the group's
// table with JSON-path errors, writing emits its fields in table order.
//
// Thread-safety: pure functions.
#include <nlohmann/json.hpp>
#include <string>

#include "schema/settings_table.h"

namespace gridifs {

/// Reads the fields of `table` that `object` has into `group` (absent keys keep their values).
/// Fields without a noun are range-checked here; fields with one only need finite numbers, and
/// validateSettingFields names their meaning afterwards. Throws ModelError with a path under `path`.
void readSettingFields(const SettingTable& table, const nlohmann::json& object, const std::string& path, void* group);
/// Appends one field of `group` to `object` (an optional number only when set), for writers whose
/// keys interleave with others.
void writeSettingField(const SettingSpec& field, const void* group, nlohmann::ordered_json& object);
/// Appends the fields of `group` to `object` in table order, those written only when changed last.
void writeSettingFields(const SettingTable& table, const void* group, nlohmann::ordered_json& object);

/// `object` (which must be a JSON object) read over `group`'s defaults, then validated.
template <class Group>
Group readSettings(const SettingTableOf<Group>& table, const nlohmann::json& object, const std::string& path,
                   Group group = Group{}) {
  readSettingFields(table, object, path, &group);
  validateSettings(table, group, path);
  return group;
}

template <class Group>
nlohmann::ordered_json writeSettings(const SettingTableOf<Group>& table, const Group& group) {
  nlohmann::ordered_json object = nlohmann::ordered_json::object();
  writeSettingFields(table, &group, object);
  return object;
}

}  // namespace gridifs
