#pragma once
// Inline sin, cos and atan2 for the chaos kernel's variation stage: accurate to about 1e-9
// relative (far below the float chain state's 6e-8), branch-light and inlined, where glibc's
// double sincos and atan2 are calls that aim at the last double bit. The renderer keeps its points
// in float, so these give the same picture point for point; FlameVariation::apply keeps std::
// math as the reference. Pure functions: thread-safe, never throw.
#include <cmath>
#include <cstdint>

namespace gridifs::kernel_math {

/// x reduced by the nearest multiple k of π/2: x = k·π/2 + r, |r| ≤ π/4 (Cody & Waite's two-part
/// constant: the high part has 33 significant bits, so k·high is exact for |k| < 2^20).
struct Reduced {
  double r;
  int quadrant;  // k mod 4
};
[[gnu::always_inline]] inline Reduced reduceHalfPi(double x) {
  constexpr double kTwoOverPi = 0.63661977236758134308;
  constexpr double kHigh = 1.5707963267341256141662597656250;  // π/2 to 33 bits
  constexpr double kLow = 6.0771005065061922e-11;              // π/2 − kHigh
  constexpr double kShift = 0x1.8p52;  // adding it rounds to an integer in the default rounding mode
  const double k = (x * kTwoOverPi + kShift) - kShift;
  return {(x - k * kHigh) - k * kLow, int(std::int64_t(k)) & 3};
}

/// Taylor series of sin and cos on [−π/4, π/4] (the first omitted terms are below 1e-11), summed
/// by Estrin's scheme: the chain of a step waits on these, and pairs of terms halve the latency of
/// Horner's rule.
[[gnu::always_inline]] inline double sinPoly(double r) {
  const double t = r * r, t2 = t * t;
  const double q01 = -1.0 / 6 + t * (1.0 / 120), q23 = -1.0 / 5040 + t * (1.0 / 362880);
  const double p = q01 + t2 * (q23 + t2 * (-1.0 / 39916800));
  return r + r * t * p;
}
[[gnu::always_inline]] inline double cosPoly(double r) {
  const double t = r * r, t2 = t * t, t4 = t2 * t2;
  const double q01 = -0.5 + t * (1.0 / 24), q23 = -1.0 / 720 + t * (1.0 / 40320),
               q45 = -1.0 / 3628800 + t * (1.0 / 479001600);
  return 1.0 + t * (q01 + t2 * q23 + t4 * q45);
}

/// Beyond this the two-part reduction loses digits; such arguments take the library's path.
inline constexpr double kReduceLimit = 1e5;

[[gnu::always_inline]] inline double sin(double x) {
  if (!(std::fabs(x) < kReduceLimit)) [[unlikely]]
    return std::sin(x);  // NaN and ±inf too
  const Reduced a = reduceHalfPi(x);
  const double s = sinPoly(a.r), c = cosPoly(a.r);
  const double v = (a.quadrant & 1) ? c : s;
  return (a.quadrant & 2) ? -v : v;
}
[[gnu::always_inline]] inline double cos(double x) {
  if (!(std::fabs(x) < kReduceLimit)) [[unlikely]]
    return std::cos(x);
  const Reduced a = reduceHalfPi(x);
  const double s = sinPoly(a.r), c = cosPoly(a.r);
  const double v = (a.quadrant & 1) ? s : c;
  return ((a.quadrant + 1) & 2) ? -v : v;
}

/// atan2 by octant: t = min/max ∈ [0, 1], folded to |u| ≤ tan(π/8) by atan t = π/4 + atan((t−1)/(t+1)),
/// then the Taylor series to u^19 (relative error below 1e-9).
[[gnu::always_inline]] inline double atan2(double y, double x) {
  constexpr double kPi = 3.14159265358979323846, kTanPi8 = 0.41421356237309504880;
  const double ax = std::fabs(x), ay = std::fabs(y);
  const double mn = ax < ay ? ax : ay, mx = ax < ay ? ay : ax;
  if (!(mx > 0.0) || !(mx < 1e300)) [[unlikely]]
    return std::atan2(y, x);  // zeros, NaN, infinities
  const bool fold = mn > kTanPi8 * mx;
  const double u = fold ? (mn - mx) / (mn + mx) : mn / mx;
  const double u2 = u * u;
  // Estrin's scheme, as for sin and cos.
  const double s2 = u2 * u2, s4 = s2 * s2, s8 = s4 * s4;
  const double q01 = -1.0 / 3 + u2 * (1.0 / 5), q23 = -1.0 / 7 + u2 * (1.0 / 9), q45 = -1.0 / 11 + u2 * (1.0 / 13),
               q67 = -1.0 / 15 + u2 * (1.0 / 17);
  const double p = (q01 + s2 * q23) + s4 * (q45 + s2 * q67) + s8 * (-1.0 / 19);
  double a = u + u * u2 * p + (fold ? kPi / 4 : 0.0);
  if (ay > ax) a = kPi / 2 - a;
  if (x < 0.0) a = kPi - a;
  return std::copysign(a, y);
}

}  // namespace gridifs::kernel_math
