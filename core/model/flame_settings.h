#pragma once
// The flame display's settings (Draves & Reckase 2003, §4–8), stored in the project under "render".
// Defaults follow flam3's where an artist would expect them (gamma 4, brightness 4,
// estimator radius 9 / minimum 0 / curve 0.4, Gaussian filter radius 0.5); see
// docs/FLAME.md for what each field does.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace gridifs {

/// Which picture a render shows: the nearest surface (z-buffer, Gröller & Wegenkittl 1994, §3.1), the
/// whole attractor's log density colored by structure (flame, Draves & Reckase 2003, §4–8), or the
/// nearest surface lit, shadowed and occluded (shaded, core/render/shaded_image.h).
enum class DisplayMode { ZBuffer, Flame, Shaded };

const char* displayModeName(DisplayMode mode);
/// Parses "zbuffer" / "flame" / "shaded"; false for anything else.
bool parseDisplayMode(const std::string& text, DisplayMode& out);

/// Whether `text` names a density display: "log", "linear" or "binary" (FlameSettings::density_display).
bool isDensityDisplayName(const std::string& text);
/// One key of a palette gradient (the palette editor): a position in [0, 1] and an RGB colour in [0, 1].
struct PaletteKey {
  double position = 0.0;
  float r = 0.f, g = 0.f, b = 0.f;
  bool operator==(const PaletteKey&) const = default;
};
inline constexpr std::size_t kMaxPaletteKeys = 64;
/// Parses FlameSettings::palette_keys: 2..64 keys "POSITION:#RRGGBB" (positions in [0, 1])
/// separated by spaces, in any order. nullopt when the text is not that. Pure.
std::optional<std::vector<PaletteKey>> parsePaletteKeys(const std::string& text);
/// The palette_keys text of `keys` (positions with up to 4 decimals, colours rounded to #RRGGBB).
std::string formatPaletteKeys(const std::vector<PaletteKey>& keys);
/// Whether `text` is a valid palette_keys value: empty (no gradient) or what parsePaletteKeys reads.
bool isPaletteKeysSyntax(const std::string& text);

struct FlameSettings {
  std::string palette = "ember";  // palette reference (core/palette.h): "ember", "flam3:27", "file:x.json"
  double hue = 0.0;               // turns the palette's hue by this fraction of a circle (flam3's `hue`)
  /// A gradient being edited (the palette editor): keys "POSITION:#RRGGBB" separated by spaces,
  /// e.g. "0:#000000 0.5:#ff8000 1:#ffffff". When not empty it replaces `palette` (tone/palette_gradient.h).
  std::string palette_keys;
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
  /// How hit counts become brightness (Draves & Reckase 2003, §4, figure 3): "log" (the flame
  /// display), "linear" (hits over the densest bucket's) or "binary" (membership: hit or not).
  std::string density_display = "log";
  bool operator==(const FlameSettings&) const = default;
};

}  // namespace gridifs
