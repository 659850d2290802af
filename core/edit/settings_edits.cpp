#include "edit/settings_edits.h"

#include <algorithm>

#include "base/errors.h"
#include "edit/edit_refs.h"
#include "model/settings_tables.h"

namespace gridifs {
namespace {

void* groupIn(Project& project, SettingGroup group, std::size_t light) {
  ShadingSettings& shading = project.render.shading;
  switch (group) {
    case SettingGroup::Render:
      return &project.render;
    case SettingGroup::Flame:
      return &project.render.flame;
    case SettingGroup::Shading:
      return &shading;
    case SettingGroup::Light:
      return &lightAt(project, light);
    case SettingGroup::AmbientOcclusion:
      return &shading.ao;
    case SettingGroup::Fog:
      return &shading.fog;
    case SettingGroup::DepthOfField:
      return &shading.dof;
  }
  return nullptr;
}

std::string groupPath(SettingGroup group, std::size_t light) {
  switch (group) {
    case SettingGroup::Render:
      return "render";
    case SettingGroup::Flame:
      return "render.flame";
    case SettingGroup::Shading:
      return "render.shading";
    case SettingGroup::Light:
      return "render.shading.lights[" + std::to_string(light) + "]";
    case SettingGroup::AmbientOcclusion:
      return "render.shading.ao";
    case SettingGroup::Fog:
      return "render.shading.fog";
    case SettingGroup::DepthOfField:
      return "render.shading.dof";
  }
  return {};
}

/// The numeric field `key` of `group`; ModelError when the table has no such number.
const SettingSpec& numberField(SettingGroup group, const std::string& key, std::size_t light) {
  const SettingTable& table = settingTable(group);
  const auto it =
      std::find_if(table.fields.begin(), table.fields.end(), [&](const SettingSpec& s) { return key == s.key; });
  if (it == table.fields.end()) throw ModelError(settingPath(groupPath(group, light), key), "no such setting");
  if (it->type != SettingType::Number && it->type != SettingType::Integer && it->type != SettingType::Count &&
      it->type != SettingType::OptionalNumber)
    throw ModelError(settingPath(groupPath(group, light), key), "not a number setting");
  return *it;
}

}  // namespace

const SettingTable& settingTable(SettingGroup group) {
  switch (group) {
    case SettingGroup::Render:
      return renderSettingsTable();
    case SettingGroup::Flame:
      return flameSettingsTable();
    case SettingGroup::Shading:
      return shadingSettingsTable();
    case SettingGroup::Light:
      return shadingLightTable();
    case SettingGroup::AmbientOcclusion:
      return ambientOcclusionTable();
    case SettingGroup::Fog:
      return fogTable();
    case SettingGroup::DepthOfField:
      return depthOfFieldTable();
  }
  return renderSettingsTable();
}

void SetSettingNumber::apply(Project& project) const {
  const SettingSpec& spec = numberField(group, key, light);
  spec.setNumber(groupIn(project, group, light), value);
}

std::string SetSettingNumber::label() const { return numberField(group, key, light).label; }

void SetDisplayMode::apply(Project& project) const { project.render.mode = mode; }

std::string SetDisplayMode::label() const {
  switch (mode) {
    case DisplayMode::Flame:
      return "Flame display";
    case DisplayMode::Shaded:
      return "Shaded display";
    case DisplayMode::ZBuffer:
      break;
  }
  return "Z-buffer display";
}

void SetSampleBudget::apply(Project& project) const { project.render.samples = samples; }

void SetBackground::apply(Project& project) const { project.render.background = color; }

std::string SetBackground::label() const { return renderSettingsTable().field("background").label; }

void SetPalette::apply(Project& project) const { project.render.flame.palette = palette; }

void SetDensityEstimation::apply(Project& project) const {
  FlameSettings& flame = project.render.flame;
  flame.estimator_radius = on ? std::max(FlameSettings{}.estimator_radius, flame.estimator_minimum) : 0.0;
}

std::string SetDensityEstimation::label() const { return on ? "Density estimation on" : "Density estimation off"; }

void ResetFlameSettings::apply(Project& project) const {
  FlameSettings d;
  d.palette = project.render.flame.palette;
  d.supersample = project.render.flame.supersample;
  project.render.flame = d;
}

void SetCamera::apply(Project& project) const { project.camera = camera; }

void SetCameraDistance::apply(Project& project) const { project.camera.distance = distance; }

void SetTime::apply(Project& project) const { project.time = time; }

void SetAnimation::apply(Project& project) const {
  AnimationSettings a = animation;
  if (a.end < a.start) a.end = a.start;
  project.animation = a;
}

}  // namespace gridifs
