#include "edit/shading_edits.h"

#include "edit/edit_refs.h"
#include "schema/settings_tables.h"

namespace gridifs {

void AddLight::apply(Project& project) const {
  ShadingLight fill;
  fill.direction = Vec3(-0.6, 0.8, 0.4);
  fill.intensity = 0.4;
  fill.shadows = false;
  project.render.shading.lights.push_back(fill);
}

void RemoveLight::apply(Project& project) const {
  lightAt(project, index);
  auto& lights = project.render.shading.lights;
  lights.erase(lights.begin() + std::ptrdiff_t(index));
}

void SetLightDirection::apply(Project& project) const { lightAt(project, index).direction = direction; }

void SetLightColor::apply(Project& project) const { lightAt(project, index).color = color; }

std::string SetLightColor::label() const { return shadingLightTable().field("color").label; }

void SetLightShadows::apply(Project& project) const { lightAt(project, index).shadows = shadows; }

std::string SetLightShadows::label() const { return shadows ? "Light casts shadows" : "Light casts no shadows"; }

void SetFogColor::apply(Project& project) const { project.render.shading.fog.color = color; }

std::string SetFogColor::label() const { return fogTable().field("color").label; }

void SetAperture::apply(Project& project) const {
  project.render.shading.dof.aperture = aperture;
  project.render.shading.dof.focus = focus;
}

std::string SetAperture::label() const { return depthOfFieldTable().field("aperture").label; }

}  // namespace gridifs
