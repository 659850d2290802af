#include "io/settings_json.h"

#include <cmath>

#include "io/json_read.h"

namespace gridifs {
namespace {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;
using namespace json_read;

double readSettingNumber(const SettingSpec& s, const json& j, const std::string& path) {
  return s.noun ? readFinite(j, path) : readNumber(j, path, s.min, s.max);
}

double readSettingInteger(const SettingSpec& s, const json& j, const std::string& path) {
  if (!s.noun) return double(readInteger(j, path, std::int64_t(s.min), std::int64_t(s.max)));
  const double v = readFinite(j, path);
  if (v != std::floor(v) || v < s.min || v > s.max)
    fail(path, "expected an integer between " + std::to_string(std::int64_t(s.min)) + " and " +
                   std::to_string(std::int64_t(s.max)));
  return v;
}

}  // namespace

void readSettingFields(const SettingTable& table, const json& object, const std::string& path, void* group) {
  requireObject(object, path);
  for (const SettingSpec& s : table.fields) {
    auto it = object.find(s.key);
    if (it == object.end()) continue;
    const std::string p = join(path, s.key);
    switch (s.type) {
      case SettingType::Number:
        s.value<double>(group) = readSettingNumber(s, *it, p);
        break;
      case SettingType::Integer:
        s.value<int>(group) = int(readSettingInteger(s, *it, p));
        break;
      case SettingType::Count:
        s.value<std::int64_t>(group) = std::int64_t(readSettingInteger(s, *it, p));
        break;
      case SettingType::Seed:
        s.value<std::uint64_t>(group) = readSeed(*it, p);
        break;
      case SettingType::Vector: {
        if (!it->is_array() || it->size() != 3) fail(p, "expected an array of 3 numbers");
        Vec3& v = s.value<Vec3>(group);
        for (int d = 0; d < 3; ++d) v[d] = readSettingNumber(s, (*it)[std::size_t(d)], item(p, std::size_t(d)));
        break;
      }
      case SettingType::Boolean:
        s.value<bool>(group) = readBoolean(*it, p);
        break;
      case SettingType::Text: {
        std::string text = readString(*it, p, s.maxLength);
        if (s.accepts && !s.accepts(text)) fail(p, s.expected);
        s.value<std::string>(group) = std::move(text);
        break;
      }
      case SettingType::OptionalNumber:
        if (!it->is_null()) s.value<std::optional<double>>(group) = readSettingNumber(s, *it, p);
        break;
    }
  }
}

void writeSettingFields(const SettingTable& table, const void* group, ordered_json& object) {
  for (const SettingSpec& s : table.fields) {
    if (s.omitDefault && s.isDefault(group)) continue;
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
    }
  }
}

}  // namespace gridifs
