#pragma once
// Palette gradients for the palette editor: a few keys (position + colour) interpolated into the
// 256 entries of a flame palette (Draves & Reckase 2003, §5), started from any palette, saved as a
// palette file that a project references as "file:NAME.palette.json". The file keeps the keys
// beside the 256 colours, so the editor reopens what the artist made; any other reader of the
// format sees the colours.
//
// Everything here is pure except savePaletteGradient (which writes a file). Thread-safe.
#include <filesystem>
#include <string>
#include <vector>

#include "model/flame_settings.h"
#include "tone/palette.h"

namespace gridifs {

/// The 256 entries of a gradient: entry i sits at position i/255 and takes the linear blend of the
/// two keys around it; before the first key and after the last, that key's colour. Keys may come
/// in any order (they are sorted by position; equal positions keep their order, a hard step).
/// With no keys the palette is black.
Palette paletteFromKeys(const std::vector<PaletteKey>& keys, const std::string& name = "gradient");

/// `count` (2..64) keys sampled evenly from `palette` (key k at k/(count−1), the palette's colour
/// there), to start editing from an existing palette.
std::vector<PaletteKey> keysFromPalette(const Palette& palette, int count = 16);

/// Palette file text (`{"format": "gridifs-palette", "name", "keys": [{"position", "color"}],
/// "colors": [256 × [r, g, b]]}`).
std::string serializeGradientPalette(const std::string& name, const std::vector<PaletteKey>& keys);

/// The keys of palette file text: its "keys" when it has them, else keysFromPalette of its colours.
/// Throws PaletteError (one sentence) when the text is not a palette file.
std::vector<PaletteKey> parseGradientKeys(const std::string& text);

/// Whether `name` may name a palette file (letters, digits, '-', '_', 1..64 characters).
bool isPaletteFileName(const std::string& name);

/// Writes `folder`/NAME.palette.json atomically and returns its reference
/// "file:NAME.palette.json". Throws PaletteError for a bad name, IoError when it cannot be written.
std::string savePaletteGradient(const std::filesystem::path& folder, const std::string& name,
                                const std::vector<PaletteKey>& keys);

/// The keys the palette editor starts from for `settings`: the keys being edited
/// (palette_keys), the keys of a palette file that has them, else 16 keys sampled from the
/// palette. Without the hue turn, which stays a setting. Throws PaletteError when the palette
/// cannot be read.
std::vector<PaletteKey> keysToEdit(const FlameSettings& settings, const std::filesystem::path& projectFolder = {});

/// The palette of a flame display: the gradient keys when `settings.palette_keys` is set, else
/// the palette reference (resolvePalette, relative to `projectFolder`), with its hue turned by
/// `settings.hue` (rotatePaletteHue, flam3's `hue`). Throws PaletteError as resolvePalette does.
Palette resolveFlamePalette(const FlameSettings& settings, const std::filesystem::path& projectFolder = {});

}  // namespace gridifs
