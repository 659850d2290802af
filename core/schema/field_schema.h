#pragma once
// The description of one named field of a struct: its JSON key, label, tooltip, valid range,
// slider range, number format and the other hints of the widget that edits it, plus its type and a
// typed accessor built from the pointer to the member. The operation table (schema/operation_table.h)
// and the settings tables (schema/settings_table.h) are lists of these, so the project file's
// readers and writers, validation, the panels' widgets and the keyframe tracks
// (schema/project_parameter.h) all read one description of a field.
//
// A field's default is the member initializer of its struct: reading starts from a
// default-constructed struct and overwrites the keys a file has.
//
// Thread-safety: a FieldSchema is a plain value, built once by its table and never changed.
#include <array>
#include <concepts>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "base/errors.h"
#include "base/types.h"

namespace gridifs {

/// How a field is stored, written and edited.
enum class FieldType {
  Number,             // double: a JSON number
  Integer,            // int: a JSON integer
  Count,              // std::int64_t (sample counts)
  Seed,               // std::uint64_t: a non-negative JSON integer
  Vector,             // Vec3 or std::array<double, N>: an array of `components` numbers
  Choice,             // an enum: one of `choices` (JSON names in enum order)
  Boolean,            // bool
  Text,               // std::string
  Expression = Text,  // an operation's text is a calculator expression
  OptionalNumber,     // std::optional<double>: absent (or null) until set; written only when set
  CalculatorVars,     // std::array<CalculatorVar, 3>: {"v1": {"value", "min", "max"}, ...}
  MorphPairs,         // std::vector<MorphPair>: [[from, to], ...]
  NodeMoves,          // std::vector<NodeMove>: [[i, j, k, [dx, dy, dz]], ...]
};

/// The names of a Choice field: `names` in the file, `labels` in the panel, both in enum order.
struct ChoiceNames {
  std::vector<const char*> names, labels;
};

/// "a, b or c": items joined for a message.
std::string listWithOr(const std::vector<std::string>& items);
/// "\"x\", \"y\" or \"z\"": a Choice's file names, for error messages.
std::string choiceList(const ChoiceNames& choices);
/// The index of `name` among `choices`' file names, or -1.
int choiceIndex(const ChoiceNames& choices, std::string_view name);

/// What a table's author writes for one field (designated initializers, in this order). The
/// hints a kind of table does not use keep their defaults.
struct FieldInfo {
  const char* key = nullptr;  // JSON name; with the table's name, the panel's probe id
  const char* label = "";     // the widget's label (for settings also its undo step and probe id)
  const char* tooltip = "";   // status-line help while hovered
  double min = -limits::kMaxCoordinate, max = limits::kMaxCoordinate;  // valid values
  double sliderMin = 0.0, sliderMax = 0.0;  // a slider over this range when min < max, else a drag
  double speed = 0.005;                     // drag speed
  const char* format = "%.3f";              // number format, with the unit ("%.1f°")
  bool logarithmic = false;                 // logarithmic slider
  const ChoiceNames* choices = nullptr;     // Choice only
  /// What messages call the value ("ambient term"). With a noun, reading only insists on finite
  /// numbers and validation names the meaning ("the ambient term must not be negative, found -1");
  /// without one, reading checks the range ("expected a number between 0 and 1, found 2").
  const char* noun = nullptr;
  /// Written only when it differs from the struct's default, after the fields that are always
  /// written, so files that never used it save as they always have.
  bool omitDefault = false;
  /// omitDefault only: the field is written at its default too while this returns true for the
  /// owner (a cloud layer's thickness, a shaped layer's blend), as its writer always did.
  bool (*writtenAtDefault)(const void* owner) = nullptr;
  /// Text only: the longest string; 0 takes the table's default (a name for settings, an
  /// expression for operations).
  std::size_t maxLength = 0;
  bool (*accepts)(const std::string&) = nullptr;  // Text only: the syntax check
  const char* expected = "";                      // Text only: the message when `accepts` refuses
  /// The whole message when validation finds the value out of range or not finite, for groups
  /// whose messages were written before the tables ("frames per second must be in (0, 1000]").
  const char* invalid = nullptr;
  bool openMin = false;    // the range excludes `min` (a frame rate above 0)
  bool placeable = false;  // Vector: the panel offers "Move to center point" (the Alt+click point)
  /// The panel greys the widget out while this returns false for the owner (omega of a linear
  /// profile).
  bool (*enabled)(const void* owner) = nullptr;
  /// A rule of this field beyond its range (an end not before the start), checked right after the
  /// range; throws ModelError at `path`, the field's path.
  void (*rule)(const void* owner, const std::string& path) = nullptr;
};

/// The C++ types a field may have, and the FieldType each is. Tables with types of their own (an
/// operation's calculator variables) add specializations.
template <class T>
struct FieldTypeOf;
template <FieldType Type, int Components = 1>
struct FieldTypeIs {
  static constexpr FieldType type = Type;
  static constexpr int components = Components;
};
template <>
struct FieldTypeOf<double> : FieldTypeIs<FieldType::Number> {};
template <>
struct FieldTypeOf<int> : FieldTypeIs<FieldType::Integer> {};
template <>
struct FieldTypeOf<std::int64_t> : FieldTypeIs<FieldType::Count> {};
template <>
struct FieldTypeOf<std::uint64_t> : FieldTypeIs<FieldType::Seed> {};
template <>
struct FieldTypeOf<Vec3> : FieldTypeIs<FieldType::Vector, 3> {};
template <std::size_t N>
struct FieldTypeOf<std::array<double, N>> : FieldTypeIs<FieldType::Vector, int(N)> {};
template <class T>
requires std::is_enum_v<T>
struct FieldTypeOf<T> : FieldTypeIs<FieldType::Choice> {
};
template <>
struct FieldTypeOf<bool> : FieldTypeIs<FieldType::Boolean> {};
template <>
struct FieldTypeOf<std::string> : FieldTypeIs<FieldType::Text> {};
template <>
struct FieldTypeOf<std::optional<double>> : FieldTypeIs<FieldType::OptionalNumber> {};

/// One field: the author's FieldInfo plus its type and accessors, deduced from the pointer to the
/// member by fieldSchema<&Struct::member>(...). An accessor takes the field's owner: the struct
/// itself, or what the table reaches the struct through (an operation's OpParams), as a pointer
/// or a reference.
struct FieldSchema : FieldInfo {
  FieldType type = FieldType::Number;
  int components = 1;
  /// The member inside `owner`; its C++ type follows from `type` (double, int, Vec3, ...).
  void* (*locate)(void* owner) = nullptr;
  /// Whether the member equals its value in a default-constructed struct.
  bool (*isDefault)(const void* owner) = nullptr;
  /// Choice only: the enum value as its index in `choices`, and back.
  int (*choiceOf)(const void* owner) = nullptr;
  void (*setChoiceOf)(void* owner, int index) = nullptr;

