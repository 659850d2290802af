#pragma once
// sin, cos, atan2, sqrt and pow of four floats at once, for the variation stage that evaluates four
// chains together (variations/variation_lanes.h). Float is what the renderer keeps its points in: these
// stay within a few float ulps of the library's double functions (the tests hold them to 3e-7
// relative or absolute), so the attractor is the same one, point for point up to float rounding.
// Branch-free but for arguments beyond the reduction's range, which go to the library lane by
// lane. Plain SSE2 (the x86-64 baseline), no fused multiply-adds: the same bits on every x86 CPU.
// Pure functions: thread-safe, never throw.
#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

// The eight-lane helpers pass AVX-sized vectors by value; they are always inlined, so no call
// crosses the ABI that GCC warns about in builds without AVX.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace gridifs::lane_math {

typedef float v4f __attribute__((vector_size(16)));
typedef std::int32_t v4i __attribute__((vector_size(16)));
/// Two four-lane values side by side (sin of x and of y at once, …): one AVX register.
typedef float v8f __attribute__((vector_size(32)));
typedef std::int32_t v8i __attribute__((vector_size(32)));

template <class V>
struct IntLanes;
template <>
struct IntLanes<v4f> {
  using type = v4i;
};
template <>
struct IntLanes<v8f> {
  using type = v8i;
};

[[gnu::always_inline]] constexpr v4f splat(float v) { return v4f{v, v, v, v}; }

/// Bit l set when lane l of the comparison `m` is true.
[[gnu::always_inline]] inline int mask(v4i m) {
#if defined(__SSE2__)
  return _mm_movemask_ps(__m128(m));
#else
  return (m[0] ? 1 : 0) | (m[1] ? 2 : 0) | (m[2] ? 4 : 0) | (m[3] ? 8 : 0);
#endif
}

[[gnu::always_inline]] inline int mask(v8i m) {
  return mask(v4i(__builtin_shufflevector(m, m, 0, 1, 2, 3))) | mask(v4i(__builtin_shufflevector(m, m, 4, 5, 6, 7)))
                                                                    << 4;
}

template <class V>
[[gnu::always_inline]] inline V abs(V x) {
  using I = typename IntLanes<V>::type;
  return V(I(x) & 0x7FFFFFFF);
}

/// a's lanes then b's.
[[gnu::always_inline]] inline v8f join(v4f a, v4f b) { return __builtin_shufflevector(a, b, 0, 1, 2, 3, 4, 5, 6, 7); }
[[gnu::always_inline]] inline v4f low(v8f v) { return __builtin_shufflevector(v, v, 0, 1, 2, 3); }
[[gnu::always_inline]] inline v4f high(v8f v) { return __builtin_shufflevector(v, v, 4, 5, 6, 7); }

[[gnu::always_inline]] inline v4f sqrt(v4f x) {
#if defined(__SSE2__)
  return v4f(_mm_sqrt_ps(__m128(x)));
#else
  return v4f{std::sqrt(x[0]), std::sqrt(x[1]), std::sqrt(x[2]), std::sqrt(x[3])};
#endif
}

/// Whole numbers nearest to x, for |x| < 2^22 (adding 1.5·2^23 rounds in the default mode).
template <class V>
[[gnu::always_inline]] inline V roundNearest(V x) {
  const V shift = V{} + 12582912.0f;
  return (x + shift) - shift;
}

/// Beyond this |x| the three-part reduction below loses digits: those lanes take the library's path.
inline constexpr float kReduceLimit = 8192.0f;

template <class V>
struct SinCos {
  V sin, cos;
};

/// sin x and cos x. x = k·π/2 + r with |r| ≤ π/4 (Cody & Waite: π/2 in three parts whose first two
/// have so few significant bits that k times each is exact for |k| < 2^13), then polynomials in
/// t = r² of degree 3: the Taylor series of sin to r^9 and of cos to r^10, economized on
/// [0, (π/4)²] by Chebyshev polynomials (Lanczos's telescoping: the top term traded for its
/// Chebyshev polynomial's lower ones), which leaves 3e-9 for sin and 3e-8 for cos. Four lanes or eight.
template <class V>
[[gnu::always_inline]] inline SinCos<V> sincos(V x) {
  using I = typename IntLanes<V>::type;
  const V k = roundNearest(x * 0.636619772f);
  const V r = ((x - k * 1.5703125f) - k * 4.837512969970703125e-4f) - k * 7.54978995489188216e-8f;
  // Estrin's scheme (pairs of terms, then the pairs together): the round's chains wait on these,
  // and it halves the latency of Horner's rule.
  const V t = r * r, t2 = t * t;
  const V s = r * ((0.9999999968829336f + t * -0.1666665049643418f) +
                   t2 * (0.008332022623657093f + t * -0.00019501295042400748f));
  const V c =
      (0.9999999723790245f + t * -0.49999856571927415f) + t2 * (0.041655021875510054f + t * -0.0013585860666678246f);
  const I quadrant = __builtin_convertvector(k, I);
  const I odd = (quadrant & 1) != 0;
  V sinV = odd ? c : s, cosV = odd ? s : c;
  sinV = V(I(sinV) ^ ((quadrant & 2) << 30));
  cosV = V(I(cosV) ^ (((quadrant + 1) & 2) << 30));
  if (const int far = mask(!(abs(x) < kReduceLimit))) [[unlikely]] {  // NaN and ±inf too
    for (int l = 0; l < int(sizeof(V) / sizeof(float)); ++l)
      if (far >> l & 1) {
        sinV[l] = float(std::sin(double(x[l])));
        cosV[l] = float(std::cos(double(x[l])));
      }
  }
  return {sinV, cosV};
}

