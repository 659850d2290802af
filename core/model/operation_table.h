#pragma once
// The one description of every operation type: its file name, title, parameters (JSON key, type,
// valid range, widget range, label, tooltip) and its semantic rules. Project reading and writing
// (io/project_io), validation (model/validation) and the Operations panel (ui/) are loops over
// this table, so a new operation is one struct in model/operation.h, one entry in
// operation_table.cpp and one apply() overload in stack_evaluator.cpp.
//
// A parameter's default is the member initializer of its operation struct: reading starts from a
// default-constructed operation and overwrites the keys a file has.
//
// Thread-safety: the table is built once (thread-safe static) and never changes.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "base/errors.h"
#include "model/operation.h"

namespace gridifs {

/// How a parameter is stored, written and edited.
enum class ParamType {
  Number,          // double: a JSON number
  Integer,         // int: a JSON integer
  Seed,            // std::uint64_t: a non-negative JSON integer
  Vector,          // Vec3 or std::array<double, N>: an array of `components` numbers
  Choice,          // an enum: one of `choices` (JSON names in enum order)
  Expression,      // std::string: a calculator expression
  CalculatorVars,  // std::array<CalculatorVar, 3>: {"v1": {"value", "min", "max"}, ...}
  MorphPairs,      // std::vector<MorphPair>: [[from, to], ...]
  NodeMoves,       // std::vector<NodeMove>: [[i, j, k, [dx, dy, dz]], ...]
};

/// The names of a Choice parameter: `names` in the file, `labels` in the panel, both in enum order.
struct ChoiceNames {
  std::vector<const char*> names, labels;
};

/// What the table's author writes for one parameter.
struct ParamInfo {
  const char* key;               // JSON name; also the panel's probe id (type.key)
  const char* label;             // widget label
  const char* tooltip = "";      // status-line help while hovered
  double min = -limits::kMaxCoordinate, max = limits::kMaxCoordinate;  // valid values
  double sliderMin = 0.0, sliderMax = 0.0;  // a slider over this range when min < max, else a drag
  double speed = 0.005;                     // drag speed
  const char* format = "%.3f";              // number format, with the unit ("%.1f°")
  const ChoiceNames* choices = nullptr;     // Choice only
  std::size_t maxLength = limits::kMaxExpressionLength;  // Expression only
  bool placeable = false;  // Vector: the panel offers "Move to center point" (the Alt+click point)
  /// The panel greys the widget out while this returns false (omega of a linear profile).
  bool (*enabled)(const OpParams&) = nullptr;
};

/// One parameter of an operation: the author's ParamInfo plus its type and accessors, deduced from
/// the struct member by param<&Op::member>(...).
struct ParamSpec : ParamInfo {
  ParamType type = ParamType::Number;
  int components = 1;
  /// The member inside the operation's alternative; its C++ type follows from `type`
  /// (double, int, std::uint64_t, Vec3 or std::array<double, components>, std::string, ...).
  void* (*locate)(OpParams&) = nullptr;
  /// Choice only: the enum value as its index in `choices`.
  int (*choice)(const OpParams&) = nullptr;
  void (*setChoice)(OpParams&, int) = nullptr;

