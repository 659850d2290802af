#pragma once
// The flame variations (Draves & Reckase, "The Fractal Flame Algorithm", §3 and the appendix's
// catalogue, with the later ones as flam3 3.1 defines them): one table drives the model's
// evaluation (a function's f(p) = post(Σ w_i V_i(g(p)))), the .flame importer and exporter, the
// modeller's list and the GPU renderer's numbering.
//
// 3D forms. Each variation acts on the point (x, y, z) and equals flam3's on the z = 0 plane:
// - the planar ones (most of the catalogue) act on (x, y) and carry z as w·z, so that a blend whose
//   weights sum to 1 keeps z (JWildfire's and Apophysis 7X's "preserve z");
// - linear, spherical, bubble and eyefish have the natural 3D form (linear: w·p; spherical:
//   w·p/|p|²; bubble: w·p/(|p|²/4 + 1); eyefish: 2w·p/(|p| + 1));
// - the random ones (julia, blur, …) are planar too: they draw flam3's 2D values and carry w·z;
// - zscale, ztranslate, zcone and flatten are the z variations of Apophysis 7X's 3D extension.
// Everything here is a pure function of its arguments (random ones advance only the stream they
// are handed): thread-safe.
#include <cstdint>
#include <string>
#include <vector>

namespace gridifs {

/// A point of the flame's space; 2D genomes keep z at 0.
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

/// The random numbers a random variation draws: the chaos game's own stream (wyrand, Wang Yi),
/// so a render stays a function of its seed. `state` is the stream's state, advanced in place.
/// Inline: the batched variations draw up to eight per round of the chaos game.
inline double variationUniform(std::uint64_t& state) {
  // The chaos kernel's generator (render/chaos_kernel.h Rng::next), 53 bits into [0, 1).
  state += 0xA0761D6478BD642Full;
  const unsigned __int128 m = (unsigned __int128)state * (state ^ 0xE7037ED1A0B428DBull);
  const std::uint64_t bits = std::uint64_t(m >> 64) ^ std::uint64_t(m);
  return double(bits >> 11) * 0x1.0p-53;
}

/// What a variation sees: the point (after the function's grid map, or the genome's pre-affine
/// map), the affine coefficients that the dependent variations (waves, popcorn, rings, fan) read,
/// its parameters in its table order, and the sample's random stream.
struct VariationInput {
  double x = 0.0, y = 0.0, z = 0.0;
  const FlameAffine* coefs = nullptr;
  const double* param = nullptr;
  std::uint64_t* random = nullptr;  // required by random variations (FlameVariation::random)
};

struct FlameVariation {
  const char* name;
  /// Parameter attributes (`blob_low`, `pdj_a`, …) with flam3's defaults, in the order `param` lists them.
  std::vector<std::pair<const char*, double>> params;
  /// weight · V(p), x, y and (for the variations that write z) z.
  FlamePoint (*apply)(const VariationInput& in, double weight);
  /// Draws random numbers (julia, blur, noise, …).
  bool random = false;
  /// A pre-variation (pre_blur): it moves the point every other variation of the function sees
  /// and contributes nothing itself.
  bool pre = false;
  /// Writes z itself (linear, the 3D forms, the z variations); the others carry w·z.
  bool writesZ = false;
  /// Reads the function's affine coefficients (waves, popcorn, rings, fan).
  bool dependent = false;
};

/// Every variation, in flam3's numbering order, then the 3D extensions.
const std::vector<FlameVariation>& flameVariations();
/// The variation named `name`, or null.
const FlameVariation* findFlameVariation(const std::string& name);
/// Its index in flameVariations(), or -1.
int flameVariationIndex(const std::string& name);
/// The variation and parameter index a parameter attribute (`julian_power`) belongs to; false when
/// no variation has it.
bool findVariationParameter(const std::string& attribute, int& variation, int& parameter);

/// Whether variation `name` writes z itself (see the 3D forms above).
bool flameVariationWritesZ(const std::string& name);
/// Whether variation `name` is affine (linear, linear3D and the z variations except zcone).
bool isAffineFlameVariation(const std::string& name);
/// Whether `name` is a variation that draws random numbers.
bool isRandomFlameVariation(const std::string& name);

/// One evaluation of a weighted variation list, as the chaos game runs it: the pre-variations
/// move the point, then Σ w_i V_i, each planar one carrying w_i·z. `params[i]` holds variation
/// `terms[i]`'s parameters in table order. Returns the sum (before any post transform).
struct VariationTerm {
  const FlameVariation* variation;
  double weight;
  const double* params;
};
FlamePoint evaluateVariations(const VariationTerm* terms, std::size_t count, FlamePoint p, const FlameAffine& coefs,
                              std::uint64_t* random);

/// A term as the chaos kernel runs it: the variation's body by number (an inline dispatch, not a
/// call through FlameVariation::apply) and its flags at hand.
struct KernelVariationTerm {
  std::int32_t body = -1;
  bool pre = false, writesZ = false, flatten = false;
  double weight = 0.0;
  const double* params = nullptr;
};
/// The kernel form of `term` (whose variation is one of flameVariations()).
KernelVariationTerm makeKernelVariationTerm(const VariationTerm& term);
/// evaluateVariations as the chaos kernel runs it: the same terms, operations and random draws, with
/// sin, cos and atan2 from variations/kernel_math.h (within 1e-9 relative of the library's, far below
/// the renderer's float points) and the bodies inlined. `anyPre`: some term is a pre-variation.
FlamePoint evaluateKernelVariations(const KernelVariationTerm* terms, std::size_t count, bool anyPre, FlamePoint p,
                                    const FlameAffine& coefs, std::uint64_t* random);
/// The kernel's body of one term (KernelVariationTerm::body), compiled on its own: what a function
/// of a single term calls directly, without the loop over terms and the switch of
/// evaluateKernelVariations (the same operations and draws).
using KernelBodyFn = FlamePoint (*)(const VariationInput&, double);
KernelBodyFn kernelVariationBody(std::int32_t body);

}  // namespace gridifs
