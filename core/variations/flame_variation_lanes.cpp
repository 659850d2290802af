#include <cmath>
#include <cstring>

#include "variations/flame_variations.h"
#include "variations/variation_lanes.h"

// The four-lane forms of the commonest variations (Draves & Reckase, appendix), each the same
// formula as its body in flame_variation_bodies.inc, in float.
// The eight-lane sincos passes AVX-sized vectors, always inlined (variations/lane_math.h).
#pragma GCC diagnostic ignored "-Wpsabi"

namespace gridifs {
namespace {

using lane_math::v4f;
using lane_math::v4i;
using lane_math::v8f;
namespace lm = lane_math;

constexpr float kEps = 1e-10f;  // flam3's guard against division by zero
constexpr float kPi = 3.14159265358979323846f;

[[gnu::always_inline]] inline v4f sumsq(VariationLanes& in) { return in.x * in.x + in.y * in.y; }
[[gnu::always_inline]] inline v4f radius(VariationLanes& in) { return in.radius(); }
/// flam3 measures the angle from the y axis: atan2(x, y).
[[gnu::always_inline]] inline v4f angle(VariationLanes& in) { return in.angle(); }

/// kDraws uniform draws in [0, 1) for each active lane, in lane order (0 elsewhere).
template <int kDraws>
[[gnu::always_inline]] inline void drawUniforms(VariationLanes& in, double (&u)[kDraws][4]) {
  for (int l = 0; l < 4; ++l)
    for (int d = 0; d < kDraws; ++d) u[d][l] = in.active >> l & 1 ? variationUniform(*in.random) : 0.0;
}

/// (r cos a, r sin a): the point at radius r and angle a (julia, blur, julian).
[[gnu::always_inline]] inline void fromPolar(v4f r, v4f a, v4f& x, v4f& y) {
  const lm::SinCos<v4f> sc = lm::sincos(a);
  x = r * sc.cos;
  y = r * sc.sin;
}

void linear(VariationLanes& in, v4f& x, v4f& y, v4f& z) {
  x = in.weight * in.x;
  y = in.weight * in.y;
  z = in.weight * in.z;
}
void sinusoidal(VariationLanes& in, v4f& x, v4f& y, v4f&) {
  const v8f s = lm::sincos(lm::join(in.x, in.y)).sin;
  x = in.weight * lm::low(s);
  y = in.weight * lm::high(s);
}
// 3D form: w·p / |p|².
void spherical(VariationLanes& in, v4f& x, v4f& y, v4f& z) {
  const v4f r2 = in.weight / (sumsq(in) + in.z * in.z + kEps);
  x = r2 * in.x;
  y = r2 * in.y;
  z = r2 * in.z;
}
void swirl(VariationLanes& in, v4f& x, v4f& y, v4f&) {
  const lm::SinCos<v4f> sc = lm::sincos(sumsq(in));
  x = in.weight * (sc.sin * in.x - sc.cos * in.y);
  y = in.weight * (sc.cos * in.x + sc.sin * in.y);
}
void horseshoe(VariationLanes& in, v4f& x, v4f& y, v4f&) {
  const v4f r = in.weight / (radius(in) + kEps);
  x = (in.x - in.y) * (in.x + in.y) * r;
  y = 2.0f * in.x * in.y * r;
}
void polar(VariationLanes& in, v4f& x, v4f& y, v4f&) {
  x = in.weight * (angle(in) / kPi);
  y = in.weight * (radius(in) - 1.0f);
}
void handkerchief(VariationLanes& in, v4f& x, v4f& y, v4f&) {
  const v4f a = angle(in), r = radius(in);
  const lm::SinCos<v8f> sc = lm::sincos(lm::join(a + r, a - r));
  x = in.weight * (r * lm::low(sc.sin));
  y = in.weight * (r * lm::high(sc.cos));
}
void heart(VariationLanes& in, v4f& x, v4f& y, v4f&) {
  const v4f radiusV = radius(in);
  const lm::SinCos<v4f> sc = lm::sincos(radiusV * angle(in));
  const v4f r = in.weight * radiusV;
  x = r * sc.sin;
  y = -r * sc.cos;
}
void disc(VariationLanes& in, v4f& x, v4f& y, v4f&) {
  const v4f a = angle(in) / kPi;
  const lm::SinCos<v4f> sc = lm::sincos(kPi * radius(in));
  x = in.weight * (sc.sin * a);
  y = in.weight * (sc.cos * a);
}
void spiral(VariationLanes& in, v4f& x, v4f& y, v4f&) {
  const v4f radiusV = radius(in), r = radiusV + kEps, r1 = in.weight / r;
  const lm::SinCos<v4f> sc = lm::sincos(r);
  x = r1 * (in.y / radiusV + sc.sin);
  y = r1 * (in.x / radiusV - sc.cos);
}
void hyperbolic(VariationLanes& in, v4f& x, v4f& y, v4f&) {
  const v4f radiusV = radius(in), r = radiusV + kEps;
  x = in.weight * (in.x / radiusV / r);
  y = in.weight * (in.y / radiusV * r);
}
void diamond(VariationLanes& in, v4f& x, v4f& y, v4f&) {
  const v4f r = radius(in);
  const lm::SinCos<v4f> sc = lm::sincos(r);
  x = in.weight * (in.x / r * sc.cos);
  y = in.weight * (in.y / r * sc.sin);
}
void ex(VariationLanes& in, v4f& x, v4f& y, v4f&) {
  const v4f a = angle(in), r = radius(in);
  const lm::SinCos<v8f> sc = lm::sincos(lm::join(a + r, a - r));
  const v4f n0 = lm::low(sc.sin), n1 = lm::high(sc.cos);
  const v4f m0 = n0 * n0 * n0 * r, m1 = n1 * n1 * n1 * r;
  x = in.weight * (m0 + m1);
  y = in.weight * (m0 - m1);
}
void bent(VariationLanes& in, v4f& x, v4f& y, v4f&) {
  x = in.weight * (in.x < 0.0f ? 2.0f * in.x : in.x);
  y = in.weight * (in.y < 0.0f ? in.y / 2.0f : in.y);
}
void fisheye(VariationLanes& in, v4f& x, v4f& y, v4f&) {
  const v4f r = 2.0f * in.weight / (radius(in) + 1.0f);
  x = r * in.y;  // the appendix notes the reversed order
  y = r * in.x;
}
void eyefish(VariationLanes& in, v4f& x, v4f& y, v4f& z) {
  const v4f r = 2.0f * in.weight / (lm::sqrt(sumsq(in) + in.z * in.z) + 1.0f);
  x = r * in.x;
  y = r * in.y;
  z = r * in.z;
}
void bubble(VariationLanes& in, v4f& x, v4f& y, v4f& z) {
  const v4f r = in.weight / (0.25f * (sumsq(in) + in.z * in.z) + 1.0f);
  x = r * in.x;
  y = r * in.y;
  z = r * in.z;
}
void cylinder(VariationLanes& in, v4f& x, v4f& y, v4f&) {
  x = in.weight * lm::sincos(in.x).sin;
  y = in.weight * in.y;
}
// Draves & Reckase, appendix: julia takes one of the two square roots at random.
void julia(VariationLanes& in, v4f& x, v4f& y, v4f&) {
  double u[1][4];
  drawUniforms(in, u);
  const v4i otherRoot = {u[0][0] < 0.5, u[0][1] < 0.5, u[0][2] < 0.5, u[0][3] < 0.5};
  const v4f a = 0.5f * angle(in) + (otherRoot != 0 ? lm::splat(kPi) : v4f{});
  const v4f r = in.weight * lm::sqrt(radius(in));
  fromPolar(r, a, x, y);
}
void blur(VariationLanes& in, v4f& x, v4f& y, v4f&) {
  double u[2][4];
  drawUniforms(in, u);
  v4f t, radial;
  for (int l = 0; l < 4; ++l) {
    t[l] = float(u[0][l] * 2.0 * 3.14159265358979323846);
    radial[l] = float(u[1][l]);
  }
  const v4f r = in.weight * radial;
  fromPolar(r, t, x, y);
}
void julian(VariationLanes& in, v4f& x, v4f& y, v4f&) {
  double u[1][4];
  drawUniforms(in, u);
  v4f turn, power, exponent;
  for (int l = 0; l < 4; ++l) {  // every lane has parameters (BatchedVariations::params)
    const double p = in.params[l][0], dist = in.params[l][1];
    turn[l] = float(2.0 * 3.14159265358979323846 * std::trunc(std::fabs(p) * u[0][l]));
    power[l] = float(p);
    exponent[l] = float(dist / p / 2.0);
  }
  const v4f a = (lm::atan2(in.y, in.x) + turn) / power, r = in.weight * lm::pow(sumsq(in), exponent);
  fromPolar(r, a, x, y);
}

// clang-format off
#define GRIDIFS_LANE_BODIES(X)                                                                            \
  X(linear) X(sinusoidal) X(spherical) X(swirl) X(horseshoe) X(polar) X(handkerchief) X(heart) X(disc)   \
  X(spiral) X(hyperbolic) X(diamond) X(ex) X(bent) X(fisheye) X(eyefish) X(bubble) X(cylinder) X(julia) \
  X(blur) X(julian)
// clang-format on

namespace lane_body {
#define GRIDIFS_ENUM(name) name,
enum Id : int { GRIDIFS_LANE_BODIES(GRIDIFS_ENUM) kCount };
#undef GRIDIFS_ENUM
}  // namespace lane_body

#define GRIDIFS_NAME(name) #name,
constexpr const char* kLaneBodyNames[] = {GRIDIFS_LANE_BODIES(GRIDIFS_NAME)};
#undef GRIDIFS_NAME
// Each body on its own with its helpers inlined, for laneVariationBody.
#define GRIDIFS_POINTER(name) [](VariationLanes& in, v4f& x, v4f& y, v4f& z) { name(in, x, y, z); },
constexpr LaneBodyFn kLaneBodies[] = {GRIDIFS_LANE_BODIES(GRIDIFS_POINTER)};
#undef GRIDIFS_POINTER

/// Lane masks (−1 where the lane is on) by the bits of VariationLanes::active.
constexpr v4i kActiveLanes[16] = {{0, 0, 0, 0},   {-1, 0, 0, 0},   {0, -1, 0, 0},   {-1, -1, 0, 0},
                                  {0, 0, -1, 0},  {-1, 0, -1, 0},  {0, -1, -1, 0},  {-1, -1, -1, 0},
                                  {0, 0, 0, -1},  {-1, 0, 0, -1},  {0, -1, 0, -1},  {-1, -1, 0, -1},
                                  {0, 0, -1, -1}, {-1, 0, -1, -1}, {0, -1, -1, -1}, {-1, -1, -1, -1}};

}  // namespace

int laneVariationBodyIndex(const char* name) {
  for (int i = 0; i < lane_body::kCount; ++i)
    if (std::strcmp(kLaneBodyNames[i], name) == 0) return i;
  return -1;
}

LaneBodyFn laneVariationBody(const char* name) {
  const int i = laneVariationBodyIndex(name);
  return i < 0 ? nullptr : kLaneBodies[i];
}

// flatten: the bodies inline into the loop over slots (a switch), so the four lanes' point and
// sums stay in registers. Compiled twice, picked at load time as the chaos kernel is: AVX2's
// three-operand forms save the SSE2 build's register copies (no fused multiply-adds either way).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(GRIDIFS_NO_KERNEL_CLONES)
#define GRIDIFS_LANE_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define GRIDIFS_LANE_CLONES
#endif
[[gnu::flatten]] GRIDIFS_LANE_CLONES void BatchedVariations::apply(const std::uint32_t (&fn)[4], v4f (&q)[4],
                                                                   std::uint64_t& random) const {
  const std::size_t count = slots.size();
  VariationLanes in;
  // The four points as x, y and z rows.
  const v4f q01 = __builtin_shufflevector(q[0], q[1], 0, 4, 1, 5),
            q23 = __builtin_shufflevector(q[2], q[3], 0, 4, 1, 5);
  const v4f z01 = __builtin_shufflevector(q[0], q[1], 2, 6, 3, 7),
            z23 = __builtin_shufflevector(q[2], q[3], 2, 6, 3, 7);
  in.x = __builtin_shufflevector(q01, q23, 0, 1, 4, 5);
  in.y = __builtin_shufflevector(q01, q23, 2, 3, 6, 7);
  in.z = __builtin_shufflevector(z01, z23, 0, 1, 4, 5);
  in.random = &random;
  const std::uint32_t masks[4] = {slotMask[fn[0]], slotMask[fn[1]], slotMask[fn[2]], slotMask[fn[3]]};
  const float* weightRows[4] = {&weights[fn[0] * count], &weights[fn[1] * count], &weights[fn[2] * count],
                                &weights[fn[3] * count]};
  const double* const* paramRows[4] = {&params[fn[0] * count], &params[fn[1] * count], &params[fn[2] * count],
                                       &params[fn[3] * count]};
  v4f sx{}, sy{}, sz{};
  for (std::size_t s = 0; s < count; ++s) {
    const int active =
        int((masks[0] >> s & 1) | (masks[1] >> s & 1) << 1 | (masks[2] >> s & 1) << 2 | (masks[3] >> s & 1) << 3);
    if (active == 0) continue;
    in.active = active;
    in.weight = v4f{weightRows[0][s], weightRows[1][s], weightRows[2][s], weightRows[3][s]};
    const Slot& slot = slots[s];
    if (slot.params)
      for (int l = 0; l < 4; ++l) in.params[l] = paramRows[l][s];
    v4f dx{}, dy{}, dz{};
    switch (slot.lanes) {
#define GRIDIFS_CASE(name) \
  case lane_body::name:    \
    name(in, dx, dy, dz);  \
    break;
      GRIDIFS_LANE_BODIES(GRIDIFS_CASE)
#undef GRIDIFS_CASE
      default:
        for (int l = 0; l < 4; ++l) {
          if (!(active >> l & 1)) continue;
          const VariationInput one{in.x[l], in.y[l], in.z[l], coefs[fn[l]], in.params[l], &random};
          const FlamePoint d = slot.scalar(one, in.weight[l]);
          dx[l] = float(d.x);
          dy[l] = float(d.y);
          dz[l] = float(d.z);
        }
    }
    if (!slot.writesZ) dz = in.weight * in.z;
    // Inactive lanes may hold NaN (spherical at 0, …): they add nothing. A blend, not a branch
    // on whether all four are active, which mispredicted as often.
    const v4i on = kActiveLanes[active];
    dx = on ? dx : v4f{};
    dy = on ? dy : v4f{};
    dz = on ? dz : v4f{};
    sx += dx;
    sy += dy;
    sz += dz;
  }
  if (anyFlatten)
    for (int l = 0; l < 4; ++l)
      if (flatten[fn[l]]) sz[l] = 0.0f;
  // Back to one point per chain, lane 3 zero; a lane whose function has no stage keeps its grid image.
  const v4f xy01 = __builtin_shufflevector(sx, sy, 0, 4, 1, 5), xy23 = __builtin_shufflevector(sx, sy, 2, 6, 3, 7);
  const v4f z0 = __builtin_shufflevector(sz, v4f{}, 0, 4, 1, 5), z1 = __builtin_shufflevector(sz, v4f{}, 2, 6, 3, 7);
  const v4f out[4] = {__builtin_shufflevector(xy01, z0, 0, 1, 4, 5), __builtin_shufflevector(xy01, z0, 2, 3, 6, 7),
                      __builtin_shufflevector(xy23, z1, 0, 1, 4, 5), __builtin_shufflevector(xy23, z1, 2, 3, 6, 7)};
  for (int l = 0; l < 4; ++l)
    if (!anyKeepsGridImage || !keepsGridImage[fn[l]]) q[l] = out[l];
  if (!anyPost) return;
  for (int l = 0; l < 4; ++l) {
    const std::uint32_t f = fn[l];
    if (!hasPost[f]) continue;
    const float* c = &postColumns[std::size_t(f) * 16];
    v4f cx, cy, cz, c1;
    std::memcpy(&cx, c, 16);
    std::memcpy(&cy, c + 4, 16);
    std::memcpy(&cz, c + 8, 16);
    std::memcpy(&c1, c + 12, 16);
    q[l] = cx * q[l][0] + cy * q[l][1] + cz * q[l][2] + c1;
  }
}

}  // namespace gridifs
