#pragma once
// Reading and writing the free-form fields of a .gridifs file (internal to io/): the project's
// "space" and a function's "kind", "matrix" and "interpolation". Kept apart from project_io.cpp so
// the grid format and the free-form one evolve independently. Throws ModelError with a JSON path.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "model/project.h"

namespace gridifs::free_form_io {

/// "space" of the root object, if present.
std::optional<FreeFormSpace> readSpace(const nlohmann::json& root);

/// "kind", "matrix" and "interpolation" of a function object into `fn`. A matrix function may
/// carry none of the grid fields (resolution, placement, ops).
void readFunctionFields(const nlohmann::json& f, const std::string& path, Function& fn);

/// Whether writeFunction should write only the fields of a matrix function.
inline bool isMatrixFunction(const Function& fn) { return fn.kind == FunctionKind::Matrix; }

/// The object of a matrix function (name, kind, matrix, weight, color, palette_index, color_speed, muted).
nlohmann::ordered_json writeMatrixFunction(const Function& fn);

/// Adds "interpolation" to a grid function's object when it is not the default.
void writeGridFunctionFields(const Function& fn, nlohmann::ordered_json& out);

/// Adds "space" to the root object when the project has one.
void writeSpace(const Project& project, nlohmann::ordered_json& root);

}  // namespace gridifs::free_form_io
