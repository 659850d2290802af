#pragma once
// flam3's deterministic variations (Draves & Reckase, "The Fractal Flame Algorithm", §3 and the
// appendix's catalogue, with the later variations as flam3 defines them): one table drives the
// importer's attribute parsing, evaluation and the list of supported names.
// Everything here is a pure function of its arguments: thread-safe.
#include <map>
#include <string>
#include <vector>

namespace gridifs {

/// A point of the flame's space. 2D genomes keep z at 0; the 3D extensions of JWildfire,
/// Fractorium and Apophysis 7X carry a z coordinate through the maps.
struct FlamePoint {
  double x = 0.0, y = 0.0, z = 0.0;
};

/// A flame affine map x' = a·x + b·y + c, y' = d·x + e·y + f (the file's `coefs` list these
/// in the order "a d b e c f").
struct FlameAffine {
  double a = 1.0, b = 0.0, c = 0.0, d = 0.0, e = 1.0, f = 0.0;
  FlamePoint apply(FlamePoint p) const { return {a * p.x + b * p.y + c, d * p.x + e * p.y + f, p.z}; }
  bool isIdentity() const { return a == 1.0 && b == 0.0 && c == 0.0 && d == 0.0 && e == 1.0 && f == 0.0; }
  bool operator==(const FlameAffine&) const = default;
};

/// What a variation sees: the point after the pre-affine map, the pre-affine coefficients (for
/// dependent variations such as waves, popcorn, rings and fan) and the xform's parameters.
struct VariationInput {
  double x = 0.0, y = 0.0;
  FlameAffine coefs;
  const std::map<std::string, double>* params = nullptr;
  double z = 0.0;  // the 3D extensions' z (planar variations ignore it)
};

struct FlameVariation {
  const char* name;
  /// Parameter attributes (`blob_low`, `pdj_a`, …) with flam3's defaults.
  std::vector<std::pair<const char*, double>> params;
  /// weight · V(p).
  FlamePoint (*apply)(const VariationInput& in, double weight);
};

/// The deterministic variations this importer evaluates, in flam3's numbering order.
const std::vector<FlameVariation>& flameVariations();
/// The variation named `name`, or null.
const FlameVariation* findFlameVariation(const std::string& name);
/// Whether `name` is a flam3 variation that draws random numbers (julia, blur, noise, …): it
/// has no closed form, so a grid cannot sample it.
bool isRandomFlameVariation(const std::string& name);
/// Whether `name` is the parameter attribute of a random variation (`julian_power`, …).
bool isRandomFlameVariationParameter(const std::string& name);

/// Whether variation `name` writes z (the 3D extensions: linear and linear3D carry it, zscale,
/// ztranslate and zcone add to it, flatten clears it). Every other variation is planar: its z
/// is 0 unless the genome asks to preserve z (JWildfire's `preserve_z`), then it carries w·z.
bool flameVariationWritesZ(const std::string& name);
/// Whether variation `name` is affine (linear, linear3D and the z variations except zcone).
bool isAffineFlameVariation(const std::string& name);

/// A parameter's value in `in.params`, or its default.
double variationParameter(const VariationInput& in, const char* name, double fallback);

}  // namespace gridifs
