#include "model/shading_settings.h"

#include <cmath>
#include <sstream>

namespace gridifs {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw ModelError(path, message); }

std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

std::string show(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

void nonNegative(double v, const std::string& path, double hi, const char* what) {
  if (!std::isfinite(v)) fail(path, std::string("the ") + what + " must be a finite number");
  if (v < 0.0) fail(path, std::string("the ") + what + " must not be negative, found " + show(v));
  if (v > hi) fail(path, std::string("the ") + what + " must be at most " + show(hi) + ", found " + show(v));
}

void unitColor(const Vec3& c, const std::string& path) {
  for (int d = 0; d < 3; ++d)
    if (!(c[d] >= 0.0 && c[d] <= 1.0))
      fail(path + "[" + std::to_string(d) + "]", "expected a colour component between 0 and 1, found " + show(c[d]));
}

}  // namespace

bool ShadingSettings::anyShadows() const {
  for (const ShadingLight& l : lights)
    if (l.shadows) return true;
  return false;
}

void validateShadingSettings(const ShadingSettings& s, const std::string& path) {
  const std::string lights = join(path, "lights");
  if (s.lights.size() > std::size_t(limits::kMaxLights))
    fail(lights, "at most " + std::to_string(limits::kMaxLights) + " lights are supported, found " +
                     std::to_string(s.lights.size()));
  for (std::size_t i = 0; i < s.lights.size(); ++i) {
    const ShadingLight& l = s.lights[i];
    const std::string p = lights + "[" + std::to_string(i) + "]";
    const Vec3& d = l.direction;
    if (!(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z)))
      fail(join(p, "direction"), "the light direction must be finite");
    if (d.x * d.x + d.y * d.y + d.z * d.z < 1e-12)
      fail(join(p, "direction"), "the light direction has zero length, so the light points nowhere");
    unitColor(l.color, join(p, "color"));
    nonNegative(l.intensity, join(p, "intensity"), 1e3, "light intensity");
  }
  nonNegative(s.ambient, join(path, "ambient"), 10.0, "ambient term");
  nonNegative(s.specular, join(path, "specular"), 10.0, "specular strength");
  if (!(s.shininess >= 1.0 && s.shininess <= 4096.0))
    fail(join(path, "shininess"), "the shininess must be between 1 and 4096, found " + show(s.shininess));
  const std::string ao = join(path, "ao");
  nonNegative(s.ao.radius, join(ao, "radius"), limits::kMaxAoRadius, "occlusion radius");
  nonNegative(s.ao.strength, join(ao, "strength"), 1.0, "occlusion strength");
  if (s.ao.directions < 1 || s.ao.directions > limits::kMaxAoDirections)
    fail(join(ao, "directions"), "expected between 1 and " + std::to_string(limits::kMaxAoDirections) +
                                     " occlusion directions, found " + std::to_string(s.ao.directions));
  const std::string fog = join(path, "fog");
  unitColor(s.fog.color, join(fog, "color"));
  nonNegative(s.fog.density, join(fog, "density"), 1e3, "fog density");
  const std::string dof = join(path, "dof");
  nonNegative(s.dof.aperture, join(dof, "aperture"), 10.0, "aperture");
  if (s.dof.focus) nonNegative(*s.dof.focus, join(dof, "focus"), 1e4, "focus distance");
  if (s.dof.aperture > 0.0 && !s.dof.focus)
    fail(join(dof, "focus"), "an aperture above 0 needs a focus distance (the view depth that stays sharp)");
}

}  // namespace gridifs
