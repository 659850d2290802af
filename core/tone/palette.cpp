#include "tone/palette.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>
#include <sstream>

namespace gridifs {
namespace {

struct Stop {
  double at;
  Rgb color;
};

/// Linear interpolation of gradient stops into 256 entries (entry i sits at i/255).
std::array<Rgb, Palette::kSize> fromStops(const std::vector<Stop>& stops) {
  std::array<Rgb, Palette::kSize> out{};
  for (int i = 0; i < Palette::kSize; ++i) {
    const double t = i / double(Palette::kSize - 1);
    std::size_t s = 0;
    while (s + 2 < stops.size() && t > stops[s + 1].at) ++s;
    const Stop& a = stops[s];
    const Stop& b = stops[std::min(s + 1, stops.size() - 1)];
    const double span = b.at - a.at;
    const float f = span > 0 ? float(std::clamp((t - a.at) / span, 0.0, 1.0)) : 0.f;
    out[i] = {a.color.r + (b.color.r - a.color.r) * f, a.color.g + (b.color.g - a.color.g) * f,
              a.color.b + (b.color.b - a.color.b) * f};
  }
  return out;
}

// Built-in palettes: hand-made gradients in the spirit of flame palettes (bright, saturated,
// no black entries, so every function stays visible). assets/palettes/*.json hold the same
// data for artists; tests/core/test_flame_palette.cpp checks that both agree.
const std::vector<std::pair<std::string, std::vector<Stop>>>& builtinStops() {
  static const std::vector<std::pair<std::string, std::vector<Stop>>> kStops = {
      {"ember",
       {{0.0, {0.45f, 0.03f, 0.02f}},
        {0.3, {0.85f, 0.18f, 0.03f}},
        {0.55, {1.0f, 0.55f, 0.08f}},
        {0.8, {1.0f, 0.85f, 0.35f}},
        {1.0, {1.0f, 0.97f, 0.85f}}}},
      {"ice",
       {{0.0, {0.05f, 0.10f, 0.45f}},
        {0.35, {0.10f, 0.40f, 0.85f}},
        {0.7, {0.35f, 0.85f, 1.0f}},
        {1.0, {0.92f, 0.98f, 1.0f}}}},
      {"aurora",
       {{0.0, {0.35f, 0.10f, 0.60f}},
        {0.3, {0.15f, 0.35f, 0.95f}},
        {0.6, {0.10f, 0.85f, 0.55f}},
        {0.85, {0.75f, 0.95f, 0.25f}},
        {1.0, {1.0f, 0.90f, 0.55f}}}},
      {"sunset",
       {{0.0, {0.20f, 0.08f, 0.45f}},
        {0.3, {0.75f, 0.15f, 0.55f}},
        {0.6, {1.0f, 0.40f, 0.25f}},
        {0.85, {1.0f, 0.72f, 0.20f}},
        {1.0, {1.0f, 0.92f, 0.60f}}}},
      {"spectrum",
       {{0.0, {1.0f, 0.15f, 0.15f}},
        {1.0 / 6, {1.0f, 0.85f, 0.10f}},
        {2.0 / 6, {0.25f, 1.0f, 0.20f}},
        {3.0 / 6, {0.10f, 0.95f, 0.95f}},
        {4.0 / 6, {0.20f, 0.35f, 1.0f}},
        {5.0 / 6, {0.90f, 0.20f, 1.0f}},
        {1.0, {1.0f, 0.15f, 0.45f}}}},
      {"gray", {{0.0, {0.25f, 0.25f, 0.25f}}, {1.0, {1.0f, 1.0f, 1.0f}}}},
  };
  return kStops;
}

int hexDigit(char ch) {
  if (ch >= '0' && ch <= '9') return ch - '0';
  if (ch >= 'a' && ch <= 'f') return ch - 'a' + 10;
  if (ch >= 'A' && ch <= 'F') return ch - 'A' + 10;
  return -1;
}

std::string readText(const std::filesystem::path& file, const char* what) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw PaletteError(std::string("cannot read the ") + what + " " + file.string() + ".");
  std::ostringstream s;
  s << in.rdbuf();
  if (s.str().size() > (64u << 20))
    throw PaletteError("the " + std::string(what) + " " + file.string() + " is too large.");
  return s.str();
}

}  // namespace

Rgb Palette::lookup(double c) const {
  // Draves & Reckase 2003, §5 with flam3's linear palette mode: index = c·256, blend entries i and i+1.
  const double index = c * kSize;
  int i0;
  double frac;
  if (!(index >= 0.0)) {  // also catches NaN
    i0 = 0;
    frac = 0.0;
  } else if (index >= kSize - 1) {
    i0 = kSize - 2;
    frac = 1.0;
  } else {
    i0 = int(index);
    frac = index - i0;
  }
  const Rgb& a = colors[i0];
  const Rgb& b = colors[i0 + 1];
  const float f = float(frac);
  return {a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f};
}

