#pragma once
// Reading JSON values with errors that name their JSON path ("render.flame.gamma: expected a
// number between 0.05 and 100, found 0"): the primitives every project reader shares.
//
// Thread-safety: pure functions.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "base/errors.h"
#include "base/types.h"

namespace gridifs::json_read {

using json = nlohmann::json;

[[noreturn]] void fail(const std::string& path, const std::string& message);
/// "path.key", or "key" when `path` is empty.
std::string join(const std::string& path, const std::string& key);
/// "path[index]".
std::string item(const std::string& path, std::size_t index);
/// "a number", "an object", ... for messages.
const char* typeName(const json& j);

void requireObject(const json& j, const std::string& path);
/// A number in [lo, hi]: "expected a number between lo and hi, found v".
double readNumber(const json& j, const std::string& path, double lo, double hi);
/// Any finite number of magnitude at most limits::kMaxCoordinate (ranges are checked later by a
/// validation that names the value's meaning).
double readFinite(const json& j, const std::string& path);
/// An integer in [lo, hi] (2.0 counts, 2.5 does not).
std::int64_t readInteger(const json& j, const std::string& path, std::int64_t lo, std::int64_t hi);
/// Any non-negative integer (random seeds).
std::uint64_t readSeed(const json& j, const std::string& path);
bool readBoolean(const json& j, const std::string& path);
std::string readString(const json& j, const std::string& path, std::size_t maxLength);
/// An array of 3 numbers, each in [lo, hi].
Vec3 readVec3(const json& j, const std::string& path, double lo, double hi);

}  // namespace gridifs::json_read
