#pragma once
// Named edits of the project's settings: any number of a settings table (model/settings_tables.h),
// the display mode, sample budget, background and palette, the flame's tone mapping, the camera,
// the time and the timeline. The shading's lights, fog colour and aperture are in
// edit/shading_edits.h. Each edit is a plain value gathered in ProjectEdit (edit/project_edit.h).
//
// Thread-safety: plain values; apply() touches only the project given. apply() throws ModelError
// when what it names is not in the project (a setting key, a light).
#include <cstdint>
#include <string>

#include "model/project.h"
#include "model/settings_table.h"

namespace gridifs {

/// A settings group of the project that sliders edit through its table.
enum class SettingGroup {
  Render,            // "render"
  Flame,             // "render.flame"
  Shading,           // "render.shading"
  Light,             // "render.shading.lights[i]"
  AmbientOcclusion,  // "render.shading.ao"
  Fog,               // "render.shading.fog"
  DepthOfField,      // "render.shading.dof"
};

/// The table of `group`.
const SettingTable& settingTable(SettingGroup group);

/// Sets the number `key` of a settings group (a Number, Integer, Count or OptionalNumber field;
/// integers are rounded) as its slider does. `light` picks the light of SettingGroup::Light.
struct SetSettingNumber {
  SettingGroup group = SettingGroup::Render;
  std::string key;
  double value = 0.0;
  std::size_t light = 0;
  void apply(Project& project) const;
  /// The table's label of the field ("Gamma threshold"); throws ModelError for an unknown key.
  std::string label() const;
};

/// How buffers become a picture: z-buffer, flame or shaded.
struct SetDisplayMode {
  DisplayMode mode = DisplayMode::ZBuffer;
  void apply(Project& project) const;
  /// "Z-buffer display", "Flame display" or "Shaded display".
  std::string label() const;
};

/// How many chaos-game points a render takes.
struct SetSampleBudget {
  std::int64_t samples = 20'000'000;
  void apply(Project& project) const;
  std::string label() const { return "Sample budget"; }
};

struct SetBackground {
  Vec3 color{0.0};
  void apply(Project& project) const;
  /// The render table's label of "background".
  std::string label() const;
};

/// The flame display's palette reference ("ember", "flam3:27").
struct SetPalette {
  std::string palette;
  void apply(Project& project) const;
  std::string label() const { return "Palette"; }
};

/// Density estimation on or off (Draves & Reckase 2003, §8): on sets the default kernel radius,
/// at least the narrowest one; off sets it to 0.
struct SetDensityEstimation {
  bool on = true;
  void apply(Project& project) const;
  /// "Density estimation on" or "Density estimation off".
  std::string label() const;
};

/// The flame display's defaults, keeping its palette and supersampling (which are choices of the
/// picture rather than of its tone).
struct ResetFlameSettings {
  void apply(Project& project) const;
  std::string label() const { return "Flame defaults"; }
};

struct SetCamera {
  Camera camera;
  void apply(Project& project) const;
  std::string label() const { return "Camera"; }
};

/// Only the camera's distance to its target (a zoom).
struct SetCameraDistance {
  double distance = 4.0;
  void apply(Project& project) const;
  std::string label() const { return "Zoom preview camera"; }
};

/// The current time in seconds (the playhead; the modeller applies it without an undo step).
struct SetTime {
  double time = 0.0;
  void apply(Project& project) const;
  std::string label() const { return "Time"; }
};

/// The timeline: range, frame rate, loop. An end before the start is moved to the start.
struct SetAnimation {
  AnimationSettings animation;
  void apply(Project& project) const;
  std::string label() const { return "Timeline"; }
};

}  // namespace gridifs
