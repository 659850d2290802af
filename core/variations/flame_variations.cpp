#include "variations/flame_variations.h"

#include <algorithm>
#include <cmath>

#include "variations/kernel_math.h"

namespace gridifs {
namespace {

// flam3's guard against division by zero.
constexpr double kEps = 1e-10;
constexpr double kPi = 3.14159265358979323846;

/// The reference math: the C library's, correctly rounded or nearly so.
struct PreciseMath {
  static double sin(double x) { return std::sin(x); }
  static double cos(double x) { return std::cos(x); }
  static double tan(double x) { return std::tan(x); }
  static double atan2(double y, double x) { return std::atan2(y, x); }
  static double sqrt(double x) { return std::sqrt(x); }
  static double exp(double x) { return std::exp(x); }
  static double log(double x) { return std::log(x); }
  static double log10(double x) { return std::log10(x); }
  static double pow(double x, double y) { return std::pow(x, y); }
  static double sinh(double x) { return std::sinh(x); }
  static double cosh(double x) { return std::cosh(x); }
  static double acos(double x) { return std::acos(x); }
};

/// The chaos kernel's math: sin, cos and atan2 inline and accurate far beyond the float chain state
/// (variations/kernel_math.h); the rarer functions stay the library's.
struct KernelMath : PreciseMath {
  [[gnu::always_inline]] static double sin(double x) { return kernel_math::sin(x); }
  [[gnu::always_inline]] static double cos(double x) { return kernel_math::cos(x); }
  [[gnu::always_inline]] static double atan2(double y, double x) { return kernel_math::atan2(y, x); }
};

// The variation bodies twice: once per math policy.
namespace precise {
using M = PreciseMath;
#include "variations/flame_variation_bodies.inc"
}  // namespace precise
namespace fast {
using M = KernelMath;
#include "variations/flame_variation_bodies.inc"
}  // namespace fast

// Every body once, for the kernel's dispatch (a switch, so the bodies inline into the loop over
// terms); the order here is free, the table below fixes the public numbering.
// clang-format off
#define GRIDIFS_VARIATION_BODIES(X)                                                                        \
  X(linear) X(sinusoidal) X(spherical) X(swirl) X(horseshoe) X(polar) X(handkerchief) X(heart) X(disc)     \
  X(spiral) X(hyperbolic) X(diamond) X(ex) X(julia) X(bent) X(waves) X(fisheye) X(popcorn) X(exponential)  \
  X(power) X(cosine) X(rings) X(fan) X(blob) X(pdj) X(fan2) X(rings2) X(eyefish) X(bubble) X(cylinder)     \
  X(perspective) X(noise) X(julian) X(juliascope) X(blur) X(gaussianBlur) X(radialBlur) X(pie) X(ngon)     \
  X(curl) X(rectangles) X(arch) X(tangent) X(square) X(rays) X(blade) X(secant2) X(twintrian) X(cross)     \
  X(disc2) X(superShape) X(flower) X(conic) X(parabola) X(bent2) X(bipolar) X(boarders) X(butterfly)       \
  X(cell) X(cpow) X(curve) X(edisc) X(elliptic) X(escher) X(foci) X(lazysusan) X(loonie) X(preBlur)        \
  X(modulus) X(oscilloscope) X(polar2) X(popcorn2) X(scry) X(separation) X(split) X(splits) X(stripes)    \
  X(wedge) X(wedgeJulia) X(wedgeSph) X(whorl) X(waves2) X(cexp) X(clog) X(csin) X(ccos) X(ctan) X(csec)    \
  X(ccsc) X(ccot) X(csinh) X(ccosh) X(ctanh) X(csech) X(ccsch) X(ccoth) X(auger) X(flux) X(mobius)         \
  X(zscale) X(ztranslate) X(zcone) X(flatten)
// clang-format on

namespace body {
#define GRIDIFS_ENUM(name) name,
enum Id : std::int32_t { GRIDIFS_VARIATION_BODIES(GRIDIFS_ENUM) kCount };
#undef GRIDIFS_ENUM
}  // namespace body

using ApplyFn = FlamePoint (*)(const VariationInput&, double);
#define GRIDIFS_POINTER(name) precise::name,
constexpr ApplyFn kPreciseBodies[] = {GRIDIFS_VARIATION_BODIES(GRIDIFS_POINTER)};
#undef GRIDIFS_POINTER

// Each kernel body on its own, with the helpers and draws inlined (kernelVariationBody).
#define GRIDIFS_KERNEL_BODY(name) \
  [[gnu::flatten]] FlamePoint kernel_##name(const VariationInput& in, double w) { return fast::name(in, w); }
GRIDIFS_VARIATION_BODIES(GRIDIFS_KERNEL_BODY)
#undef GRIDIFS_KERNEL_BODY
#define GRIDIFS_KERNEL_POINTER(name) kernel_##name,
constexpr ApplyFn kKernelBodies[] = {GRIDIFS_VARIATION_BODIES(GRIDIFS_KERNEL_POINTER)};
#undef GRIDIFS_KERNEL_POINTER

/// One term of the kernel's sum, its body inlined by the switch.
[[gnu::always_inline]] inline FlamePoint applyKernelBody(std::int32_t id, const VariationInput& in, double w) {
  switch (id) {
#define GRIDIFS_CASE(name) \
  case body::name:         \
    return fast::name(in, w);
    GRIDIFS_VARIATION_BODIES(GRIDIFS_CASE)
#undef GRIDIFS_CASE
    default:
      return {};
  }
}

}  // namespace

const std::vector<FlameVariation>& flameVariations() {
  using namespace precise;
  // Flags: random, pre, writesZ, dependent.
  static const std::vector<FlameVariation> table = {
      {"linear", {}, linear, false, false, true},
      {"sinusoidal", {}, sinusoidal},
      {"spherical", {}, spherical, false, false, true},
      {"swirl", {}, swirl},
      {"horseshoe", {}, horseshoe},
      {"polar", {}, polar},
      {"handkerchief", {}, handkerchief},
      {"heart", {}, heart},
      {"disc", {}, disc},
      {"spiral", {}, spiral},
      {"hyperbolic", {}, hyperbolic},
      {"diamond", {}, diamond},
      {"ex", {}, ex},
      {"julia", {}, julia, true},
      {"bent", {}, bent},
      {"waves", {}, waves, false, false, false, true},
      {"fisheye", {}, fisheye},
      {"popcorn", {}, popcorn, false, false, false, true},
      {"exponential", {}, exponential},
      {"power", {}, power},
      {"cosine", {}, cosine},
      {"rings", {}, rings, false, false, false, true},
      {"fan", {}, fan, false, false, false, true},
      {"blob", {{"blob_low", 0.0}, {"blob_high", 1.0}, {"blob_waves", 1.0}}, blob},
      {"pdj", {{"pdj_a", 0.0}, {"pdj_b", 0.0}, {"pdj_c", 0.0}, {"pdj_d", 0.0}}, pdj},
      {"fan2", {{"fan2_x", 0.0}, {"fan2_y", 0.0}}, fan2},
      {"rings2", {{"rings2_val", 0.0}}, rings2},
      {"eyefish", {}, eyefish, false, false, true},
      {"bubble", {}, bubble, false, false, true},
      {"cylinder", {}, cylinder},
      {"perspective", {{"perspective_angle", 0.0}, {"perspective_dist", 0.0}}, perspective},
      {"noise", {}, noise, true},
      {"julian", {{"julian_power", 1.0}, {"julian_dist", 1.0}}, julian, true},
      {"juliascope", {{"juliascope_power", 1.0}, {"juliascope_dist", 1.0}}, juliascope, true},
      {"blur", {}, blur, true},
      {"gaussian_blur", {}, gaussianBlur, true},
      {"radial_blur", {{"radial_blur_angle", 0.0}}, radialBlur, true},
      {"pie", {{"pie_slices", 6.0}, {"pie_rotation", 0.0}, {"pie_thickness", 0.5}}, pie, true},
      {"ngon", {{"ngon_sides", 5.0}, {"ngon_power", 3.0}, {"ngon_circle", 1.0}, {"ngon_corners", 2.0}}, ngon},
      {"curl", {{"curl_c1", 1.0}, {"curl_c2", 0.0}}, curl},
      {"rectangles", {{"rectangles_x", 1.0}, {"rectangles_y", 1.0}}, rectangles},
      {"arch", {}, arch, true},
      {"tangent", {}, tangent},
      {"square", {}, square, true},
      {"rays", {}, rays, true},
      {"blade", {}, blade, true},
      {"secant2", {}, secant2},
      {"twintrian", {}, twintrian, true},
      {"cross", {}, cross},
      {"disc2", {{"disc2_rot", 0.0}, {"disc2_twist", 0.0}}, disc2},
      {"super_shape",
       {{"super_shape_rnd", 0.0},
        {"super_shape_m", 0.0},
        {"super_shape_n1", 1.0},
        {"super_shape_n2", 1.0},
        {"super_shape_n3", 1.0},
        {"super_shape_holes", 0.0}},
       superShape,
       true},
      {"flower", {{"flower_petals", 0.0}, {"flower_holes", 0.0}}, flower, true},
      {"conic", {{"conic_eccentricity", 1.0}, {"conic_holes", 0.0}}, conic, true},
      {"parabola", {{"parabola_height", 0.0}, {"parabola_width", 0.0}}, parabola, true},
      {"bent2", {{"bent2_x", 1.0}, {"bent2_y", 1.0}}, bent2},
      {"bipolar", {{"bipolar_shift", 0.0}}, bipolar},
      {"boarders", {}, boarders, true},
      {"butterfly", {}, butterfly},
      {"cell", {{"cell_size", 1.0}}, cell},
      {"cpow", {{"cpow_r", 1.0}, {"cpow_i", 0.0}, {"cpow_power", 1.0}}, cpow, true},
      {"curve", {{"curve_xamp", 0.0}, {"curve_yamp", 0.0}, {"curve_xlength", 1.0}, {"curve_ylength", 1.0}}, curve},
      {"edisc", {}, edisc},
      {"elliptic", {}, elliptic},
      {"escher", {{"escher_beta", 0.0}}, escher},
      {"foci", {}, foci},
      {"lazysusan",
       {{"lazysusan_x", 0.0},
        {"lazysusan_y", 0.0},
        {"lazysusan_spin", 0.0},
        {"lazysusan_space", 0.0},
        {"lazysusan_twist", 0.0}},
       lazysusan},
      {"loonie", {}, loonie},
      {"pre_blur", {}, preBlur, true, true},
      {"modulus", {{"modulus_x", 0.0}, {"modulus_y", 0.0}}, modulus},
      {"oscilloscope",
       {{"oscilloscope_separation", 1.0},
        {"oscilloscope_frequency", kPi},
        {"oscilloscope_amplitude", 1.0},
        {"oscilloscope_damping", 0.0}},
       oscilloscope},
      {"polar2", {}, polar2},
      {"popcorn2", {{"popcorn2_x", 0.0}, {"popcorn2_y", 0.0}, {"popcorn2_c", 0.0}}, popcorn2},
      {"scry", {}, scry},
      {"separation",
       {{"separation_x", 0.0}, {"separation_xinside", 0.0}, {"separation_y", 0.0}, {"separation_yinside", 0.0}},
       separation},
      {"split", {{"split_xsize", 0.0}, {"split_ysize", 0.0}}, split},
      {"splits", {{"splits_x", 0.0}, {"splits_y", 0.0}}, splits},
      {"stripes", {{"stripes_space", 0.0}, {"stripes_warp", 0.0}}, stripes},
      {"wedge", {{"wedge_angle", 0.0}, {"wedge_hole", 0.0}, {"wedge_count", 1.0}, {"wedge_swirl", 0.0}}, wedge},
      {"wedge_julia",
       {{"wedge_julia_angle", 0.0}, {"wedge_julia_count", 1.0}, {"wedge_julia_power", 1.0}, {"wedge_julia_dist", 0.0}},
       wedgeJulia,
       true},
      {"wedge_sph",
       {{"wedge_sph_angle", 0.0}, {"wedge_sph_hole", 0.0}, {"wedge_sph_count", 1.0}, {"wedge_sph_swirl", 0.0}},
       wedgeSph},
      {"whorl", {{"whorl_inside", 0.0}, {"whorl_outside", 0.0}}, whorl},
      {"waves2",
       {{"waves2_freqx", 0.0}, {"waves2_scalex", 0.0}, {"waves2_freqy", 0.0}, {"waves2_scaley", 0.0}},
       waves2},
      {"exp", {}, cexp},
      {"log", {}, clog},
      {"sin", {}, csin},
      {"cos", {}, ccos},
      {"tan", {}, ctan},
      {"sec", {}, csec},
      {"csc", {}, ccsc},
      {"cot", {}, ccot},
      {"sinh", {}, csinh},
      {"cosh", {}, ccosh},
      {"tanh", {}, ctanh},
      {"sech", {}, csech},
      {"csch", {}, ccsch},
      {"coth", {}, ccoth},
      {"auger", {{"auger_freq", 1.0}, {"auger_weight", 0.5}, {"auger_sym", 0.0}, {"auger_scale", 1.0}}, auger},
      {"flux", {{"flux_spread", 0.0}}, flux},
      {"mobius",
       {{"mobius_re_a", 0.0},
        {"mobius_im_a", 0.0},
        {"mobius_re_b", 0.0},
        {"mobius_im_b", 0.0},
        {"mobius_re_c", 0.0},
        {"mobius_im_c", 0.0},
        {"mobius_re_d", 0.0},
        {"mobius_im_d", 0.0}},
       mobius},
      // The 3D extensions of Apophysis 7X (as JWildfire and Fractorium evaluate them).
      {"linear3D", {}, linear, false, false, true},
      {"zscale", {}, zscale, false, false, true},
      {"ztranslate", {}, ztranslate, false, false, true},
      {"zcone", {}, zcone, false, false, true},
      {"flatten", {}, flatten, false, false, true},
  };
  return table;
}

const FlameVariation* findFlameVariation(const std::string& name) {
  const int i = flameVariationIndex(name);
  return i < 0 ? nullptr : &flameVariations()[std::size_t(i)];
}

int flameVariationIndex(const std::string& name) {
  const auto& table = flameVariations();
  for (std::size_t i = 0; i < table.size(); ++i)
    if (name == table[i].name) return int(i);
  return -1;
}

bool findVariationParameter(const std::string& attribute, int& variation, int& parameter) {
  const auto& table = flameVariations();
  for (std::size_t i = 0; i < table.size(); ++i)
    for (std::size_t k = 0; k < table[i].params.size(); ++k)
      if (attribute == table[i].params[k].first) {
        variation = int(i);
        parameter = int(k);
        return true;
      }
  return false;
}

bool flameVariationWritesZ(const std::string& name) {
  const FlameVariation* v = findFlameVariation(name);
  return v && v->writesZ;
}

bool isAffineFlameVariation(const std::string& name) {
  return name == "linear" || name == "linear3D" || name == "zscale" || name == "ztranslate" || name == "flatten";
}

bool isRandomFlameVariation(const std::string& name) {
  const FlameVariation* v = findFlameVariation(name);
  return v && v->random;
}

FlamePoint evaluateVariations(const VariationTerm* terms, std::size_t count, FlamePoint p, const FlameAffine& coefs,
                              std::uint64_t* random) {
  VariationInput in{p.x, p.y, p.z, &coefs, nullptr, random};
  for (std::size_t i = 0; i < count; ++i)
    if (terms[i].variation->pre) {
      in.param = terms[i].params;
      const FlamePoint d = terms[i].variation->apply(in, terms[i].weight);
      in.x += d.x;
      in.y += d.y;
    }
  FlamePoint sum;
  bool flatten = false;
  for (std::size_t i = 0; i < count; ++i) {
    const FlameVariation& v = *terms[i].variation;
    if (v.pre) continue;
    in.param = terms[i].params;
    const FlamePoint q = v.apply(in, terms[i].weight);
    sum.x += q.x;
    sum.y += q.y;
    sum.z += v.writesZ ? q.z : terms[i].weight * in.z;
    flatten |= v.apply == precise::flatten;
  }
  if (flatten) sum.z = 0.0;
  return sum;
}

}  // namespace gridifs

