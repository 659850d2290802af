#include "io/shading_io.h"

#include "io/json_read.h"
#include "io/settings_json.h"
#include "schema/settings_tables.h"
#include "schema/validation.h"

namespace gridifs {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;

// Every field of the shading tables has a noun: reading only insists on finite numbers of sane
// magnitude, and validateShadingSettings then checks ranges with messages that name the meaning.
ShadingSettings readShadingSettings(const json& o, const std::string& path) {
  using namespace json_read;
  requireObject(o, path);
  ShadingSettings s;
  if (auto it = o.find("lights"); it != o.end()) {
    const std::string p = join(path, "lights");
    if (!it->is_array()) fail(p, std::string("expected an array of lights, found ") + typeName(*it));
    if (it->size() > std::size_t(limits::kMaxLights))
      fail(p, "at most " + std::to_string(limits::kMaxLights) + " lights are supported, found " +
                  std::to_string(it->size()));
    s.lights.assign(it->size(), ShadingLight{});
    for (std::size_t i = 0; i < it->size(); ++i)
      readSettingFields(shadingLightTable(), (*it)[i], item(p, i), &s.lights[i]);
  }
  readSettingFields(shadingSettingsTable(), o, path, &s);
  if (auto it = o.find("ao"); it != o.end()) readSettingFields(ambientOcclusionTable(), *it, join(path, "ao"), &s.ao);
  if (auto it = o.find("fog"); it != o.end()) readSettingFields(fogTable(), *it, join(path, "fog"), &s.fog);
  if (auto it = o.find("dof"); it != o.end()) readSettingFields(depthOfFieldTable(), *it, join(path, "dof"), &s.dof);
  validateShadingSettings(s, path);
  return s;
}

ordered_json writeShadingSettings(const ShadingSettings& s) {
  ordered_json o = ordered_json::object();
  ordered_json lights = ordered_json::array();
  for (const ShadingLight& l : s.lights) lights.push_back(writeSettings(shadingLightTable(), l));
  o["lights"] = lights;
  writeSettingFields(shadingSettingsTable(), &s, o);
  o["ao"] = writeSettings(ambientOcclusionTable(), s.ao);
  o["fog"] = writeSettings(fogTable(), s.fog);
  o["dof"] = writeSettings(depthOfFieldTable(), s.dof);
  return o;
}

}  // namespace gridifs
