#include "tone/palette_gradient.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "base/atomic_file.h"

namespace gridifs {

Palette paletteFromKeys(const std::vector<PaletteKey>& keys, const std::string& name) {
  Palette p;
  p.name = name;
  if (keys.empty()) return p;
  std::vector<PaletteKey> sorted = keys;
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const PaletteKey& a, const PaletteKey& b) { return a.position < b.position; });
  for (int i = 0; i < Palette::kSize; ++i) {
    const double t = i / double(Palette::kSize - 1);
    // The last key at or before t and the first after it.
    std::size_t after = 0;
    while (after < sorted.size() && sorted[after].position <= t) ++after;
    Rgb& out = p.colors[std::size_t(i)];
    if (after == 0) {
      out = {sorted.front().r, sorted.front().g, sorted.front().b};
    } else if (after == sorted.size()) {
      out = {sorted.back().r, sorted.back().g, sorted.back().b};
    } else {
      const PaletteKey& a = sorted[after - 1];
      const PaletteKey& b = sorted[after];
      const float f = float((t - a.position) / (b.position - a.position));
      out = {a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f};
    }
  }
  return p;
}

std::vector<PaletteKey> keysFromPalette(const Palette& palette, int count) {
  count = std::clamp(count, 2, int(kMaxPaletteKeys));
  std::vector<PaletteKey> keys;
  for (int k = 0; k < count; ++k) {
    const double position = k / double(count - 1);
    const Rgb& c = palette.colors[std::size_t(std::lround(position * (Palette::kSize - 1)))];
    keys.push_back({position, c.r, c.g, c.b});
  }
  return keys;
}

std::string serializeGradientPalette(const std::string& name, const std::vector<PaletteKey>& keys) {
  std::string text = serializePaletteJson(paletteFromKeys(keys, name));
  // The keys go before the colours: the same file, plus what the editor reopens.
  std::string block = "  \"keys\": [\n";
  char buffer[128];
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const PaletteKey& k = keys[i];
    std::snprintf(buffer, sizeof buffer, "    {\"position\": %.6g, \"color\": [%.4f, %.4f, %.4f]}%s\n", k.position,
                  double(k.r), double(k.g), double(k.b), i + 1 < keys.size() ? "," : "");
    block += buffer;
  }
  block += "  ],\n";
  const std::size_t colors = text.find("  \"colors\"");
  text.insert(colors, block);
  return text;
}

std::vector<PaletteKey> parseGradientKeys(const std::string& text) {
  const Palette palette = parsePaletteJson(text);  // checks the format and the colours
  const nlohmann::json j = nlohmann::json::parse(text);
  const auto keys = j.find("keys");
  if (keys == j.end()) return keysFromPalette(palette);
  if (!keys->is_array() || keys->size() < 2 || keys->size() > kMaxPaletteKeys)
    throw PaletteError("keys: expected an array of 2 to 64 keys.");
  std::vector<PaletteKey> out;
  for (std::size_t i = 0; i < keys->size(); ++i) {
    const auto& k = (*keys)[i];
    const std::string path = "keys[" + std::to_string(i) + "]";
    if (!k.is_object() || !k.contains("position") || !k["position"].is_number() || !k.contains("color") ||
        !k["color"].is_array() || k["color"].size() != 3)
      throw PaletteError(path + ": expected {\"position\": number, \"color\": [r, g, b]}.");
    PaletteKey key;
    key.position = k["position"].get<double>();
    if (!(key.position >= 0.0 && key.position <= 1.0))
      throw PaletteError(path + ": the position must be between 0 and 1.");
    float* channel[3] = {&key.r, &key.g, &key.b};
    for (int c = 0; c < 3; ++c) {
      const auto& v = k["color"][std::size_t(c)];
      if (!v.is_number() || !(v.get<double>() >= 0.0 && v.get<double>() <= 1.0))
        throw PaletteError(path + ": colour channels must be numbers between 0 and 1.");
      *channel[c] = v.get<float>();
    }
    out.push_back(key);
  }
  return out;
}

bool isPaletteFileName(const std::string& name) {
  if (name.empty() || name.size() > 64) return false;
  return std::all_of(name.begin(), name.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_'; });
}

std::string savePaletteGradient(const std::filesystem::path& folder, const std::string& name,
                                const std::vector<PaletteKey>& keys) {
  if (!isPaletteFileName(name))
    throw PaletteError("a palette name must be 1 to 64 letters, digits, '-' or '_', not \"" + name.substr(0, 64) +
                       "\".");
  if (keys.size() < 2 || keys.size() > kMaxPaletteKeys) throw PaletteError("a gradient needs 2 to 64 keys.");
  const std::string file = name + ".palette.json";
  writeFileAtomically((folder.empty() ? std::filesystem::path(".") : folder) / file,
                      serializeGradientPalette(name, keys));
  return "file:" + file;
}

std::vector<PaletteKey> keysToEdit(const FlameSettings& settings, const std::filesystem::path& projectFolder) {
  if (auto keys = parsePaletteKeys(settings.palette_keys)) return *keys;
  if (settings.palette.rfind("file:", 0) == 0) {
    std::filesystem::path file = settings.palette.substr(5);
    if (file.is_relative() && !projectFolder.empty()) file = projectFolder / file;
    if (file.extension() == ".json") {
      std::ifstream in(file, std::ios::binary);
      if (!in) throw PaletteError("cannot read the palette file " + file.string() + ".");
      std::ostringstream text;
      text << in.rdbuf();
      if (text.str().size() > (64u << 20)) throw PaletteError("the palette file " + file.string() + " is too large.");
      try {
        return parseGradientKeys(text.str());
      } catch (const PaletteError& e) {
        throw PaletteError("the palette file " + file.string() + " is invalid: " + e.what());
      }
    }
  }
  return keysFromPalette(resolvePalette(settings.palette, projectFolder));
}

Palette resolveFlamePalette(const FlameSettings& settings, const std::filesystem::path& projectFolder) {
  Palette palette;
  if (!settings.palette_keys.empty()) {
    const auto keys = parsePaletteKeys(settings.palette_keys);
    if (!keys) throw PaletteError("the palette's gradient keys are not \"POSITION:#RRGGBB\" words.");
    palette = paletteFromKeys(*keys);
  } else {
    palette = resolvePalette(settings.palette, projectFolder);
  }
  if (settings.hue != 0.0) palette = rotatePaletteHue(palette, settings.hue);
  return palette;
}

}  // namespace gridifs
