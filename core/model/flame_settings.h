#pragma once
// The flame display's settings (Draves & Reckase 2003, §4–8), stored in the project under "render".
// Defaults follow flam3's where an artist would expect them (gamma 4, brightness 4,
// estimator radius 9 / minimum 0 / curve 0.4, Gaussian filter radius 0.5); see
// docs/FLAME.md for what each field does.
#include <string>

namespace gridifs {

/// Which picture a render shows: the nearest surface (z-buffer, Gröller & Wegenkittl 1994, §3.1), the
/// whole attractor's log density colored by structure (flame, Draves & Reckase 2003, §4–8), or the
/// nearest surface lit, shadowed and occluded (shaded, core/render/shaded_image.h).
enum class DisplayMode { ZBuffer, Flame, Shaded };

const char* displayModeName(DisplayMode mode);
/// Parses "zbuffer" / "flame" / "shaded"; false for anything else.
bool parseDisplayMode(const std::string& text, DisplayMode& out);

struct FlameSettings {
  std::string palette = "ember";   // palette reference (core/palette.h): "ember", "flam3:27", "file:x.json"
  double brightness = 4.0;         // Draves & Reckase 2003, §4 k1 (flam3 "brightness")
  double gamma = 4.0;              // Draves & Reckase 2003, §6
  double gamma_threshold = 0.01;   // below this density, gamma becomes linear (keeps noise down)
  double vibrancy = 1.0;           // 0: gamma per channel, 1: gamma through alpha (Draves & Reckase 2003, §6)
  double highlight_power = 1.0;    // >= 0: desaturate saturated highlights toward white; < 0: clip
  int supersample = 1;             // histogram at supersample× the output size (Draves & Reckase 2003, §8)
  double estimator_radius = 9.0;   // density estimation: widest kernel radius in output pixels (0: off)
  double estimator_minimum = 0.0;  // narrowest kernel radius
  double estimator_curve = 0.4;    // how fast the kernel shrinks as density grows (radius ∝ hits^-curve)
  double filter_radius = 0.5;      // Gaussian spatial filter radius in output pixels
  /// X units per unit of the plane the exposure counts density in (flam3 normalises hits by
  /// pixels per unit of its flame plane). 1 for GridIFS projects; an imported genome stores the
  /// scale of its frame here so that it keeps flam3's exposure.
  double density_unit = 1.0;
  bool operator==(const FlameSettings&) const = default;
};

}  // namespace gridifs
