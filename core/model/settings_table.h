#pragma once
// The one description of a settings group ("render", "render.flame", "render.shading", ...): each
// field's JSON key, type, valid range, slider range, number format, label and tooltip. Project
// reading and writing (io/settings_json), validation (validateSettings) and the panels' sliders
// (ui/setting_slider) are loops over or look-ups in these tables, so a new setting is one member
// with its default plus one table entry (model/settings_tables.cpp).
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

namespace gridifs {

/// How a setting is stored, written and edited.
enum class SettingType {
  Number,          // double
  Integer,         // int
  Count,           // std::int64_t (sample counts)
  Seed,            // std::uint64_t: any non-negative JSON integer (in [min, max] with SettingWords::IntegerRange)
  Vector,          // Vec3: an array of 3 numbers, each in [min, max] (a colour: [0, 1])
  Boolean,         // bool
  Text,            // std::string, checked by `accepts`
  OptionalNumber,  // std::optional<double>: absent (or null) until set; written only when set
};

/// What a table's author writes for one setting.
struct SettingInfo {
  const char* key;           // JSON name
  const char* label = "";    // the panel's label, its undo step and probe id ("Gamma threshold")
  const char* tooltip = "";  // status-line help while hovered
  double min = -limits::kMaxCoordinate, max = limits::kMaxCoordinate;  // valid values
  double sliderMin = 0.0, sliderMax = 0.0;                             // the panel's slider range
  const char* format = "%.3f";                                         // slider text, with the unit
  bool logarithmic = false;                                            // logarithmic slider
  /// What messages call the value ("ambient term"). With a noun, reading only insists on finite
  /// numbers and validation names the meaning ("the ambient term must not be negative, found -1");
  /// without one, reading checks the range ("expected a number between 0 and 1, found 2").
  const char* noun = nullptr;
  /// Written only when it differs from the group's default, after the fields that are always
  /// written, so files that never used it save as they always have.
  bool omitDefault = false;
  std::size_t maxLength = limits::kMaxNameLength;  // Text only
  bool (*accepts)(const std::string&) = nullptr;   // Text only: the syntax check
  const char* expected = "";                       // Text only: the message when `accepts` refuses
  /// The whole message when validation finds the value out of range or not finite, for groups
  /// whose messages were written before the tables ("frames per second must be in (0, 1000]").
  const char* invalid = nullptr;
  bool openMin = false;  // the range excludes `min` (a frame rate above 0)
  /// A rule of this field beyond its range (an end not before the start), checked right after the
  /// range; throws ModelError at `path`, the field's path.
  void (*rule)(const void* group, const std::string& path) = nullptr;
};

/// One setting: the author's SettingInfo plus its type and accessors, deduced from the struct
/// member by setting<&Group::member>(...).
struct SettingSpec : SettingInfo {
  SettingType type = SettingType::Number;
  void* (*locate)(void* group) = nullptr;
  bool (*isDefault)(const void* group) = nullptr;

  template <class T>
  T& value(void* group) const {
    return *static_cast<T*>(locate(group));
  }
  template <class T>
  const T& value(const void* group) const {
    return *static_cast<const T*>(locate(const_cast<void*>(group)));
  }
  /// A Number, Integer or Count field as a double (an unset OptionalNumber reads `fallback`).
  double number(const void* group, double fallback = 0.0) const;
  /// Sets a Number, Integer, Count or OptionalNumber field (integers are rounded).
  void setNumber(void* group, double value) const;
};

/// Builds the SettingSpec of `Member` (a pointer to a data member of a settings group).
template <auto Member>
SettingSpec setting(SettingInfo info);

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

/// "path.key", or "key" when `path` is empty.
std::string settingPath(const std::string& path, std::string_view key);

// ---- implementation of setting<> -------------------------------------------------------------

namespace detail {
template <class T>
struct SettingMember;
template <class C, class T>
struct SettingMember<T C::*> {
  using Group = C;
  using Type = T;
};
}  // namespace detail

template <auto Member>
SettingSpec setting(SettingInfo info) {
  using Group = typename detail::SettingMember<decltype(Member)>::Group;
  using T = typename detail::SettingMember<decltype(Member)>::Type;
  SettingSpec s;
  static_cast<SettingInfo&>(s) = info;
  s.locate = [](void* g) -> void* { return &(static_cast<Group*>(g)->*Member); };
  s.isDefault = [](const void* g) { return static_cast<const Group*>(g)->*Member == Group{}.*Member; };
  if constexpr (std::is_same_v<T, double>) {
    s.type = SettingType::Number;
  } else if constexpr (std::is_same_v<T, int>) {
    s.type = SettingType::Integer;
  } else if constexpr (std::is_same_v<T, std::int64_t>) {
    s.type = SettingType::Count;
  } else if constexpr (std::is_same_v<T, std::uint64_t>) {
    s.type = SettingType::Seed;
  } else if constexpr (std::is_same_v<T, Vec3>) {
    s.type = SettingType::Vector;
  } else if constexpr (std::is_same_v<T, bool>) {
    s.type = SettingType::Boolean;
  } else if constexpr (std::is_same_v<T, std::string>) {
    s.type = SettingType::Text;
  } else if constexpr (std::is_same_v<T, std::optional<double>>) {
    s.type = SettingType::OptionalNumber;
  } else {
    static_assert(sizeof(T) == 0, "no SettingType for this member type");
  }
  return s;
}

}  // namespace gridifs
