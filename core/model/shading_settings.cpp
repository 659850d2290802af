#include "model/shading_settings.h"

#include "model/settings_tables.h"

namespace gridifs {

bool ShadingSettings::anyShadows() const {
  for (const ShadingLight& l : lights)
    if (l.shadows) return true;
  return false;
}

void validateShadingSettings(const ShadingSettings& s, const std::string& path) {
  const std::string lights = settingPath(path, "lights");
  if (s.lights.size() > std::size_t(limits::kMaxLights))
    throw ModelError(lights, "at most " + std::to_string(limits::kMaxLights) + " lights are supported, found " +
                                 std::to_string(s.lights.size()));
  for (std::size_t i = 0; i < s.lights.size(); ++i)
    validateSettings(shadingLightTable(), s.lights[i], lights + "[" + std::to_string(i) + "]");
  validateSettings(shadingSettingsTable(), s, path);
  validateSettings(ambientOcclusionTable(), s.ao, settingPath(path, "ao"));
  validateSettings(fogTable(), s.fog, settingPath(path, "fog"));
  validateSettings(depthOfFieldTable(), s.dof, settingPath(path, "dof"));
}

}  // namespace gridifs
