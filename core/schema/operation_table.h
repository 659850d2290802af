#pragma once
// The one description of every operation type: its file name, title, parameters (each a
// FieldSchema, schema/field_schema.h: JSON key, type, valid range, widget range, label, tooltip)
// and its semantic rules. Project reading and writing (io/project_io), validation
// (model/validation), keyframe tracks (model/project_parameter) and the Operations panel (ui/) are
// loops over this table, so a new operation is one struct in model/operation.h, one row in
// operation_table.cpp (which checks at compile time that its rows follow OpParams) and one
// apply() overload in stack_evaluator.cpp.
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
#include "schema/field_schema.h"

namespace gridifs {

/// How a parameter is stored, written and edited: a FieldType (schema/field_schema.h).
using ParamType = FieldType;
/// What the table's author writes for one parameter (schema/field_schema.h); its key is also the
/// panel's probe id (type.key).
using ParamInfo = FieldInfo;
/// One parameter of an operation: a FieldSchema whose owner is the OpParams variant holding the
/// operation.
using ParamSpec = FieldSchema;

template <>
struct FieldTypeOf<std::array<CalculatorVar, 3>> : FieldTypeIs<FieldType::CalculatorVars> {};
template <>
struct FieldTypeOf<std::vector<MorphPair>> : FieldTypeIs<FieldType::MorphPairs> {};
template <>
struct FieldTypeOf<std::vector<NodeMove>> : FieldTypeIs<FieldType::NodeMoves> {};

namespace detail {
/// The operation `Op` inside the OpParams variant that holds it.
template <class Op>
Op* alternative(void* params) {
  return &std::get<Op>(*static_cast<OpParams*>(params));
}
}  // namespace detail

/// Builds the ParamSpec of `Member` (a pointer to a member of one OpParams alternative). An
/// Expression without a maxLength may be an expression long.
template <auto Member>
ParamSpec param(ParamInfo info) {
  using Op = typename detail::MemberOf<decltype(Member)>::Class;
  if (info.maxLength == 0) info.maxLength = limits::kMaxExpressionLength;
  return fieldSchema<Member, &detail::alternative<Op>>(info);
}

/// One operation type.
struct OperationSpec {
  const char* type;               // the file's "type"
  const char* title;              // "Twist": the stack row, the add button, the menu
  const char* heading;            // the panel's heading, with the paper it comes from
  OpParams defaults;              // the default-constructed alternative
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
/// The file-format name of each alternative, in variant order ("translate", ...).
const char* opTypeName(const OpParams& params);
/// The entry whose file name is `type`, or nullptr.
const OperationSpec* findOperation(std::string_view type);
/// "translate, rotate, ... or nodes": the file names, for error messages.
std::string operationTypeList();
/// The stack row's one-line summary.
std::string operationSummary(const OpParams& params);

/// Checks one parameter against its range ("expected a number between 0 and 1000, found -1"),
/// then the operation's rules. Throws ModelError with a path relative to the operation.
void validateOperationParams(const OpParams& params);

}  // namespace gridifs