  template <class T> T& value(OpParams& p) const { return *static_cast<T*>(locate(p)); }
  template <class T> const T& value(const OpParams& p) const {
    return *static_cast<const T*>(locate(const_cast<OpParams&>(p)));
  }
  /// Component `c` of a Number, Integer or Vector parameter.
  double number(const OpParams& p, int c = 0) const;
  void setNumber(OpParams& p, int c, double v) const;
};

/// Builds the ParamSpec of `Member` (a pointer to a member of one OpParams alternative).
template <auto Member>
ParamSpec param(ParamInfo info);

/// One operation type.
struct OperationSpec {
  const char* type;     // the file's "type"
  const char* title;    // "Twist": the stack row, the add button, the menu
  const char* heading;  // the panel's heading, with the paper it comes from
  OpParams defaults;    // the default-constructed alternative
  std::vector<ParamSpec> params;  // in the order they are written
  bool absolute = false;          // works in absolute coordinates: the center is not used
  bool addable = true;            // offered by the add toolbar and menu (node drags are not)
  /// Rules across parameters or beyond ranges (a bend's axes, a calculator's syntax, a morph's
  /// solvability). Throws ModelError with a path relative to the operation.
  void (*rules)(const OpParams&) = nullptr;
  /// A new operation from the panel starts where the artist works (a magnet at the selection).
  void (*placeAt)(OpParams&, const Vec3& anchor) = nullptr;
  /// A one-line summary for the stack row; without one, the first two scalar parameters.
  std::string (*summary)(const OpParams&) = nullptr;
};

/// Every operation type, in OpParams variant order.
const std::vector<OperationSpec>& operationTable();
/// The entry of `params`'s alternative.
const OperationSpec& operationSpec(const OpParams& params);
/// The entry whose file name is `type`, or nullptr.
const OperationSpec* findOperation(std::string_view type);
/// "translate, rotate, ... or nodes": the file names, for error messages.
std::string operationTypeList();
/// "\"x\", \"y\" or \"z\"": a Choice's file names, for error messages.
std::string choiceList(const ChoiceNames& choices);
/// The stack row's one-line summary.
std::string operationSummary(const OpParams& params);

/// Checks one parameter against its range ("expected a number between 0 and 1000, found -1"),
/// then the operation's rules. Throws ModelError with a path relative to the operation.
void validateOperationParams(const OpParams& params);

// ---- implementation of param<> ----------------------------------------------------------------

namespace detail {
template <class T> struct MemberOf;
template <class C, class T> struct MemberOf<T C::*> {
  using Class = C;
  using Type = T;
};
template <class T> struct IsDoubleArray : std::false_type {};
template <std::size_t N> struct IsDoubleArray<std::array<double, N>> : std::true_type {
  static constexpr int size = int(N);
};
}  // namespace detail

template <auto Member>
ParamSpec param(ParamInfo info) {
  using Op = typename detail::MemberOf<decltype(Member)>::Class;
  using T = typename detail::MemberOf<decltype(Member)>::Type;
  ParamSpec s;
  static_cast<ParamInfo&>(s) = info;
  s.locate = [](OpParams& p) -> void* { return &(std::get<Op>(p).*Member); };
  if constexpr (std::is_enum_v<T>) {
    s.type = ParamType::Choice;
    s.choice = [](const OpParams& p) { return int(std::get<Op>(p).*Member); };
    s.setChoice = [](OpParams& p, int v) { std::get<Op>(p).*Member = T(v); };
  } else if constexpr (std::is_same_v<T, double>) {
    s.type = ParamType::Number;
  } else if constexpr (std::is_same_v<T, int>) {
    s.type = ParamType::Integer;
  } else if constexpr (std::is_same_v<T, std::uint64_t>) {
    s.type = ParamType::Seed;
  } else if constexpr (std::is_same_v<T, Vec3>) {
    s.type = ParamType::Vector;
    s.components = 3;
  } else if constexpr (detail::IsDoubleArray<T>::value) {
    s.type = ParamType::Vector;
    s.components = detail::IsDoubleArray<T>::size;
  } else if constexpr (std::is_same_v<T, std::string>) {
    s.type = ParamType::Expression;
  } else if constexpr (std::is_same_v<T, std::array<CalculatorVar, 3>>) {
    s.type = ParamType::CalculatorVars;
  } else if constexpr (std::is_same_v<T, std::vector<MorphPair>>) {
    s.type = ParamType::MorphPairs;
  } else if constexpr (std::is_same_v<T, std::vector<NodeMove>>) {
    s.type = ParamType::NodeMoves;
  } else {
    static_assert(sizeof(T) == 0, "no ParamType for this member type");
  }
  return s;
}

}  // namespace gridifs