/// atan2(y, x) by octant, as variations/kernel_math.h's: t = min/max ∈ [0, 1], folded to |u| ≤ tan(π/8)
/// by atan t = π/4 + atan((t−1)/(t+1)), then the Taylor series to u^15 economized to u^11 on
/// [0, tan²(π/8)] as sincos's (1.6e-8 in all). atan2(±0, x) is ±0 or ±π as the library's; infinite arguments give NaN.
[[gnu::always_inline]] inline v4f atan2(v4f y, v4f x) {
  constexpr float kPi = 3.14159265358979323846f;
  const v4f ax = abs(x), ay = abs(y);
  const v4i yMajor = ay > ax;
  const v4f mn = yMajor ? ax : ay, mx = yMajor ? ay : ax;
  const v4i fold = mn > 0.414213562f * mx;
  v4f u = (fold ? mn - mx : mn) / (fold ? mn + mx : mx);
  u = mx > 0.0f ? u : v4f{};                         // atan2(0, 0) = ±0 or ±π, by the signs
  const v4f u2 = u * u, s2 = u2 * u2, s4 = s2 * s2;  // Estrin's scheme, as sincos
  const v4f p = ((splat(0.9999999995049061f) + u2 * splat(-0.3333331201714171f)) +
                 s2 * (splat(0.1999849915296146f) + u2 * splat(-0.14246474643963947f))) +
                s4 * (splat(0.10634129575613752f) + u2 * splat(-0.06247697500165487f));
  v4f a = u * p + (fold ? splat(kPi / 4) : v4f{});
  a = yMajor ? kPi / 2 - a : a;
  a = v4i(x) < 0 ? kPi - a : a;  // the sign bit: atan2(±0, −0) = ±π
  return v4f((v4i(a) & 0x7FFFFFFF) | (v4i(y) & std::int32_t(0x80000000u)));
}

/// log2 x for normal positive x: x = 2^e·m with m ∈ [√½, √2), and ln m = 2·atanh u with
/// u = (m−1)/(m+1), |u| ≤ 0.172, by its series to u^9 (the first omitted term is below 2e-9).
/// Other arguments give garbage: pow() sends them to the library.
[[gnu::always_inline]] inline v4f log2(v4f x) {
  const v4i bits = v4i(x);
  v4i e = ((bits >> 23) & 0xFF) - 127;
  v4f m = v4f((bits & 0x007FFFFF) | 0x3F800000);  // [1, 2)
  const v4i high = m > 1.41421356f;
  m = high ? m * 0.5f : m;
  e -= high;  // high is −1 where true
  const v4f u = (m - 1.0f) / (m + 1.0f), u2 = u * u, u4 = u2 * u2;
  const v4f ln = 2.0f * u *
                 ((splat(1.0f) + u2 * splat(1.0f / 3)) + u4 * (splat(1.0f / 5) + u2 * splat(1.0f / 7)) +
                  u4 * u4 * splat(1.0f / 9));
  return __builtin_convertvector(e, v4f) + ln * 1.44269504f;
}

/// 2^t for |t| < 126: t = n + f with n whole and |f| ≤ ½, 2^f = e^(f·ln 2) by the Taylor series
/// to degree 7 (the first omitted term is below 6e-9; Estrin's scheme, as sincos), 2^n put in the exponent bits.
[[gnu::always_inline]] inline v4f exp2(v4f t) {
  const v4f n = roundNearest(t), g = (t - n) * 0.693147181f;
  const v4f g2 = g * g, g4 = g2 * g2;
  const v4f p = ((splat(1.0f) + g) + g2 * (splat(0.5f) + g * splat(1.0f / 6))) +
                g4 * ((splat(1.0f / 24) + g * splat(1.0f / 120)) + g2 * (splat(1.0f / 720) + g * splat(1.0f / 5040)));
  return p * v4f((__builtin_convertvector(n, v4i) + 127) << 23);
}

/// base^exponent for base > 0, as exp2(exponent·log2 base); a base that is 0, denormal, huge,
/// negative or not a number, or a result beyond 2^±126, goes to the library lane by lane.
[[gnu::always_inline]] inline v4f pow(v4f base, v4f exponent) {
  const v4f t = exponent * log2(base);
  v4f out = exp2(t);
  const v4i ordinary = (base > 1e-30f) & (base < 1e30f) & (abs(t) < 126.0f);
  if (const int odd = mask(~ordinary) & 0xF) [[unlikely]] {
    for (int l = 0; l < 4; ++l)
      if (odd >> l & 1) out[l] = float(std::pow(double(base[l]), double(exponent[l])));
  }
  return out;
}

}  // namespace gridifs::lane_math

#pragma GCC diagnostic pop