namespace gridifs {

KernelVariationTerm makeKernelVariationTerm(const VariationTerm& term) {
  KernelVariationTerm out;
  for (std::int32_t i = 0; i < body::kCount; ++i)
    if (kPreciseBodies[i] == term.variation->apply) out.body = i;
  out.pre = term.variation->pre;
  out.writesZ = term.variation->writesZ;
  out.flatten = term.variation->apply == precise::flatten;
  out.weight = term.weight;
  out.params = term.params;
  return out;
}

// flatten: every body, its helpers and the stream's draws inline into this one loop (GCC would
// otherwise keep the larger bodies as calls, with the point passed through memory). No SLP
// vectorisation: it summed the terms as pairs loaded from the switch's scalar stores, a
// store-forwarding stall on every term.
#if defined(__GNUC__) && !defined(__clang__)
#define GRIDIFS_KERNEL_SUM_ATTRIBUTES [[gnu::flatten, gnu::optimize("no-tree-slp-vectorize")]]
#else
#define GRIDIFS_KERNEL_SUM_ATTRIBUTES [[gnu::flatten]]  // clang: no per-function optimisation switches
#endif
KernelBodyFn kernelVariationBody(std::int32_t body) {
  return body >= 0 && body < body::kCount ? kKernelBodies[body] : nullptr;
}

GRIDIFS_KERNEL_SUM_ATTRIBUTES FlamePoint evaluateKernelVariations(const KernelVariationTerm* terms, std::size_t count,
                                                                  bool anyPre, FlamePoint p, const FlameAffine& coefs,
                                                                  std::uint64_t* random) {
  // The order of operations and of random draws is evaluateVariations's.
  VariationInput in{p.x, p.y, p.z, &coefs, nullptr, random};
  if (anyPre) [[unlikely]]
    for (std::size_t i = 0; i < count; ++i)
      if (terms[i].pre) {
        in.param = terms[i].params;
        const FlamePoint d = applyKernelBody(terms[i].body, in, terms[i].weight);
        in.x += d.x;
        in.y += d.y;
      }
  FlamePoint sum;
  bool flatten = false;
  for (std::size_t i = 0; i < count; ++i) {
    const KernelVariationTerm& t = terms[i];
    if (t.pre) continue;
    in.param = t.params;
    const FlamePoint q = applyKernelBody(t.body, in, t.weight);
    sum.x += q.x;
    sum.y += q.y;
    sum.z += t.writesZ ? q.z : t.weight * in.z;
    flatten |= t.flatten;
  }
  if (flatten) sum.z = 0.0;
  return sum;
}

}  // namespace gridifs
