#pragma once
// Reading and writing a function's flame variations in a .gridifs file (internal to io/):
// "variations" (weights by name), "variation_params" (flam3's attribute names) and "post"
// ({"rotate", "scale", "translate"} or {"matrix": 3 rows of 4}). Throws ModelError with a JSON path.
#include <nlohmann/json.hpp>
#include <string>

#include "model/function.h"

namespace gridifs::variation_io {

void readFunctionFields(const nlohmann::json& f, const std::string& path, Function& fn);
/// Adds the fields a function has (none for a function without variations or post).
void writeFunctionFields(const Function& fn, nlohmann::ordered_json& out);

}  // namespace gridifs::variation_io
