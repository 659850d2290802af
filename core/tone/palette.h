#pragma once
// 256-entry palettes for the flame display's structural coloring (Draves & Reckase 2003, §5: "a palette is
// classically specified with an array of 256 triples of bytes").
//
// Sources of palettes:
//  - built-in GridIFS palettes (the same data as assets/palettes/*.json, always available);
//  - flam3's collection (Debian's flam3-palette package: /usr/share/flam3/flam3-palettes.xml),
//    addressed by number or name;
//  - a palette file: JSON `{"format": "gridifs-palette", "name": "...", "colors": [[r,g,b], ...]}`
//    with 2..256 colors in [0, 1] (fewer than 256 are linearly interpolated), or a flam3 XML file.
//
// A palette reference (FlameSettings::palette) is a string:
//   "ember"                    built-in palette by name
//   "flam3:27", "flam3:south-sea-bather"   flam3 collection by number or name
//   "file:relative/or/absolute.json"       a palette file (relative to the project's folder)
// Everything here is a pure function of its inputs: thread-safe.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "base/types.h"
#include "schema/palette_reference.h"

namespace gridifs {

/// One RGB color with channels in [0, 1].
struct Rgb {
  float r = 0.f, g = 0.f, b = 0.f;
  bool operator==(const Rgb&) const = default;
};

struct Palette {
  static constexpr int kSize = 256;
  std::string name;
  std::array<Rgb, kSize> colors{};

  /// Color at coordinate c in [0, 1] (clamped) with flam3's "linear" palette mode: index c·256
  /// and linear interpolation between the two neighbouring entries (Draves & Reckase 2003, §5).
  Rgb lookup(double c) const;
  bool operator==(const Palette&) const = default;
};

/// Thrown when a palette cannot be found or read; the message is one sentence.
class PaletteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Default location of flam3's palette collection on Debian.
inline constexpr const char* kFlam3PaletteFile = "/usr/share/flam3/flam3-palettes.xml";

/// Parses flam3 palette XML text: `<palette number="N" name="..." data="00RRGGBB..."/>` elements
/// (256 hex entries each; whitespace inside data is ignored). Throws PaletteError.
std::vector<Palette> parseFlam3Palettes(const std::string& xmlText);

/// Reads and caches flam3's collection (first call parses the file; later calls are cheap).
/// Throws PaletteError when the file is missing or unreadable.
const std::vector<Palette>& flam3Palettes(const std::filesystem::path& file = kFlam3PaletteFile);

/// flam3 palette by number ("27") or name ("south-sea-bather"). Throws PaletteError.
Palette flam3Palette(const std::string& numberOrName, const std::filesystem::path& file = kFlam3PaletteFile);

/// Parses a GridIFS palette JSON text (format above). Throws PaletteError naming the field.
Palette parsePaletteJson(const std::string& text);

/// Serialises a palette as GridIFS palette JSON (256 colors, 4 decimals).
std::string serializePaletteJson(const Palette& palette);

/// A built-in palette by name. Throws PaletteError for an unknown name.
Palette builtinPalette(const std::string& name);

/// `palette` with every color's hue turned by `turns` of a full circle in HSV space, as flam3
/// applies a genome's `hue` to the palette it takes from its collection (hue in sixths of a
/// turn, saturation and value kept). Pure.
Palette rotatePaletteHue(const Palette& palette, double turns);

/// Resolves a palette reference (see the top of this file). `projectFolder` anchors relative
/// "file:" paths. Throws PaletteError with a sentence naming the reference.
Palette resolvePalette(const std::string& reference, const std::filesystem::path& projectFolder = {});

}  // namespace gridifs
