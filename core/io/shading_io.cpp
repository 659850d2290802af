#include "io/shading_io.h"

#include <cmath>

namespace gridifs {
namespace {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw ModelError(path, message); }

std::string join(const std::string& path, const std::string& key) { return path + "." + key; }
std::string item(const std::string& path, std::size_t index) { return path + "[" + std::to_string(index) + "]"; }

const char* kindOf(const json& j) {
  if (j.is_object()) return "an object";
  if (j.is_array()) return "an array";
  if (j.is_string()) return "a string";
  if (j.is_boolean()) return "a boolean";
  if (j.is_number()) return "a number";
  return "null";
}

void requireObject(const json& j, const std::string& path) {
  if (!j.is_object()) fail(path, std::string("expected an object, found ") + kindOf(j));
}

// Ranges are checked by validateShadingSettings, which names each field's meaning; reading only
// insists on finite numbers of sane magnitude.
double readNumber(const json& j, const std::string& path) {
  if (!j.is_number()) fail(path, std::string("expected a number, found ") + kindOf(j));
  const double v = j.get<double>();
  if (!std::isfinite(v) || std::abs(v) > limits::kMaxCoordinate) fail(path, "expected a finite number");
  return v;
}

double number(const json& o, const char* key, const std::string& path, double fallback) {
  auto it = o.find(key);
  return it == o.end() ? fallback : readNumber(*it, join(path, key));
}

Vec3 vec3(const json& o, const char* key, const std::string& path, Vec3 fallback) {
  auto it = o.find(key);
  if (it == o.end()) return fallback;
  const std::string p = join(path, key);
  if (!it->is_array() || it->size() != 3) fail(p, "expected an array of 3 numbers");
  return Vec3(readNumber((*it)[0], item(p, 0)), readNumber((*it)[1], item(p, 1)), readNumber((*it)[2], item(p, 2)));
}

bool boolean(const json& o, const char* key, const std::string& path, bool fallback) {
  auto it = o.find(key);
  if (it == o.end()) return fallback;
  if (!it->is_boolean()) fail(join(path, key), std::string("expected true or false, found ") + kindOf(*it));
  return it->get<bool>();
}

ShadingLight readLight(const json& o, const std::string& path) {
  requireObject(o, path);
  ShadingLight l;
  l.direction = vec3(o, "direction", path, l.direction);
  l.color = vec3(o, "color", path, l.color);
  l.intensity = number(o, "intensity", path, l.intensity);
  l.shadows = boolean(o, "shadows", path, l.shadows);
  return l;
}

ordered_json writeVec3(const Vec3& v) { return ordered_json::array({v.x, v.y, v.z}); }

}  // namespace

ShadingSettings readShadingSettings(const json& o, const std::string& path) {
  requireObject(o, path);
  ShadingSettings s;
  if (auto it = o.find("lights"); it != o.end()) {
    const std::string p = join(path, "lights");
    if (!it->is_array()) fail(p, std::string("expected an array of lights, found ") + kindOf(*it));
    if (it->size() > std::size_t(limits::kMaxLights))
      fail(p, "at most " + std::to_string(limits::kMaxLights) + " lights are supported, found " +
                  std::to_string(it->size()));
    s.lights.clear();
    for (std::size_t i = 0; i < it->size(); ++i) s.lights.push_back(readLight((*it)[i], item(p, i)));
  }
  s.ambient = number(o, "ambient", path, s.ambient);
  s.specular = number(o, "specular", path, s.specular);
  s.shininess = number(o, "shininess", path, s.shininess);
  if (auto it = o.find("ao"); it != o.end()) {
    const std::string p = join(path, "ao");
    requireObject(*it, p);
    s.ao.radius = number(*it, "radius", p, s.ao.radius);
    s.ao.strength = number(*it, "strength", p, s.ao.strength);
    const double directions = number(*it, "directions", p, s.ao.directions);
    if (directions != std::floor(directions) || directions < 1 || directions > limits::kMaxAoDirections)
      fail(join(p, "directions"), "expected an integer between 1 and " + std::to_string(limits::kMaxAoDirections));
    s.ao.directions = int(directions);
  }
  if (auto it = o.find("fog"); it != o.end()) {
    const std::string p = join(path, "fog");
    requireObject(*it, p);
    s.fog.color = vec3(*it, "color", p, s.fog.color);
    s.fog.density = number(*it, "density", p, s.fog.density);
  }
  if (auto it = o.find("dof"); it != o.end()) {
    const std::string p = join(path, "dof");
    requireObject(*it, p);
    s.dof.aperture = number(*it, "aperture", p, s.dof.aperture);
    if (auto f = it->find("focus"); f != it->end() && !f->is_null()) s.dof.focus = readNumber(*f, join(p, "focus"));
  }
  validateShadingSettings(s, path);
  return s;
}

ordered_json writeShadingSettings(const ShadingSettings& s) {
  ordered_json lights = ordered_json::array();
  for (const ShadingLight& l : s.lights)
    lights.push_back({{"direction", writeVec3(l.direction)},
                      {"color", writeVec3(l.color)},
                      {"intensity", l.intensity},
                      {"shadows", l.shadows}});
  ordered_json dof = {{"aperture", s.dof.aperture}};
  if (s.dof.focus) dof["focus"] = *s.dof.focus;
  return {{"lights", lights},
          {"ambient", s.ambient},
          {"specular", s.specular},
          {"shininess", s.shininess},
          {"ao", {{"radius", s.ao.radius}, {"strength", s.ao.strength}, {"directions", s.ao.directions}}},
          {"fog", {{"color", writeVec3(s.fog.color)}, {"density", s.fog.density}}},
          {"dof", dof}};
}

}  // namespace gridifs