  template <class T>
  T& value(void* owner) const {
    return *static_cast<T*>(locate(owner));
  }
  template <class T>
  const T& value(const void* owner) const {
    return *static_cast<const T*>(locate(const_cast<void*>(owner)));
  }
  template <class T, class Owner>
  requires(!std::is_pointer_v<Owner>) T& value(Owner& owner) const { return value<T>(static_cast<void*>(&owner)); }
  template <class T, class Owner>
  requires(!std::is_pointer_v<Owner>) const T& value(const Owner& owner) const {
    return value<T>(static_cast<const void*>(&owner));
  }

  /// Component `c` of a Number, Integer, Count or Vector field as a double (an unset
  /// OptionalNumber reads 0; other types read 0).
  double number(const void* owner, int c = 0) const;
  /// The settings' former number(group, fallback): a component index is an int, so a double
  /// there is a mistake the compiler should name.
  double number(const void* owner, double fallback) const = delete;
  /// Sets component `c` of a Number, Integer, Count, OptionalNumber or Vector field (integers are
  /// rounded). Throws std::logic_error for other types (a programming error).
  void setNumber(void* owner, int c, double value) const;
  void setNumber(void* owner, double value) const { setNumber(owner, 0, value); }

  template <class Owner>
  requires(!std::is_pointer_v<Owner>) double number(const Owner& owner, int c = 0) const {
    return number(static_cast<const void*>(&owner), c);
  }
  template <class Owner>
  requires(!std::is_pointer_v<Owner>) void setNumber(Owner& owner, int c, double value) const {
    setNumber(static_cast<void*>(&owner), c, value);
  }

  /// Choice only: the enum value as its index in `choices`, and back.
  template <class Owner>
  int choice(const Owner& owner) const {
    return choiceOf(address(owner));
  }
  template <class Owner>
  void setChoice(Owner& owner, int index) const {
    setChoiceOf(address(owner), index);
  }

 private:
  template <class Owner>
  static auto address(Owner& owner) {
    if constexpr (std::is_pointer_v<std::remove_const_t<Owner>>)
      return owner;
    else
      return &owner;
  }
};

namespace detail {
template <class T>
struct MemberOf;
template <class C, class T>
struct MemberOf<T C::*> {
  using Class = C;
  using Type = T;
};
/// The owner is the struct itself.
template <class Struct>
Struct* ownStruct(void* owner) {
  return static_cast<Struct*>(owner);
}
}  // namespace detail

/// Builds the FieldSchema of `Member` (a pointer to a data member of a struct). `Reach` finds the
/// struct in the owner the accessors are given: by default the owner is the struct itself.
template <auto Member, auto Reach = &detail::ownStruct<typename detail::MemberOf<decltype(Member)>::Class>>
FieldSchema fieldSchema(const FieldInfo& info) {
  using Struct = typename detail::MemberOf<decltype(Member)>::Class;
  using T = typename detail::MemberOf<decltype(Member)>::Type;
  static_assert(
      requires { FieldTypeOf<T>::type; }, "no FieldType for this member type");
  static_assert(std::is_same_v<decltype(Reach(nullptr)), Struct*>, "Reach must find the member's struct");
  FieldSchema s;
  static_cast<FieldInfo&>(s) = info;
  s.type = FieldTypeOf<T>::type;
  s.components = FieldTypeOf<T>::components;
  s.locate = [](void* owner) -> void* { return &(Reach(owner)->*Member); };
  s.isDefault = [](const void* owner) { return Reach(const_cast<void*>(owner))->*Member == Struct{}.*Member; };
  if constexpr (std::is_enum_v<T>) {
    s.choiceOf = [](const void* owner) { return int(Reach(const_cast<void*>(owner))->*Member); };
    s.setChoiceOf = [](void* owner, int index) { Reach(owner)->*Member = T(index); };
  }
  return s;
}

}  // namespace gridifs
