#include "edit/settings_edits.h"

#include <algorithm>

#include "schema/settings_tables.h"

namespace gridifs {

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

void SetSampleBudget::apply(Project& project) const {
  project.render.samples = samples;
  project.render.quality.reset();
}

void SetBackground::apply(Project& project) const { project.render.background = color; }

std::string SetBackground::label() const { return renderSettingsTable().field("background").label; }

void SetPalette::apply(Project& project) const {
  // A palette chosen (or saved from the gradient editor) replaces the gradient being edited.
  project.render.flame.palette = palette;
  project.render.flame.palette_keys.clear();
}

void SetDensityEstimation::apply(Project& project) const {
  FlameSettings& flame = project.render.flame;
  flame.estimator_radius = on ? std::max(FlameSettings{}.estimator_radius, flame.estimator_minimum) : 0.0;
}

std::string SetDensityEstimation::label() const { return on ? "Density estimation on" : "Density estimation off"; }

void ResetFlameSettings::apply(Project& project) const {
  FlameSettings d;
  d.palette = project.render.flame.palette;
  d.palette_keys = project.render.flame.palette_keys;
  d.supersample = project.render.flame.supersample;
  project.render.flame = d;
}

void SetDensityDisplay::apply(Project& project) const { project.render.flame.density_display = display; }

void SetQuality::apply(Project& project) const { project.render.quality = quality; }

void SetPaletteKeys::apply(Project& project) const { project.render.flame.palette_keys = keys; }

void SetCamera::apply(Project& project) const { project.camera = camera; }

void SetTime::apply(Project& project) const { project.time = time; }

void SetAnimation::apply(Project& project) const {
  AnimationSettings a = animation;
  if (a.end < a.start) a.end = a.start;
  project.animation = a;
}

}  // namespace gridifs
