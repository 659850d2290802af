#include "model/flame_settings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace gridifs {

const char* displayModeName(DisplayMode mode) {
  switch (mode) {
    case DisplayMode::Flame:
      return "flame";
    case DisplayMode::Shaded:
      return "shaded";
    default:
      return "zbuffer";
  }
}

bool parseDisplayMode(const std::string& text, DisplayMode& out) {
  if (text == "zbuffer")
    out = DisplayMode::ZBuffer;
  else if (text == "flame")
    out = DisplayMode::Flame;
  else if (text == "shaded")
    out = DisplayMode::Shaded;
  else
    return false;
  return true;
}

namespace {

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

/// "POSITION:#RRGGBB" → key; false when the word is anything else.
bool parseKey(const std::string& word, PaletteKey& key) {
  const std::size_t colon = word.find(':');
  if (colon == std::string::npos || colon == 0 || word.size() != colon + 8 || word[colon + 1] != '#') return false;
  const std::string number = word.substr(0, colon);
  char* end = nullptr;
  const double position = std::strtod(number.c_str(), &end);
  if (end != number.c_str() + number.size() || !(position >= 0.0 && position <= 1.0)) return false;
  float channel[3];
  for (int k = 0; k < 3; ++k) {
    const int hi = hexDigit(word[colon + 2 + 2 * k]), lo = hexDigit(word[colon + 3 + 2 * k]);
    if (hi < 0 || lo < 0) return false;
    channel[k] = float(hi * 16 + lo) / 255.f;
  }
  key = {position, channel[0], channel[1], channel[2]};
  return true;
}

}  // namespace

std::optional<std::vector<PaletteKey>> parsePaletteKeys(const std::string& text) {
  std::istringstream in(text);
  std::vector<PaletteKey> keys;
  std::string word;
  while (in >> word) {
    PaletteKey key;
    if (keys.size() >= kMaxPaletteKeys || !parseKey(word, key)) return std::nullopt;
    keys.push_back(key);
  }
  if (keys.size() < 2) return std::nullopt;
  return keys;
}

std::string formatPaletteKeys(const std::vector<PaletteKey>& keys) {
  std::string out;
  char buffer[48];
  for (const PaletteKey& k : keys) {
    auto byte = [](float v) { return int(std::lround(std::clamp(v, 0.f, 1.f) * 255.f)); };
    std::snprintf(buffer, sizeof buffer, "%s%.4g:#%02x%02x%02x", out.empty() ? "" : " ",
                  std::clamp(k.position, 0.0, 1.0), byte(k.r), byte(k.g), byte(k.b));
    out += buffer;
  }
  return out;
}

bool isPaletteKeysSyntax(const std::string& text) { return text.empty() || parsePaletteKeys(text).has_value(); }

bool isDensityDisplayName(const std::string& text) { return text == "log" || text == "linear" || text == "binary"; }

}  // namespace gridifs
