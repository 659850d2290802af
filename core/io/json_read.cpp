#include "io/json_read.h"

#include <cmath>
#include <sstream>

namespace gridifs::json_read {

void fail(const std::string& path, const std::string& message) { throw ModelError(path, message); }

std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }
std::string item(const std::string& path, std::size_t index) { return path + "[" + std::to_string(index) + "]"; }

const char* typeName(const json& j) {
  switch (j.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::object:
      return "an object";
    case json::value_t::array:
      return "an array";
    case json::value_t::string:
      return "a string";
    case json::value_t::boolean:
      return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float:
      return "a number";
    default:
      return "an unsupported value";
  }
}

void requireObject(const json& j, const std::string& path) {
  if (!j.is_object()) fail(path.empty() ? "(root)" : path, std::string("expected an object, found ") + typeName(j));
}

double readNumber(const json& j, const std::string& path, double lo, double hi) {
  if (!j.is_number()) fail(path, std::string("expected a number, found ") + typeName(j));
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(path, "expected a finite number");
  if (v < lo || v > hi) {
    std::ostringstream s;
    s << "expected a number between " << lo << " and " << hi << ", found " << v;
    fail(path, s.str());
  }
  return v;
}

double readFinite(const json& j, const std::string& path) {
  if (!j.is_number()) fail(path, std::string("expected a number, found ") + typeName(j));
  const double v = j.get<double>();
  if (!std::isfinite(v) || std::abs(v) > limits::kMaxCoordinate) fail(path, "expected a finite number");
  return v;
}

std::int64_t readInteger(const json& j, const std::string& path, std::int64_t lo, std::int64_t hi) {
  const std::string range = "expected an integer between " + std::to_string(lo) + " and " + std::to_string(hi);
  if (!j.is_number()) fail(path, std::string("expected an integer, found ") + typeName(j));
  if (j.is_number_float()) {
    const double v = j.get<double>();
    if (!std::isfinite(v) || v != std::floor(v)) fail(path, "expected an integer");
    if (v < double(lo) || v > double(hi)) fail(path, range);
    return std::int64_t(v);
  }
  if (j.is_number_unsigned() && j.get<std::uint64_t>() > std::uint64_t(INT64_MAX)) fail(path, range);
  const std::int64_t v = j.get<std::int64_t>();
  if (v < lo || v > hi) fail(path, range);
  return v;
}

std::uint64_t readSeed(const json& j, const std::string& path) {
  if (j.is_number_unsigned()) return j.get<std::uint64_t>();
  if (j.is_number_integer() && j.get<std::int64_t>() >= 0) return std::uint64_t(j.get<std::int64_t>());
  if (j.is_number_float()) {
    const double v = j.get<double>();
    if (std::isfinite(v) && v >= 0 && v == std::floor(v) && v < 1.8e19) return std::uint64_t(v);
  }
  fail(path, std::string("expected a non-negative integer, found ") + typeName(j));
}

bool readBoolean(const json& j, const std::string& path) {
  if (!j.is_boolean()) fail(path, std::string("expected true or false, found ") + typeName(j));
  return j.get<bool>();
}

std::string readString(const json& j, const std::string& path, std::size_t maxLength) {
  if (!j.is_string()) fail(path, std::string("expected a string, found ") + typeName(j));
  const std::string& s = j.get_ref<const std::string&>();
  if (s.size() > maxLength) fail(path, "the string is longer than " + std::to_string(maxLength) + " characters");
  return s;
}

Vec3 readVec3(const json& j, const std::string& path, double lo, double hi) {
  if (!j.is_array() || j.size() != 3) fail(path, "expected an array of 3 numbers");
  return {readNumber(j[0], item(path, 0), lo, hi), readNumber(j[1], item(path, 1), lo, hi),
          readNumber(j[2], item(path, 2), lo, hi)};
}

}  // namespace gridifs::json_read
