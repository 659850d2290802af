#pragma once
// Named edits of the project's settings (a single number of a settings table is set by
// SetParameter, edit/parameter_edit.h): the display mode, sample budget, background and palette, the flame's tone
// mapping, the camera, the time and the timeline. The shading's lights, fog colour and aperture are in
// edit/shading_edits.h. Each edit is a plain value gathered in ProjectEdit (edit/project_edit.h).
//
// Thread-safety: plain values; apply() touches only the project given. apply() throws ModelError
// when what it names is not in the project (a setting key, a light).
#include <cstdint>
#include <optional>
#include <string>

#include "model/project.h"
#include "schema/settings_table.h"

namespace gridifs {

/// How buffers become a picture: z-buffer, flame or shaded.
struct SetDisplayMode {
  DisplayMode mode = DisplayMode::ZBuffer;
  void apply(Project& project) const;
  /// "Z-buffer display", "Flame display" or "Shaded display".
  std::string label() const;
};

/// How many chaos-game points a render takes.
/// A sample budget replaces a quality (samples per pixel): the artist asked for this count.
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

/// The flame display's defaults, keeping its palette, its gradient and supersampling (which are
/// choices of the picture rather than of its tone).
struct ResetFlameSettings {
  void apply(Project& project) const;
  std::string label() const { return "Flame defaults"; }
};

/// How densities become brightness: "log", "linear" or "binary" (Draves & Reckase 2003, figure 3).
struct SetDensityDisplay {
  std::string display = "log";
  void apply(Project& project) const;
  std::string label() const { return "Density display"; }
};

/// Samples per pixel for renders, or none (the sample budget decides).
struct SetQuality {
  std::optional<double> quality;
  void apply(Project& project) const;
  std::string label() const { return quality ? "Quality" : "Quality off"; }
};

/// The gradient keys being edited ("0:#000000 1:#ffffff"; empty: none), which replace the palette.
struct SetPaletteKeys {
  std::string keys;
  void apply(Project& project) const;
  std::string label() const { return keys.empty() ? "Discard gradient" : "Palette gradient"; }
};

struct SetCamera {
  Camera camera;
  void apply(Project& project) const;
  std::string label() const { return "Camera"; }
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