std::vector<Palette> parseFlam3Palettes(const std::string& xmlText) {
  pugi::xml_document document;
  const pugi::xml_parse_result parsed = document.load_buffer(xmlText.data(), xmlText.size());
  if (!parsed)
    throw PaletteError(std::string("the flam3 palette XML is not well-formed (") + parsed.description() + " at byte " +
                       std::to_string(parsed.offset) + ").");
  std::vector<Palette> out;
  // flam3-palettes.xml is <palettes><palette number="" name="" data=""/>...</palettes>; a
  // single <palette> element (a palette file of its own) is read the same way.
  for (const pugi::xpath_node& node : document.select_nodes("//palette")) {
    const pugi::xml_node element = node.node();
    Palette p;
    const std::string number = element.attribute("number").value();
    p.name = element.attribute("name").value();
    if (p.name.empty()) p.name = number;
    // The digits without the whitespace between them, read in place: every flame render reads
    // the whole collection (~700 palettes) before its chaos game starts.
    const char* data = element.attribute("data").value();
    char hex[Palette::kSize * 8];
    std::size_t digits = 0;
    for (const char* c = data; *c; ++c) {
      const char ch = *c;
      if (ch == ' ' || ch == '\n' || ch == '\r' || ch == '\t' || ch == '\v' || ch == '\f') continue;
      if (digits < sizeof hex) hex[digits] = ch;
      ++digits;
    }
    if (digits != sizeof hex)
      throw PaletteError("flam3 palette " + number + " has " + std::to_string(digits / 8) + " entries instead of 256.");
    for (int i = 0; i < Palette::kSize; ++i) {
      int bytes[4];
      for (int b = 0; b < 4; ++b) {
        const int hi = hexDigit(hex[i * 8 + b * 2]), lo = hexDigit(hex[i * 8 + b * 2 + 1]);
        if (hi < 0 || lo < 0) throw PaletteError("flam3 palette " + number + " has a non-hex digit.");
        bytes[b] = hi * 16 + lo;
      }
      // Entries are "00RRGGBB" (the first byte is unused).
      p.colors[i] = {bytes[1] / 255.f, bytes[2] / 255.f, bytes[3] / 255.f};
    }
    out.push_back(std::move(p));
  }
  if (out.empty()) throw PaletteError("the flam3 palette XML contains no <palette> element.");
  return out;
}

const std::vector<Palette>& flam3Palettes(const std::filesystem::path& file) {
  static std::mutex mutex;
  static std::map<std::string, std::vector<Palette>> cache;
  std::lock_guard lock(mutex);
  auto it = cache.find(file.string());
  if (it != cache.end()) return it->second;
  std::vector<Palette> parsed = parseFlam3Palettes(readText(file, "flam3 palette collection"));
  return cache.emplace(file.string(), std::move(parsed)).first->second;
}

Palette flam3Palette(const std::string& numberOrName, const std::filesystem::path& file) {
  const auto& all = flam3Palettes(file);
  const bool numeric = !numberOrName.empty() && std::all_of(numberOrName.begin(), numberOrName.end(),
                                                            [](char ch) { return ch >= '0' && ch <= '9'; });
  if (numeric && numberOrName.size() < 9) {
    // flam3 numbers its palettes 0..N-1 in file order.
    const std::size_t n = std::stoul(numberOrName);
    if (n < all.size()) return all[n];
    throw PaletteError("flam3 has no palette number " + numberOrName + " (it has " + std::to_string(all.size()) + ").");
  }
  for (const Palette& p : all)
    if (p.name == numberOrName) return p;
  throw PaletteError("flam3 has no palette named \"" + numberOrName.substr(0, 64) + "\".");
}

