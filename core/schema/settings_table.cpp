#include "schema/settings_table.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace gridifs {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw ModelError(path, message); }

std::string show(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string integerRange(const SettingSpec& s) {
  return std::to_string(std::int64_t(s.min)) + " and " + std::to_string(std::int64_t(s.max));
}

/// A number against its range: the field's own message, "expected a number between 0 and 1,
/// found 2", or with a noun "the fog density must not be negative, found -1".
void checkNumber(const SettingSpec& s, double v, const std::string& path) {
  if (s.invalid) {
    if (!settingInRange(s, v)) fail(path, s.invalid);
    return;
  }
  if (!s.noun) {
    if (!(v >= s.min && v <= s.max)) fail(path, numberRangeMessage(s, v));
    return;
  }
  const std::string what = std::string("the ") + s.noun;
  if (!std::isfinite(v)) fail(path, what + " must be a finite number");
  if (s.min == 0.0) {
    if (v < 0.0) fail(path, what + " must not be negative, found " + show(v));
    if (v > s.max) fail(path, what + " must be at most " + show(s.max) + ", found " + show(v));
  } else if (!(v >= s.min && v <= s.max)) {
    fail(path, what + " must be between " + show(s.min) + " and " + show(s.max) + ", found " + show(v));
  }
}

void checkInteger(const SettingSpec& s, double v, const std::string& path) {
  if (s.invalid) {
    if (!settingInRange(s, v)) fail(path, s.invalid);
    return;
  }
  if (v >= s.min && v <= s.max) return;
  if (s.noun) fail(path, "expected between " + integerRange(s) + " " + s.noun + ", found " + show(v));
  fail(path, integerRangeMessage(s));
}

void checkVector(const SettingSpec& s, const Vec3& v, const std::string& path) {
  if (s.invalid) {
    for (int d = 0; d < 3; ++d)
      if (!settingInRange(s, v[d])) fail(path + "[" + std::to_string(d) + "]", s.invalid);
    return;
  }
  if (s.noun && !(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)))
    fail(path, std::string("the ") + s.noun + " must be finite");
  for (int d = 0; d < 3; ++d) {
    if (v[d] >= s.min && v[d] <= s.max) continue;
    const std::string what = s.noun ? std::string("a ") + s.noun + " component" : std::string("a number");
    fail(path + "[" + std::to_string(d) + "]",
         "expected " + what + " between " + show(s.min) + " and " + show(s.max) + ", found " + show(v[d]));
  }
}

}  // namespace

std::string numberRangeMessage(const FieldInfo& field, double v) {
  return "expected a number between " + show(field.min) + " and " + show(field.max) + ", found " + show(v);
}

std::string integerRangeMessage(const FieldInfo& field) {
  return "expected an integer between " + std::to_string(std::int64_t(field.min)) + " and " +
         std::to_string(std::int64_t(field.max));
}

bool settingInRange(const FieldInfo& s, double v) {
  return std::isfinite(v) && (s.openMin ? v > s.min : v >= s.min) && v <= s.max;
}

bool settingWritten(const SettingSpec& field, const void* group) {
  if (!field.omitDefault || !field.isDefault(group)) return true;
  return field.writtenAtDefault && field.writtenAtDefault(group);
}

std::string settingPath(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

const SettingSpec& SettingTable::field(std::string_view key) const {
  for (const SettingSpec& s : fields)
    if (key == s.key) return s;
  throw std::logic_error("no setting \"" + std::string(key) + "\" in this table");
}

void validateSettingFields(const SettingTable& table, const void* group, const std::string& path) {
  for (const SettingSpec& s : table.fields) {
    const std::string p = settingPath(path, s.key);
    switch (s.type) {
      case SettingType::Number:
        checkNumber(s, s.value<double>(group), p);
        break;
      case SettingType::Integer:
        checkInteger(s, double(s.value<int>(group)), p);
        break;
      case SettingType::Count:
        checkInteger(s, double(s.value<std::int64_t>(group)), p);
        break;
      case SettingType::OptionalNumber:
        if (const auto& v = s.value<std::optional<double>>(group)) checkNumber(s, *v, p);
        break;
      case SettingType::Vector:
        checkVector(s, s.value<Vec3>(group), p);
        break;
      case SettingType::Text: {
        const std::string& text = s.value<std::string>(group);
        if (text.size() > s.maxLength || (s.accepts && !s.accepts(text))) fail(p, s.expected);
        break;
      }
      case SettingType::Seed:
      case SettingType::Boolean:
      case SettingType::Choice:  // an enum holds only its choices
        break;
      case SettingType::CalculatorVars:
      case SettingType::MorphPairs:
      case SettingType::NodeMoves:
        throw std::logic_error(std::string("settings field ") + s.key + " has a type settings cannot hold");
    }
    if (s.rule) s.rule(group, p);
  }
  if (table.rules) table.rules(group, path);
}

}  // namespace gridifs
