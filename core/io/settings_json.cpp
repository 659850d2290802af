#include "io/settings_json.h"

#include <cmath>
#include <stdexcept>

#include "io/json_read.h"

namespace gridifs {
namespace {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;
using namespace json_read;

// ---- SettingWords::FiniteOnly -----------------------------------------------------------------

double readAnyFinite(const json& j, const std::string& path) {
  if (!j.is_number()) fail(path, "expected a number");
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(path, "expected a finite number");
  return v;
}

// ---- SettingWords::IntegerRange ---------------------------------------------------------------

/// A range bound as an integer (a table's INT64_MAX is stored as the double 2^63).
std::int64_t integerBound(double v) {
  if (v >= 0x1p63) return INT64_MAX;
  if (v <= -0x1p63) return INT64_MIN;
  return std::int64_t(v);
}

/// Throws "expected an integer between MIN and MAX" unless `j` is a whole number in the range.
void requireIntegerInRange(const SettingSpec& s, const json& j, const std::string& path) {
  const std::int64_t lo = integerBound(s.min), hi = integerBound(s.max);
  const std::string range = "expected an integer between " + std::to_string(lo) + " and " + std::to_string(hi);
  if (!j.is_number()) fail(path, range);
  const double v = j.get<double>();
  if (!std::isfinite(v) || v != std::floor(v) || v < double(lo) || v > double(hi)) fail(path, range);
}

std::int64_t readIntegerInRange(const SettingSpec& s, const json& j, const std::string& path) {
  requireIntegerInRange(s, j, path);
  return j.is_number_float() ? std::int64_t(j.get<double>()) : j.get<std::int64_t>();
}

std::uint64_t readSeedInRange(const SettingSpec& s, const json& j, const std::string& path) {
  requireIntegerInRange(s, j, path);
  return j.is_number_float() ? std::uint64_t(j.get<double>()) : j.get<std::uint64_t>();
}

// ---- by the table's words ---------------------------------------------------------------------

double readSettingNumber(SettingWords words, const SettingSpec& s, const json& j, const std::string& path) {
  if (words == SettingWords::FiniteOnly) return readAnyFinite(j, path);
  if (s.noun) return readFinite(j, path);
  if (s.invalid) {
    // A field with a message of its own says it for any value out of its range, as validation does.
    const double v = readFinite(j, path);
    if (!settingInRange(s, v)) fail(path, s.invalid);
    return v;
  }
  return readNumber(j, path, s.min, s.max);
}

double readSettingInteger(SettingWords words, const SettingSpec& s, const json& j, const std::string& path) {
  if (words == SettingWords::IntegerRange) return double(readIntegerInRange(s, j, path));
  if (!s.noun) return double(readInteger(j, path, std::int64_t(s.min), std::int64_t(s.max)));
  const double v = readFinite(j, path);
  if (v != std::floor(v) || v < s.min || v > s.max)
    fail(path, "expected an integer between " + std::to_string(std::int64_t(s.min)) + " and " +
                   std::to_string(std::int64_t(s.max)));
  return v;
}

std::uint64_t readSettingSeed(SettingWords words, const SettingSpec& s, const json& j, const std::string& path) {
  return words == SettingWords::IntegerRange ? readSeedInRange(s, j, path) : readSeed(j, path);
}

bool readSettingBoolean(SettingWords words, const json& j, const std::string& path) {
  if (words == SettingWords::FiniteOnly && !j.is_boolean()) fail(path, "expected true or false");
  return readBoolean(j, path);
}

}  // namespace

void readSettingFields(const SettingTable& table, const json& object, const std::string& path, void* group) {
  requireObject(object, path);
  const SettingWords words = table.words;
  for (const SettingSpec& s : table.fields) {
    auto it = object.find(s.key);
    if (it == object.end()) continue;
    const std::string p = join(path, s.key);
    switch (s.type) {
      case SettingType::Number:
        s.value<double>(group) = readSettingNumber(words, s, *it, p);
        break;
      case SettingType::Integer:
        s.value<int>(group) = int(readSettingInteger(words, s, *it, p));
        break;
      case SettingType::Count:
        s.value<std::int64_t>(group) = std::int64_t(readSettingInteger(words, s, *it, p));
        break;
      case SettingType::Seed:
        s.value<std::uint64_t>(group) = readSettingSeed(words, s, *it, p);
        break;
      case SettingType::Vector: {
        if (!it->is_array() || it->size() != 3) fail(p, "expected an array of 3 numbers");
        Vec3& v = s.value<Vec3>(group);
        for (int d = 0; d < 3; ++d) v[d] = readSettingNumber(words, s, (*it)[std::size_t(d)], item(p, std::size_t(d)));
        break;
      }
      case SettingType::Boolean:
        s.value<bool>(group) = readSettingBoolean(words, *it, p);
        break;
      case SettingType::Text: {
        std::string text = readString(*it, p, s.maxLength);
        if (s.accepts && !s.accepts(text)) fail(p, s.expected);
        s.value<std::string>(group) = std::move(text);
        break;
      }
      case SettingType::OptionalNumber:
        if (!it->is_null()) s.value<std::optional<double>>(group) = readSettingNumber(words, s, *it, p);
        break;
      case SettingType::Choice: {
        const int index = choiceIndex(*s.choices, readString(*it, p, 64));
        if (index < 0) fail(p, "expected " + choiceList(*s.choices));
        s.setChoiceOf(group, index);
        break;
      }
      case SettingType::CalculatorVars:
      case SettingType::MorphPairs:
      case SettingType::NodeMoves:
        throw std::logic_error(std::string("settings field ") + s.key + " has a type settings cannot hold");
    }
  }
}

void writeSettingField(const SettingSpec& s, const void* group, ordered_json& object) {
  switch (s.type) {
    case SettingType::Number:
      object[s.key] = s.value<double>(group);
      break;
    case SettingType::Integer:
      object[s.key] = s.value<int>(group);
      break;
    case SettingType::Count:
      object[s.key] = s.value<std::int64_t>(group);
      break;
    case SettingType::Seed:
      object[s.key] = s.value<std::uint64_t>(group);
      break;
    case SettingType::Vector: {
      const Vec3& v = s.value<Vec3>(group);
      object[s.key] = ordered_json::array({v.x, v.y, v.z});
      break;
    }
    case SettingType::Boolean:
      object[s.key] = s.value<bool>(group);
      break;
    case SettingType::Text:
      object[s.key] = s.value<std::string>(group);
      break;
    case SettingType::OptionalNumber:
      if (const auto& v = s.value<std::optional<double>>(group)) object[s.key] = *v;
      break;
    case SettingType::Choice:
      object[s.key] = s.choices->names[std::size_t(s.choiceOf(group))];
      break;
    case SettingType::CalculatorVars:
    case SettingType::MorphPairs:
    case SettingType::NodeMoves:
      throw std::logic_error(std::string("settings field ") + s.key + " has a type settings cannot hold");
  }
}

void writeSettingFields(const SettingTable& table, const void* group, ordered_json& object) {
  // Fields written only when changed come after the others, in table order, so a file that never
  // changed them saves as it always has and one that did keeps them at the end.
  for (bool optional : {false, true})
    for (const SettingSpec& s : table.fields)
      if (s.omitDefault == optional && settingWritten(s, group)) writeSettingField(s, group, object);
}

}  // namespace gridifs