Palette parsePaletteJson(const std::string& text) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error&) {
    throw PaletteError("the palette file is not valid JSON.");
  }
  if (!j.is_object()) throw PaletteError("the palette file must hold a JSON object.");
  if (auto f = j.find("format"); f == j.end() || !f->is_string() || f->get<std::string>() != "gridifs-palette")
    throw PaletteError("format: expected \"gridifs-palette\".");
  Palette p;
  if (auto n = j.find("name"); n != j.end()) {
    if (!n->is_string() || n->get<std::string>().size() > 256) throw PaletteError("name: expected a short string.");
    p.name = n->get<std::string>();
  }
  auto colors = j.find("colors");
  if (colors == j.end() || !colors->is_array() || colors->size() < 2 || colors->size() > 256)
    throw PaletteError("colors: expected an array of 2 to 256 [r, g, b] colors.");
  std::vector<Stop> stops;
  for (std::size_t i = 0; i < colors->size(); ++i) {
    const auto& c = (*colors)[i];
    const std::string path = "colors[" + std::to_string(i) + "]";
    if (!c.is_array() || c.size() != 3) throw PaletteError(path + ": expected [r, g, b].");
    float v[3];
    for (int k = 0; k < 3; ++k) {
      if (!c[k].is_number()) throw PaletteError(path + ": expected numbers.");
      const double x = c[k].get<double>();
      if (!(x >= 0.0 && x <= 1.0)) throw PaletteError(path + ": channels must be between 0 and 1.");
      v[k] = float(x);
    }
    stops.push_back({i / double(colors->size() - 1), {v[0], v[1], v[2]}});
  }
  if (stops.size() == std::size_t(Palette::kSize)) {
    for (int i = 0; i < Palette::kSize; ++i) p.colors[i] = stops[i].color;
  } else {
    p.colors = fromStops(stops);
  }
  return p;
}

std::string serializePaletteJson(const Palette& palette) {
  std::string out = "{\n  \"format\": \"gridifs-palette\",\n  \"name\": " + nlohmann::json(palette.name).dump() +
                    ",\n  \"colors\": [\n";
  char buffer[96];
  for (int i = 0; i < Palette::kSize; ++i) {
    const Rgb& c = palette.colors[i];
    std::snprintf(buffer, sizeof buffer, "    [%.4f, %.4f, %.4f]%s\n", c.r, c.g, c.b,
                  i + 1 < Palette::kSize ? "," : "");
    out += buffer;
  }
  out += "  ]\n}\n";
  return out;
}

Palette builtinPalette(const std::string& name) {
  for (const auto& [n, stops] : builtinStops())
    if (n == name) {
      Palette p;
      p.name = n;
      p.colors = fromStops(stops);
      return p;
    }
  throw PaletteError("there is no built-in palette named \"" + name.substr(0, 64) + "\".");
}

Palette resolvePalette(const std::string& reference, const std::filesystem::path& projectFolder) {
  if (reference.rfind("flam3:", 0) == 0) return flam3Palette(reference.substr(6));
  if (reference.rfind("file:", 0) == 0) {
    std::filesystem::path file = reference.substr(5);
    if (file.is_relative() && !projectFolder.empty()) file = projectFolder / file;
    const std::string text = readText(file, "palette file");
    if (file.extension() == ".xml") return parseFlam3Palettes(text).front();
    try {
      Palette p = parsePaletteJson(text);
      if (p.name.empty()) p.name = file.stem().string();
      return p;
    } catch (const PaletteError& e) {
      throw PaletteError("the palette file " + file.string() + " is invalid: " + e.what());
    }
  }
  return builtinPalette(reference);
}

namespace {

/// RGB in [0, 1] → hue in [0, 6), saturation and value in [0, 1] (the hexcone model).
std::array<double, 3> rgbToHsv(double r, double g, double b) {
  const double max = std::max({r, g, b}), min = std::min({r, g, b}), del = max - min;
  const double s = max > 0.0 ? del / max : 0.0;
  double h = 0.0;
  if (s > 0.0) {
    const double rc = (max - r) / del, gc = (max - g) / del, bc = (max - b) / del;
    if (r == max)
      h = bc - gc;
    else if (g == max)
      h = 2.0 + rc - bc;
    else
      h = 4.0 + gc - rc;
    if (h < 0.0) h += 6.0;
  }
  return {h, s, max};
}

std::array<double, 3> hsvToRgb(double h, double s, double v) {
  h = std::fmod(h, 6.0);
  if (h < 0.0) h += 6.0;
  const int sector = std::min(5, int(std::floor(h)));
  const double f = h - sector, p = v * (1.0 - s), q = v * (1.0 - s * f), t = v * (1.0 - s * (1.0 - f));
  switch (sector) {
    case 0:
      return {v, t, p};
    case 1:
      return {q, v, p};
    case 2:
      return {p, v, t};
    case 3:
      return {p, q, v};
    case 4:
      return {t, p, v};
    default:
      return {v, p, q};
  }
}

}  // namespace

Palette rotatePaletteHue(const Palette& palette, double turns) {
  Palette out = palette;
  for (Rgb& c : out.colors) {
    const auto hsv = rgbToHsv(c.r, c.g, c.b);
    const auto rgb = hsvToRgb(hsv[0] + 6.0 * turns, hsv[1], hsv[2]);
    c = {float(rgb[0]), float(rgb[1]), float(rgb[2])};
  }
  return out;
}

}  // namespace gridifs
