#pragma once
// One parameter of an operation, read from and written to JSON as the operation table describes
// it (internal to io/). Operations in a function's stack use it, and so does any other block that
// carries an operation's parameters (the volume's density field).
// Throws ModelError with a JSON path.
#include <nlohmann/json.hpp>
#include <string>

#include "schema/operation_table.h"

namespace gridifs::operation_json {

/// Reads `spec`'s key of `object` (at `objectPath`) into `params`; an absent key keeps the value.
void readParam(const ParamSpec& spec, const nlohmann::json& object, const std::string& objectPath, OpParams& params);

/// `spec`'s value in `params` as JSON.
nlohmann::ordered_json writeParam(const ParamSpec& spec, const OpParams& params);

}  // namespace gridifs::operation_json
