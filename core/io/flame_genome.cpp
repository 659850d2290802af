#include "io/flame_genome.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <pugixml.hpp>
#include <set>
#include <sstream>

#include "base/bounded_read.h"
#include "io/project_io.h"

namespace gridifs {
namespace {

[[noreturn]] void fail(const std::string& message) { throw FlameError(message); }

std::vector<double> numbers(const std::string& text, const std::string& what) {
  std::vector<double> out;
  std::istringstream in(text);
  std::string token;
  while (in >> token) {
    char* end = nullptr;
    const double v = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0')
      fail(what + " has \"" + token.substr(0, 32) + "\", which is not a number");
    if (!std::isfinite(v)) fail(what + " has a value that is not finite");
    if (std::fabs(v) > 1e12) fail(what + " has an absurdly large value");
    out.push_back(v);
    if (out.size() > 4096) fail(what + " has too many values");
  }
  return out;
}

double number(const pugi::xml_node& node, const char* name, double fallback, const std::string& where) {
  const pugi::xml_attribute a = node.attribute(name);
  if (!a) return fallback;
  const auto v = numbers(a.value(), where + " attribute " + name);
  if (v.empty()) fail(where + " attribute " + name + " is empty");
  return v[0];
}

FlameAffine affine(const std::string& text, const std::string& what) {
  const auto v = numbers(text, what);
  if (v.size() != 6) fail(what + " needs 6 numbers (a d b e c f), found " + std::to_string(v.size()));
  // The file's order is a d b e c f.
  return FlameAffine{v[0], v[2], v[4], v[1], v[3], v[5]};
}

const std::set<std::string>& structuralAttributes() {
  static const std::set<std::string> names = {
      "weight",  "color",   "color_speed", "symmetry",         "coefs",           "post",     "chaos",   "opacity",
      "name",    "animate", "var_color",   "motion_frequency", "motion_function", "plotmode", "visible", "yzCoefs",
      "zxCoefs", "yzPost",  "zxPost"};
  return names;
}

bool isVariationParameter(const std::string& name) {
  for (const FlameVariation& v : flameVariations())
    for (const auto& p : v.params)
      if (name == p.first) return true;
  return false;
}

FlameXform parseXform(const pugi::xml_node& node, const std::string& where, bool isFinal,
                      std::set<std::string>& unknownLeftOut) {
  FlameXform x;
  x.weight = number(node, "weight", isFinal ? 0.0 : 0.5, where);
  if (!isFinal && x.weight < 0.0) fail(where + " has a negative weight");
  x.color = std::clamp(number(node, "color", 0.0, where), 0.0, 1.0);
  if (node.attribute("color_speed"))
    x.color_speed = number(node, "color_speed", 0.5, where);
  else if (node.attribute("symmetry"))
    x.color_speed = (1.0 - number(node, "symmetry", 0.0, where)) / 2.0;
  else
    x.color_speed = isFinal ? 0.0 : 0.5;
  x.color_speed = std::clamp(x.color_speed, 0.0, 1.0);
  const pugi::xml_attribute coefs = node.attribute("coefs");
  if (!coefs) fail(where + " has no coefs");
  x.coefs = affine(coefs.value(), where + " coefs");
  if (const pugi::xml_attribute post = node.attribute("post")) x.post = affine(post.value(), where + " post");
  // JWildfire's 3D affine parts; an identity part is the same as none.
  auto part = [&](const char* name, std::optional<FlameAffine>& into) {
    if (const pugi::xml_attribute a = node.attribute(name)) {
      const FlameAffine m = affine(a.value(), where + " " + name);
      if (!m.isIdentity()) into = m;
    }
  };
  part("yzCoefs", x.yz);
  part("zxCoefs", x.zx);
  part("yzPost", x.postYz);
  part("zxPost", x.postZx);
  if (const pugi::xml_attribute chaos = node.attribute("chaos")) {
    x.chaos = numbers(chaos.value(), where + " chaos");
    for (double c : x.chaos)
      if (c < 0.0) fail(where + " chaos has a negative weight");
  }
  x.name = node.attribute("name").value();
  for (const pugi::xml_attribute a : node.attributes()) {
    const std::string name = a.name();
    if (structuralAttributes().count(name)) continue;
    if (findFlameVariation(name)) {
      const auto v = numbers(a.value(), where + " variation " + name);
      if (v.size() != 1) fail(where + " variation " + name + " needs one weight");
      if (v[0] != 0.0) x.variations.emplace_back(name, v[0]);
    } else if (isVariationParameter(name)) {
      const auto v = numbers(a.value(), where + " parameter " + name);
      if (v.size() != 1) fail(where + " parameter " + name + " needs one number");
      x.params[name] = v[0];
    } else {
      unknownLeftOut.insert(name);
    }
  }
  return x;
}

std::array<Rgb, Palette::kSize> hexPalette(const std::string& raw, const std::string& where) {
  std::string hex;
  for (char c : raw)
    if (!std::isspace(static_cast<unsigned char>(c))) hex += c;
  for (char c : hex)
    if (!std::isxdigit(static_cast<unsigned char>(c))) fail(where + " has a character that is not hexadecimal");
  // 6 hex digits per entry (RRGGBB, Apophysis) or 8 (00RRGGBB, flam3's `colors data`).
  const std::size_t digits = hex.size() == 256 * 8 ? 8 : 6;
  if (hex.size() != 256 * digits)
    fail(where + " needs 256 colors (" + std::to_string(hex.size()) + " hex digits found)");
  std::array<Rgb, Palette::kSize> colors{};
  for (int i = 0; i < 256; ++i) {
    const std::size_t at = std::size_t(i) * digits + (digits - 6);
    auto channel = [&](std::size_t k) { return float(std::stoi(hex.substr(at + 2 * k, 2), nullptr, 16)) / 255.0f; };
    colors[std::size_t(i)] = {channel(0), channel(1), channel(2)};
  }
  return colors;
}

FlameGenome parseGenome(const pugi::xml_node& flame, std::size_t index) {
  FlameGenome g;
  g.name = flame.attribute("name").value();
  const std::string where = "genome " + std::to_string(index) + (g.name.empty() ? "" : " \"" + g.name + "\"");
  if (const pugi::xml_attribute size = flame.attribute("size")) {
    const auto v = numbers(size.value(), where + " size");
    if (v.size() != 2) fail(where + " size needs a width and a height");
    if (!(v[0] >= 1 && v[0] <= flame_limits::kMaxImageSize && v[1] >= 1 && v[1] <= flame_limits::kMaxImageSize))
      fail(where + " size must be between 1 and " + std::to_string(flame_limits::kMaxImageSize) + " pixels");
    g.width = int(v[0]);
    g.height = int(v[1]);
  } else {
    fail(where + " has no size");
  }
  if (const pugi::xml_attribute center = flame.attribute("center")) {
    const auto v = numbers(center.value(), where + " center");
    if (v.size() != 2) fail(where + " center needs two numbers");
    g.centerX = v[0];
    g.centerY = v[1];
  }
  g.scale = number(flame, "scale", 0.0, where);
  if (!(g.scale > 0.0)) g.scale = g.width / 4.0;  // flam3's default: the width spans 4 units
  g.zoom = number(flame, "zoom", 0.0, where);
  if (std::fabs(g.zoom) > 40.0) fail(where + " zoom is out of range");
  g.rotate = number(flame, "rotate", 0.0, where);
  g.quality = number(flame, "quality", g.quality, where);
  if (!(g.quality > 0.0 && g.quality <= flame_limits::kMaxQuality))
    fail(where + " quality must be positive and at most " + std::to_string(int(flame_limits::kMaxQuality)));
  g.supersample = int(number(flame, "supersample", number(flame, "oversample", 1.0, where), where));
  if (g.supersample < 1 || g.supersample > 16) fail(where + " supersample must be between 1 and 16");
  g.filter = number(flame, "filter", g.filter, where);
  g.brightness = number(flame, "brightness", g.brightness, where);
  g.gamma = number(flame, "gamma", g.gamma, where);
  g.gamma_threshold = number(flame, "gamma_threshold", g.gamma_threshold, where);
  g.vibrancy = number(flame, "vibrancy", g.vibrancy, where);
  g.highlight_power = number(flame, "highlight_power", g.highlight_power, where);
  if (const pugi::xml_attribute bg = flame.attribute("background")) {
    const auto v = numbers(bg.value(), where + " background");
    if (v.size() != 3) fail(where + " background needs three numbers");
    for (int c = 0; c < 3; ++c) g.background[std::size_t(c)] = std::clamp(v[std::size_t(c)], 0.0, 1.0);
  }
  g.estimator_radius = number(flame, "estimator_radius", g.estimator_radius, where);
  g.estimator_minimum = number(flame, "estimator_minimum", g.estimator_minimum, where);
  g.estimator_curve = number(flame, "estimator_curve", g.estimator_curve, where);
  if (flame.attribute("palette")) g.paletteNumber = int(number(flame, "palette", -1.0, where));
  g.hue = number(flame, "hue", 0.0, where);
  g.camPitch = number(flame, "cam_pitch", 0.0, where);
  g.camYaw = number(flame, "cam_yaw", 0.0, where);
  // JWildfire writes cam_persp, Apophysis 7X and Fractorium cam_perspective.
  g.camPerspective = number(flame, "cam_persp", number(flame, "cam_perspective", 0.0, where), where);
  g.camZpos = number(flame, "cam_zpos", 0.0, where);
  g.camZoom = number(flame, "cam_zoom", 1.0, where);
  g.camDof = number(flame, "cam_dof", 0.0, where);
  if (!(std::fabs(g.camDof) <= 1e3)) fail(where + " cam_dof is out of range");
  if (!(g.camZoom > 1e-6 && g.camZoom < 1e6)) fail(where + " cam_zoom is out of range");
  if (std::fabs(g.camPitch) > 1e3 || std::fabs(g.camYaw) > 1e3) fail(where + " cam_pitch or cam_yaw is out of range");
  if (std::fabs(g.camPerspective) > 1e3 || std::fabs(g.camZpos) > 1e6)
    fail(where + " cam_perspective or cam_zpos is out of range");
  const bool preserveZ = number(flame, "preserve_z", number(flame, "new_linear", 0.0, where), where) != 0.0;
  if (const pugi::xml_attribute hint = flame.attribute("gridifs_frame")) {
    const auto v = numbers(hint.value(), where + " gridifs_frame");
    if (v.size() != 3 || !(v[2] > 0.0)) fail(where + " gridifs_frame needs a centre and a positive scale");
    g.frameHint = std::array<double, 3>{v[0], v[1], v[2]};
  }

  std::set<std::string> unknownLeftOut;
  std::array<Rgb, Palette::kSize> colors{};
  int colorEntries = 0;
  for (const pugi::xml_node child : flame.children()) {
    const std::string tag = child.name();
    if (tag == "xform") {
      if (g.xforms.size() >= std::size_t(flame_limits::kMaxXforms))
        fail(where + " has more than " + std::to_string(flame_limits::kMaxXforms) + " xforms");
      g.xforms.push_back(parseXform(child, where + " xform " + std::to_string(g.xforms.size()), false, unknownLeftOut));
      g.xforms.back().preserveZ = preserveZ;
    } else if (tag == "finalxform") {
      if (g.finalXform) fail(where + " has more than one finalxform");
      g.finalXform = parseXform(child, where + " finalxform", true, unknownLeftOut);
      g.finalXform->preserveZ = preserveZ;
    } else if (tag == "color") {
      const int i = int(number(child, "index", -1.0, where + " color"));
      if (i < 0 || i > 255) fail(where + " has a color entry whose index is not in 0..255");
      const auto rgb = numbers(child.attribute("rgb").value(), where + " color rgb");
      if (rgb.size() != 3) fail(where + " has a color entry without three rgb values");
      colors[std::size_t(i)] = {float(std::clamp(rgb[0], 0.0, 255.0) / 255.0),
                                float(std::clamp(rgb[1], 0.0, 255.0) / 255.0),
                                float(std::clamp(rgb[2], 0.0, 255.0) / 255.0)};
      ++colorEntries;
    } else if (tag == "palette") {
      Palette p;
      p.name = g.name.empty() ? "imported" : g.name;
      p.colors = hexPalette(child.text().get(), where + " palette");
      g.palette = p;
    } else if (tag == "colors") {
      Palette p;
      p.name = g.name.empty() ? "imported" : g.name;
      p.colors = hexPalette(child.attribute("data").value(), where + " colors");
      g.palette = p;
    }
  }
  if (!g.palette && colorEntries > 0) {
    Palette p;
    p.name = g.name.empty() ? "imported" : g.name;
    p.colors = colors;
    g.palette = p;
  }
  if (g.xforms.empty()) fail(where + " has no xforms");
  g.threeD = g.camPitch != 0.0 || g.camYaw != 0.0 || g.camPerspective != 0.0;
  for (const FlameXform& x : g.xforms) g.threeD |= x.isThreeD();
  if (g.finalXform) g.threeD |= g.finalXform->isThreeD();
  // What a GridIFS scene cannot hold: fog, moved camera positions.
  std::string camera;
  for (const char* name : {"cam_zdimish", "cam_pos_x", "cam_pos_y", "cam_pos_z"})
    if (number(flame, name, 0.0, where) != 0.0) camera += std::string(camera.empty() ? "" : ", ") + name;
  if (!camera.empty())
    g.warnings.push_back("the camera settings " + camera + " have no GridIFS equivalent and were left out");
  if (!unknownLeftOut.empty()) {
    std::string list;
    for (const auto& n : unknownLeftOut) list += (list.empty() ? "" : ", ") + n;
    g.warnings.push_back("unknown or unsupported attributes were left out: " + list);
  }
  return g;
}

}  // namespace

double FlameGenome::pixelsPerUnit() const { return scale * std::pow(2.0, zoom) * camZoom; }

namespace {

/// An affine map with JWildfire's 3D parts: the xy part's linear terms, then yz mixes y and z,
/// then zx mixes x and z, then all translations add (JWildfire's full affine step).
FlamePoint applyAffine3(const FlameAffine& xy, const std::optional<FlameAffine>& yz,
                        const std::optional<FlameAffine>& zx, FlamePoint p) {
  if (!yz && !zx) return xy.apply(p);
  double x = xy.a * p.x + xy.b * p.y, y = xy.d * p.x + xy.e * p.y, z = p.z;
  double tx = xy.c, ty = xy.f, tz = 0.0;
  if (yz) {
    const double ny = yz->a * y + yz->b * z, nz = yz->d * y + yz->e * z;
    y = ny;
    z = nz;
    ty += yz->c;
    tz += yz->f;
  }
  if (zx) {
    const double nx = zx->a * x + zx->b * z, nz = zx->d * x + zx->e * z;
    x = nx;
    z = nz;
    tx += zx->c;
    tz += zx->f;
  }
  return {x + tx, y + ty, z + tz};
}

}  // namespace

bool isGenomeZVariation(const std::string& name) {
  return name == "linear" || name == "linear3D" || name == "zscale" || name == "ztranslate" || name == "zcone" ||
         name == "flatten";
}

bool flipsSignWithZ(const std::string& name) { return name == "ztranslate" || name == "zcone"; }

FlamePoint FlameXform::preAffine(FlamePoint p) const { return applyAffine3(coefs, yz, zx, p); }
FlamePoint FlameXform::postAffine(FlamePoint p) const { return applyAffine3(post, postYz, postZx, p); }

FlamePoint FlameXform::apply(FlamePoint p) const {
  const FlamePoint t = applyAffine3(coefs, yz, zx, p);
  FlamePoint sum;
  bool flatten = false;
  std::uint64_t random = 0x9E3779B97F4A7C15ull;  // only the importer's extent search evaluates random ones
  for (const auto& [name, weight] : variations) {
    const FlameVariation* v = findFlameVariation(name);
    std::vector<double> values;
    for (const auto& [attribute, fallback] : v->params) {
      const auto it = params.find(attribute);
      values.push_back(it == params.end() ? fallback : it->second);
    }
    // The genome's own 3D semantics (Apophysis 7X, JWildfire): planar variations see the plane
    // and drop z unless the genome preserves it; only the z variations and linear write z.
    const bool zVariation = isGenomeZVariation(name);
    const VariationInput in{t.x, t.y, zVariation ? t.z : 0.0, &coefs, values.data(), &random};
    const FlamePoint q = v->apply(in, weight);
    sum.x += q.x;
    sum.y += q.y;
    if (zVariation)
      sum.z += q.z;
    else if (preserveZ)
      sum.z += weight * t.z;
    flatten |= name == "flatten";
  }
  if (flatten) sum.z = 0.0;
  return applyAffine3(post, postYz, postZx, sum);
}

bool FlameXform::isAffine() const {
  return std::all_of(variations.begin(), variations.end(),
                     [](const auto& v) { return isAffineFlameVariation(v.first); });
}

bool FlameXform::xyDependsOnZ() const {
  // The pre-affine's x and y at z = 1 and z = 0 differ exactly when z is mixed in.
  const FlamePoint a = applyAffine3(coefs, yz, zx, {0.0, 0.0, 0.0}), b = applyAffine3(coefs, yz, zx, {0.0, 0.0, 1.0});
  return a.x != b.x || a.y != b.y;
}

bool FlameXform::isThreeD() const {
  if (yz || zx || postYz || postZx) return true;
  return std::any_of(variations.begin(), variations.end(),
                     [](const auto& v) { return isGenomeZVariation(v.first) && v.first != "linear"; });
}

std::vector<FlameGenome> parseFlameFile(const std::string& xmlText) {
  if (xmlText.size() > flame_limits::kMaxFileBytes) fail("the file is larger than 64 MiB");
  if (xmlText.find_first_not_of(" \t\r\n") == std::string::npos) fail("the file is empty");
  pugi::xml_document doc;
  const pugi::xml_parse_result result = doc.load_buffer(xmlText.data(), xmlText.size());
  if (!result) {
    std::size_t line = 1;
    for (std::ptrdiff_t i = 0; i < result.offset && std::size_t(i) < xmlText.size(); ++i)
      line += xmlText[std::size_t(i)] == '\n';
    fail(std::string("the XML is malformed (") + result.description() + " at line " + std::to_string(line) + ")");
  }
  // Walk iteratively with a depth limit: no recursion a hostile file could exhaust.
  std::vector<pugi::xml_node> flames;
  std::vector<std::pair<pugi::xml_node, int>> stack{{doc, 0}};
  while (!stack.empty()) {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    if (depth > flame_limits::kMaxDepth)
      fail("the XML is nested more than " + std::to_string(flame_limits::kMaxDepth) + " levels deep");
    if (std::string(node.name()) == "flame") {
      flames.push_back(node);
      continue;
    }
    std::vector<pugi::xml_node> children;
    for (const pugi::xml_node c : node.children())
      if (c.type() == pugi::node_element) children.push_back(c);
    for (auto it = children.rbegin(); it != children.rend(); ++it) stack.emplace_back(*it, depth + 1);
  }
  if (flames.empty()) fail("the file has no <flame> genome");
  std::vector<FlameGenome> genomes;
  for (std::size_t i = 0; i < flames.size(); ++i) genomes.push_back(parseGenome(flames[i], i));
  return genomes;
}

std::vector<FlameGenome> loadFlameFile(const std::filesystem::path& file) {
  const std::optional<std::string> text = readBoundedFile(file, flame_limits::kMaxFileBytes, "flame file");
  if (!text) fail("the file is larger than 64 MiB");
  return parseFlameFile(*text);
}

const FlameGenome& selectGenome(const std::vector<FlameGenome>& genomes, const std::string& indexOrName) {
  if (indexOrName.empty()) return genomes.front();
  for (const FlameGenome& g : genomes)
    if (g.name == indexOrName) return g;
  if (indexOrName.find_first_not_of("0123456789") == std::string::npos && indexOrName.size() < 9) {
    const std::size_t i = std::stoul(indexOrName);
    if (i < genomes.size()) return genomes[i];
    fail("there is no genome " + indexOrName + " (the file has " + std::to_string(genomes.size()) + ")");
  }
  fail("there is no genome named \"" + indexOrName + "\"");
}

}  // namespace gridifs
