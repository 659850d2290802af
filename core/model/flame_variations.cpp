#include "model/flame_variations.h"

#include <algorithm>
#include <cmath>

namespace gridifs {
namespace {

// flam3's guard against division by zero.
constexpr double kEps = 1e-10;
constexpr double kPi = 3.14159265358979323846;

double sumsq(const VariationInput& in) { return in.x * in.x + in.y * in.y; }
double radius(const VariationInput& in) { return std::sqrt(sumsq(in)); }
/// flam3 measures the angle from the y axis: atan2(x, y).
double angle(const VariationInput& in) { return std::atan2(in.x, in.y); }
double angleYx(const VariationInput& in) { return std::atan2(in.y, in.x); }
/// sin and cos of flam3's angle: x / r and y / r.
double sinA(const VariationInput& in) { return in.x / radius(in); }
double cosA(const VariationInput& in) { return in.y / radius(in); }

FlamePoint scaled(double w, double x, double y) { return {w * x, w * y}; }

// Draves & Reckase, appendix: variations 0–30 and 38–40, 42, 46.
// linear carries z as linear3D does: JWildfire, Fractorium and Apophysis 7X treat them alike.
FlamePoint linear(const VariationInput& in, double w) { return {w * in.x, w * in.y, w * in.z}; }
// The z variations of Apophysis 7X's 3D extension, as JWildfire and Fractorium evaluate them.
FlamePoint zscale(const VariationInput& in, double w) { return {0.0, 0.0, w * in.z}; }
FlamePoint ztranslate(const VariationInput&, double w) { return {0.0, 0.0, w}; }
FlamePoint zcone(const VariationInput& in, double w) { return {0.0, 0.0, w * std::sqrt(in.x * in.x + in.y * in.y)}; }
// flatten contributes nothing; FlameXform::apply clears z when the xform has it.
FlamePoint flatten(const VariationInput&, double) { return {}; }
constexpr auto flatten_ = flatten;
FlamePoint sinusoidal(const VariationInput& in, double w) { return scaled(w, std::sin(in.x), std::sin(in.y)); }
// 3D form: w·p / |p|² (equal to flam3's on z = 0).
FlamePoint spherical(const VariationInput& in, double w) {
  const double r2 = w / (sumsq(in) + in.z * in.z + kEps);
  return {r2 * in.x, r2 * in.y, r2 * in.z};
}
FlamePoint swirl(const VariationInput& in, double w) {
  const double r2 = sumsq(in), s = std::sin(r2), c = std::cos(r2);
  return scaled(w, s * in.x - c * in.y, c * in.x + s * in.y);
}
FlamePoint horseshoe(const VariationInput& in, double w) {
  const double r = w / (radius(in) + kEps);
  return {(in.x - in.y) * (in.x + in.y) * r, 2.0 * in.x * in.y * r};
}
FlamePoint polar(const VariationInput& in, double w) { return scaled(w, angle(in) / kPi, radius(in) - 1.0); }
FlamePoint handkerchief(const VariationInput& in, double w) {
  const double a = angle(in), r = radius(in);
  return scaled(w, r * std::sin(a + r), r * std::cos(a - r));
}
FlamePoint heart(const VariationInput& in, double w) {
  const double a = radius(in) * angle(in), r = w * radius(in);
  return {r * std::sin(a), -r * std::cos(a)};
}
FlamePoint disc(const VariationInput& in, double w) {
  const double a = angle(in) / kPi, r = kPi * radius(in);
  return scaled(w, std::sin(r) * a, std::cos(r) * a);
}
FlamePoint spiral(const VariationInput& in, double w) {
  const double r = radius(in) + kEps, r1 = w / r;
  return {r1 * (cosA(in) + std::sin(r)), r1 * (sinA(in) - std::cos(r))};
}
FlamePoint hyperbolic(const VariationInput& in, double w) {
  const double r = radius(in) + kEps;
  return scaled(w, sinA(in) / r, cosA(in) * r);
}
FlamePoint diamond(const VariationInput& in, double w) {
  const double r = radius(in);
  return scaled(w, sinA(in) * std::cos(r), cosA(in) * std::sin(r));
}
FlamePoint ex(const VariationInput& in, double w) {
  const double a = angle(in), r = radius(in);
  const double n0 = std::sin(a + r), n1 = std::cos(a - r);
  const double m0 = n0 * n0 * n0 * r, m1 = n1 * n1 * n1 * r;
  return scaled(w, m0 + m1, m0 - m1);
}
FlamePoint bent(const VariationInput& in, double w) {
  const double x = in.x < 0.0 ? 2.0 * in.x : in.x, y = in.y < 0.0 ? in.y / 2.0 : in.y;
  return scaled(w, x, y);
}
FlamePoint waves(const VariationInput& in, double w) {
  const double dx2 = 1.0 / (in.coefs->c * in.coefs->c + kEps), dy2 = 1.0 / (in.coefs->f * in.coefs->f + kEps);
  return scaled(w, in.x + in.coefs->b * std::sin(in.y * dx2), in.y + in.coefs->e * std::sin(in.x * dy2));
}
FlamePoint fisheye(const VariationInput& in, double w) {
  const double r = 2.0 * w / (radius(in) + 1.0);
  return {r * in.y, r * in.x};  // the appendix notes the reversed order
}
FlamePoint popcorn(const VariationInput& in, double w) {
  return scaled(w, in.x + in.coefs->c * std::sin(std::tan(3.0 * in.y)),
                in.y + in.coefs->f * std::sin(std::tan(3.0 * in.x)));
}
FlamePoint exponential(const VariationInput& in, double w) {
  const double dx = w * std::exp(in.x - 1.0), dy = kPi * in.y;
  return {dx * std::cos(dy), dx * std::sin(dy)};
}
FlamePoint power(const VariationInput& in, double w) {
  const double r = w * std::pow(radius(in), sinA(in));
  return {r * cosA(in), r * sinA(in)};
}
FlamePoint cosine(const VariationInput& in, double w) {
  const double a = in.x * kPi;
  return scaled(w, std::cos(a) * std::cosh(in.y), -std::sin(a) * std::sinh(in.y));
}
FlamePoint rings(const VariationInput& in, double w) {
  const double dx = in.coefs->c * in.coefs->c + kEps, r0 = radius(in);
  const double r = w * (std::fmod(r0 + dx, 2.0 * dx) - dx + r0 * (1.0 - dx));
  return {r * cosA(in), r * sinA(in)};
}
FlamePoint fan(const VariationInput& in, double w) {
  const double dx = kPi * (in.coefs->c * in.coefs->c + kEps), dy = in.coefs->f, half = 0.5 * dx;
  double a = angle(in);
  const double r = w * radius(in);
  a += std::fmod(a + dy, dx) > half ? -half : half;
  return {r * std::cos(a), r * std::sin(a)};
}
FlamePoint blob(const VariationInput& in, double w) {
  const double low = in.param[0], high = in.param[1],
               wavesCount = in.param[2];
  const double r = radius(in) * (low + (high - low) * (0.5 + 0.5 * std::sin(wavesCount * angle(in))));
  return scaled(w, sinA(in) * r, cosA(in) * r);
}
FlamePoint pdj(const VariationInput& in, double w) {
  const double a = in.param[0], b = in.param[1], c = in.param[2],
               d = in.param[3];
  return scaled(w, std::sin(a * in.y) - std::cos(b * in.x), std::sin(c * in.x) - std::cos(d * in.y));
}
FlamePoint fan2(const VariationInput& in, double w) {
  const double fx = in.param[0], dy = in.param[1];
  const double dx = kPi * (fx * fx + kEps), half = 0.5 * dx;
  double a = angle(in);
  const double r = w * radius(in);
  const double t = a + dy - dx * std::trunc((a + dy) / dx);
  a += t > half ? -half : half;
  return {r * std::sin(a), r * std::cos(a)};
}
FlamePoint rings2(const VariationInput& in, double w) {
  const double v = in.param[0], dx = v * v + kEps;
  double r = radius(in);
  r += -2.0 * dx * std::trunc((r + dx) / (2.0 * dx)) + r * (1.0 - dx);
  return scaled(w, sinA(in) * r, cosA(in) * r);
}
// 3D forms: the radius is |p| (equal to flam3's on z = 0).
FlamePoint eyefish(const VariationInput& in, double w) {
  const double r = 2.0 * w / (std::sqrt(sumsq(in) + in.z * in.z) + 1.0);
  return {r * in.x, r * in.y, r * in.z};
}
FlamePoint bubble(const VariationInput& in, double w) {
  const double r = w / (0.25 * (sumsq(in) + in.z * in.z) + 1.0);
  return {r * in.x, r * in.y, r * in.z};
}
FlamePoint cylinder(const VariationInput& in, double w) { return scaled(w, std::sin(in.x), in.y); }
FlamePoint perspective(const VariationInput& in, double w) {
  const double ang = in.param[0] * kPi / 2.0, dist = in.param[1];
  const double t = 1.0 / (dist - in.y * std::sin(ang));
  return {w * dist * in.x * t, w * dist * std::cos(ang) * in.y * t};
}
FlamePoint ngon(const VariationInput& in, double w) {
  const double pw = in.param[1], sides = in.param[0],
               corners = in.param[3], circle = in.param[2];
  const double rFactor = std::pow(sumsq(in), pw / 2.0), b = 2.0 * kPi / sides;
  double phi = angleYx(in) - b * std::floor(angleYx(in) / b);
  if (phi > b / 2.0) phi -= b;
  const double amp = (corners * (1.0 / (std::cos(phi) + kEps) - 1.0) + circle) / (rFactor + kEps);
  return scaled(w, in.x * amp, in.y * amp);
}
FlamePoint curl(const VariationInput& in, double w) {
  const double c1 = in.param[0], c2 = in.param[1];
  const double re = 1.0 + c1 * in.x + c2 * (in.x * in.x - in.y * in.y), im = c1 * in.y + 2.0 * c2 * in.x * in.y;
  const double r = w / (re * re + im * im);
  return {(in.x * re + in.y * im) * r, (in.y * re - in.x * im) * r};
}
FlamePoint rectangles(const VariationInput& in, double w) {
  const double rx = in.param[0], ry = in.param[1];
  const double x = rx == 0.0 ? in.x : (2.0 * std::floor(in.x / rx) + 1.0) * rx - in.x;
  const double y = ry == 0.0 ? in.y : (2.0 * std::floor(in.y / ry) + 1.0) * ry - in.y;
  return scaled(w, x, y);
}
FlamePoint tangent(const VariationInput& in, double w) {
  return scaled(w, std::sin(in.x) / std::cos(in.y), std::tan(in.y));
}
FlamePoint secant2(const VariationInput& in, double w) {
  const double cr = std::cos(w * radius(in)), icr = 1.0 / cr;
  return {w * in.x, cr < 0.0 ? w * (icr + 1.0) : w * (icr - 1.0)};
}
FlamePoint cross(const VariationInput& in, double w) {
  const double s = in.x * in.x - in.y * in.y, r = w * std::sqrt(1.0 / (s * s + kEps));
  return {in.x * r, in.y * r};
}
FlamePoint disc2(const VariationInput& in, double w) {
  const double rot = in.param[0], twist = in.param[1];
  double sinAdd = std::sin(twist), cosAdd = std::cos(twist) - 1.0;
  if (twist > 2.0 * kPi) {
    const double k = 1.0 + twist - 2.0 * kPi;
    cosAdd *= k, sinAdd *= k;
  }
  if (twist < -2.0 * kPi) {
    const double k = 1.0 + twist + 2.0 * kPi;
    cosAdd *= k, sinAdd *= k;
  }
  const double t = rot * kPi * (in.x + in.y), r = w * angle(in) / kPi;
  return {(std::sin(t) + cosAdd) * r, (std::cos(t) + sinAdd) * r};
}
FlamePoint bent2(const VariationInput& in, double w) {
  const double x = in.x < 0.0 ? in.x * in.param[0] : in.x;
  const double y = in.y < 0.0 ? in.y * in.param[1] : in.y;
  return scaled(w, x, y);
}
FlamePoint bipolar(const VariationInput& in, double w) {
  const double x2y2 = sumsq(in), t = x2y2 + 1.0, x2 = 2.0 * in.x;
  double y = 0.5 * std::atan2(2.0 * in.y, x2y2 - 1.0) - kPi / 2.0 * in.param[0];
  if (y > kPi / 2.0)
    y = -kPi / 2.0 + std::fmod(y + kPi / 2.0, kPi);
  else if (y < -kPi / 2.0)
    y = kPi / 2.0 - std::fmod(kPi / 2.0 - y, kPi);
  return {w * 0.25 * (2.0 / kPi) * std::log((t + x2) / (t - x2)), w * (2.0 / kPi) * y};
}
FlamePoint butterfly(const VariationInput& in, double w) {
  const double wx = w * 1.3029400317411197908970256609023, y2 = 2.0 * in.y;  // 4 / sqrt(3π)
  const double r = wx * std::sqrt(std::fabs(in.y * in.x) / (kEps + in.x * in.x + y2 * y2));
  return {r * in.x, r * y2};
}
FlamePoint cell(const VariationInput& in, double w) {
  const double size = in.param[0], inv = 1.0 / size;
  double x = std::floor(in.x * inv), y = std::floor(in.y * inv);
  const double dx = in.x - x * size, dy = in.y - y * size;
  if (y >= 0.0) {
    y *= 2.0;
    x = x >= 0.0 ? 2.0 * x : -(2.0 * x + 1.0);
  } else {
    y = -(2.0 * y + 1.0);
    x = x >= 0.0 ? 2.0 * x : -(2.0 * x + 1.0);
  }
  return {w * (dx + x * size), -w * (dy + y * size)};
}
FlamePoint curve(const VariationInput& in, double w) {
  const double xl = in.param[2], yl = in.param[3];
  const double xlen = std::max(xl * xl, 1e-20), ylen = std::max(yl * yl, 1e-20);
  return scaled(w, in.x + in.param[0] * std::exp(-in.y * in.y / xlen),
                in.y + in.param[1] * std::exp(-in.x * in.x / ylen));
}
FlamePoint elliptic(const VariationInput& in, double w) {
  const double tmp = sumsq(in) + 1.0, x2 = 2.0 * in.x;
  const double xmax = 0.5 * (std::sqrt(tmp + x2) + std::sqrt(tmp - x2));
  const double a = in.x / xmax, b = std::sqrt(std::max(0.0, 1.0 - a * a)), s = std::sqrt(std::max(0.0, xmax - 1.0));
  const double ww = w / (kPi / 2.0), l = std::log(xmax + s);
  return {ww * std::atan2(a, b), in.y > 0.0 ? ww * l : -ww * l};
}
FlamePoint foci(const VariationInput& in, double w) {
  const double ex = 0.5 * std::exp(in.x), enx = 0.25 / ex;
  const double t = w / (ex + enx - std::cos(in.y));
  return {t * (ex - enx), t * std::sin(in.y)};
}
FlamePoint loonie(const VariationInput& in, double w) {
  const double r2 = sumsq(in), w2 = w * w;
  if (r2 < w2 && r2 > 0.0) {
    const double r = w * std::sqrt(w2 / r2 - 1.0);
    return {r * in.x, r * in.y};
  }
  return scaled(w, in.x, in.y);
}
double modulusAxis(double t, double m) {
  if (t > m) return -m + std::fmod(t + m, 2.0 * m);
  if (t < -m) return m - std::fmod(m - t, 2.0 * m);
  return t;
}
FlamePoint modulus(const VariationInput& in, double w) {
  return scaled(w, modulusAxis(in.x, in.param[0]), modulusAxis(in.y, in.param[1]));
}
FlamePoint oscilloscope(const VariationInput& in, double w) {
  const double sep = in.param[0], freq = in.param[1],
               amp = in.param[2], damp = in.param[3];
  const double c = std::cos(2.0 * kPi * freq * in.x);
  const double t = (damp == 0.0 ? amp * c : amp * std::exp(-std::fabs(in.x) * damp) * c) + sep;
  return {w * in.x, std::fabs(in.y) <= t ? -w * in.y : w * in.y};
}
FlamePoint polar2(const VariationInput& in, double w) {
  const double p = w / kPi;
  return {p * angle(in), p / 2.0 * std::log(sumsq(in))};
}
FlamePoint popcorn2(const VariationInput& in, double w) {
  const double c = in.param[2];
  return scaled(w, in.x + in.param[0] * std::sin(std::tan(in.y * c)),
                in.y + in.param[1] * std::sin(std::tan(in.x * c)));
}
FlamePoint scry(const VariationInput& in, double w) {
  const double t = sumsq(in), r = 1.0 / (std::sqrt(t) * (t + 1.0 / (w + kEps)));
  return {in.x * r, in.y * r};
}
double separationAxis(double t, double s, double inside) {
  const double root = std::sqrt(t * t + s * s);
  return t > 0.0 ? root - t * inside : -(root + t * inside);
}
FlamePoint separation(const VariationInput& in, double w) {
  return scaled(w, separationAxis(in.x, in.param[0], in.param[1]),
                separationAxis(in.y, in.param[2], in.param[3]));
}
FlamePoint split(const VariationInput& in, double w) {
  const double xs = in.param[0], ys = in.param[1];
  return {std::cos(in.y * ys * kPi) >= 0.0 ? w * in.x : -w * in.x,
          std::cos(in.x * xs * kPi) >= 0.0 ? w * in.y : -w * in.y};
}
FlamePoint splits(const VariationInput& in, double w) {
  const double sx = in.param[0], sy = in.param[1];
  return scaled(w, in.x >= 0.0 ? in.x + sx : in.x - sx, in.y >= 0.0 ? in.y + sy : in.y - sy);
}
FlamePoint stripes(const VariationInput& in, double w) {
  const double space = in.param[0], warp = in.param[1];
  const double rx = std::floor(in.x + 0.5), ox = in.x - rx;
  return {w * (ox * (1.0 - space) + rx), w * (in.y + ox * ox * warp)};
}
FlamePoint wedgeWith(double r, double baseAngle, double w, double ang, double hole, double count, double swirlK) {
  double a = baseAngle + swirlK * r;
  const double c = std::floor((count * a + kPi) / kPi * 0.5);
  const double comp = 1.0 - ang * count / kPi * 0.5;
  a = a * comp + c * ang;
  const double rr = w * (r + hole);
  return {rr * std::cos(a), rr * std::sin(a)};
}
FlamePoint wedge(const VariationInput& in, double w) {
  return wedgeWith(radius(in), angleYx(in), w, in.param[0], in.param[1],
                   in.param[2], in.param[3]);
}
FlamePoint wedgeSph(const VariationInput& in, double w) {
  return wedgeWith(1.0 / (radius(in) + kEps), angleYx(in), w, in.param[0],
                   in.param[1], in.param[2],
                   in.param[3]);
}
FlamePoint whorl(const VariationInput& in, double w) {
  const double r = radius(in);
  const double a = angleYx(in) + (r < w ? in.param[0] : in.param[1]) / (w - r);
  return scaled(w, r * std::cos(a), r * std::sin(a));
}
FlamePoint waves2(const VariationInput& in, double w) {
  return scaled(w, in.x + in.param[1] * std::sin(in.y * in.param[0]),
                in.y + in.param[3] * std::sin(in.x * in.param[2]));
}
// The complex functions (exp, log, sin, …) of z = x + iy.
FlamePoint cexp(const VariationInput& in, double w) {
  const double e = std::exp(in.x);
  return scaled(w, e * std::cos(in.y), e * std::sin(in.y));
}
FlamePoint clog(const VariationInput& in, double w) { return scaled(w, 0.5 * std::log(sumsq(in)), angleYx(in)); }
FlamePoint csin(const VariationInput& in, double w) {
  return scaled(w, std::sin(in.x) * std::cosh(in.y), std::cos(in.x) * std::sinh(in.y));
}
FlamePoint ccos(const VariationInput& in, double w) {
  return scaled(w, std::cos(in.x) * std::cosh(in.y), -std::sin(in.x) * std::sinh(in.y));
}
FlamePoint ctan(const VariationInput& in, double w) {
  const double den = 1.0 / (std::cos(2.0 * in.x) + std::cosh(2.0 * in.y));
  return scaled(w, den * std::sin(2.0 * in.x), den * std::sinh(2.0 * in.y));
}
FlamePoint csec(const VariationInput& in, double w) {
  const double den = 2.0 / (std::cos(2.0 * in.x) + std::cosh(2.0 * in.y));
  return scaled(w, den * std::cos(in.x) * std::cosh(in.y), den * std::sin(in.x) * std::sinh(in.y));
}
FlamePoint ccsc(const VariationInput& in, double w) {
  const double den = 2.0 / (std::cosh(2.0 * in.y) - std::cos(2.0 * in.x));
  return scaled(w, den * std::sin(in.x) * std::cosh(in.y), -den * std::cos(in.x) * std::sinh(in.y));
}
FlamePoint ccot(const VariationInput& in, double w) {
  const double den = 1.0 / (std::cosh(2.0 * in.y) - std::cos(2.0 * in.x));
  return scaled(w, den * std::sin(2.0 * in.x), -den * std::sinh(2.0 * in.y));
}
FlamePoint csinh(const VariationInput& in, double w) {
  return scaled(w, std::sinh(in.x) * std::cos(in.y), std::cosh(in.x) * std::sin(in.y));
}
FlamePoint ccosh(const VariationInput& in, double w) {
  return scaled(w, std::cosh(in.x) * std::cos(in.y), std::sinh(in.x) * std::sin(in.y));
}
FlamePoint ctanh(const VariationInput& in, double w) {
  const double den = 1.0 / (std::cos(2.0 * in.y) + std::cosh(2.0 * in.x));
  return scaled(w, den * std::sinh(2.0 * in.x), den * std::sin(2.0 * in.y));
}
FlamePoint csech(const VariationInput& in, double w) {
  const double den = 2.0 / (std::cos(2.0 * in.y) + std::cosh(2.0 * in.x));
  return scaled(w, den * std::cos(in.y) * std::cosh(in.x), -den * std::sin(in.y) * std::sinh(in.x));
}
FlamePoint ccsch(const VariationInput& in, double w) {
  const double den = 2.0 / (std::cosh(2.0 * in.x) - std::cos(2.0 * in.y));
  return scaled(w, den * std::sinh(in.x) * std::cos(in.y), -den * std::cosh(in.x) * std::sin(in.y));
}
FlamePoint ccoth(const VariationInput& in, double w) {
  const double den = 1.0 / (std::cosh(2.0 * in.x) - std::cos(2.0 * in.y));
  return scaled(w, den * std::sinh(2.0 * in.x), den * std::sin(2.0 * in.y));
}
FlamePoint auger(const VariationInput& in, double w) {
  const double freq = in.param[0], aw = in.param[1],
               sym = in.param[2], sc = in.param[3];
  const double s = std::sin(freq * in.x), t = std::sin(freq * in.y);
  const double dy = in.y + aw * (sc * s / 2.0 + std::fabs(in.y) * s);
  const double dx = in.x + aw * (sc * t / 2.0 + std::fabs(in.x) * t);
  return {w * (in.x + sym * (dx - in.x)), w * dy};
}
FlamePoint flux(const VariationInput& in, double w) {
  const double spread = in.param[0], xpw = in.x + w, xmw = in.x - w, y2 = in.y * in.y;
  const double r = w * (2.0 + spread) * std::sqrt(std::sqrt(y2 + xpw * xpw) / std::sqrt(y2 + xmw * xmw));
  const double a = (std::atan2(in.y, xmw) - std::atan2(in.y, xpw)) * 0.5;
  return {r * std::cos(a), r * std::sin(a)};
}
FlamePoint mobius(const VariationInput& in, double w) {
  const double ra = in.param[0], ia = in.param[1],
               rb = in.param[2], ib = in.param[3],
               rc = in.param[4], ic = in.param[5],
               rd = in.param[6], id = in.param[7];
  const double ru = ra * in.x - ia * in.y + rb, iu = ra * in.y + ia * in.x + ib;
  const double rv = rc * in.x - ic * in.y + rd, iv = rc * in.y + ic * in.x + id;
  const double k = w / (rv * rv + iv * iv);
  return {k * (ru * rv + iu * iv), k * (iu * rv - ru * iv)};
}
FlamePoint escher(const VariationInput& in, double w) {
  const double beta = in.param[0], a = angleYx(in), lnr = 0.5 * std::log(sumsq(in));
  const double vc = 0.5 * (1.0 + std::cos(beta)), vd = 0.5 * std::sin(beta);
  const double m = w * std::exp(vc * lnr - vd * a), n = vc * a + vd * lnr;
  return {m * std::cos(n), m * std::sin(n)};
}

// flam3's edisc and lazysusan (the Apophysis plugin pack), deterministic.
FlamePoint edisc(const VariationInput& in, double w) {
  const double tmp = sumsq(in) + 1.0, tmp2 = 2.0 * in.x;
  const double xmax = 0.5 * (std::sqrt(tmp + tmp2) + std::sqrt(tmp - tmp2));
  const double a1 = std::log(xmax + std::sqrt(xmax - 1.0)), a2 = -std::acos(in.x / xmax);
  const double k = w / 11.57034632;
  double snv = std::sin(a1);
  const double csv = std::cos(a1);
  if (in.y > 0.0) snv = -snv;
  return {k * std::cosh(a2) * csv, k * std::sinh(a2) * snv};
}
FlamePoint lazysusan(const VariationInput& in, double w) {
  const double lx = in.param[0], ly = in.param[1], spin = in.param[2], space = in.param[3], twist = in.param[4];
  const double x = in.x - lx, y = in.y + ly;
  double r = std::sqrt(x * x + y * y);
  if (r < w) {
    const double a = std::atan2(y, x) + spin + twist * (w - r);
    r = w * r;
    return {r * std::cos(a) + lx, r * std::sin(a) - ly};
  }
  r = w * (1.0 + space / r);
  return {r * x + lx, r * y - ly};
}

// The random variations: each draws from the sample's own stream (variationUniform), in flam3's
// order of draws, so their distributions are flam3's.
double uniform(const VariationInput& in) { return variationUniform(*in.random); }
/// flam3's pseudo-Gaussian: the sum of four uniforms, minus 2.
double pseudoGaussian(const VariationInput& in) {
  const double a = uniform(in), b = uniform(in), c = uniform(in), d = uniform(in);
  return a + b + c + d - 2.0;
}
// Draves & Reckase, appendix: julia takes one of the two square roots at random.
FlamePoint julia(const VariationInput& in, double w) {
  double a = 0.5 * angle(in);
  if (variationUniform(*in.random) < 0.5) a += kPi;
  const double r = w * std::sqrt(radius(in));
  return {r * std::cos(a), r * std::sin(a)};
}
FlamePoint noise(const VariationInput& in, double w) {
  const double t = uniform(in) * 2.0 * kPi, r = w * uniform(in);
  return {in.x * r * std::cos(t), in.y * r * std::sin(t)};
}
FlamePoint julian(const VariationInput& in, double w) {
  const double power = in.param[0], dist = in.param[1];
  const double rN = std::fabs(power), cn = dist / power / 2.0;
  const double t = std::trunc(rN * uniform(in));
  const double a = (angleYx(in) + 2.0 * kPi * t) / power, r = w * std::pow(sumsq(in), cn);
  return {r * std::cos(a), r * std::sin(a)};
}
FlamePoint juliascope(const VariationInput& in, double w) {
  const double power = in.param[0], dist = in.param[1];
  const double rN = std::fabs(power), cn = dist / power / 2.0;
  const int t = int(std::trunc(rN * uniform(in)));
  const double a = ((t & 1) == 0 ? 2.0 * kPi * t + angleYx(in) : 2.0 * kPi * t - angleYx(in)) / power;
  const double r = w * std::pow(sumsq(in), cn);
  return {r * std::cos(a), r * std::sin(a)};
}
FlamePoint blur(const VariationInput& in, double w) {
  const double t = uniform(in) * 2.0 * kPi, r = w * uniform(in);
  return {r * std::cos(t), r * std::sin(t)};
}
FlamePoint gaussianBlur(const VariationInput& in, double w) {
  const double a = uniform(in) * 2.0 * kPi, r = w * pseudoGaussian(in);
  return {r * std::cos(a), r * std::sin(a)};
}
FlamePoint radialBlur(const VariationInput& in, double w) {
  const double angleParam = in.param[0] * kPi / 2.0;
  const double spin = std::sin(angleParam), zoom = std::cos(angleParam);
  const double g = w * pseudoGaussian(in);
  const double ra = radius(in), a = angleYx(in) + spin * g, rz = zoom * g - 1.0;
  return {ra * std::cos(a) + rz * in.x, ra * std::sin(a) + rz * in.y};
}
FlamePoint pie(const VariationInput& in, double w) {
  const double slices = in.param[0], rotation = in.param[1], thickness = in.param[2];
  const int slice = int(uniform(in) * slices + 0.5);
  const double a = rotation + 2.0 * kPi * (slice + uniform(in) * thickness) / slices;
  const double r = w * uniform(in);
  return {r * std::cos(a), r * std::sin(a)};
}
// arch, rays, blade and twintrian use the weight inside the map, as flam3 does.
FlamePoint arch(const VariationInput& in, double w) {
  const double a = uniform(in) * w * kPi, s = std::sin(a), c = std::cos(a);
  return {w * s, w * s * s / c};
}
FlamePoint square(const VariationInput& in, double w) {
  const double u = uniform(in), v = uniform(in);
  return {w * (u - 0.5), w * (v - 0.5)};
}
FlamePoint rays(const VariationInput& in, double w) {
  const double a = w * uniform(in) * kPi, r = w / (sumsq(in) + kEps), t = w * std::tan(a) * r;
  return {t * std::cos(in.x), t * std::sin(in.y)};
}
FlamePoint blade(const VariationInput& in, double w) {
  const double r = uniform(in) * w * radius(in), s = std::sin(r), c = std::cos(r);
  return {w * in.x * (c + s), w * in.x * (c - s)};
}
FlamePoint twintrian(const VariationInput& in, double w) {
  const double r = uniform(in) * w * radius(in), s = std::sin(r), c = std::cos(r);
  double diff = std::log10(s * s) + c;
  if (!std::isfinite(diff) || std::fabs(diff) > 1e10) diff = -30.0;
  return {w * in.x * diff, w * in.x * (diff - s * kPi)};
}
FlamePoint superShape(const VariationInput& in, double w) {
  const double rnd = in.param[0], m = in.param[1], n1 = in.param[2], n2 = in.param[3], n3 = in.param[4],
               holes = in.param[5];
  const double theta = m / 4.0 * angleYx(in) + kPi / 4.0;
  const double t1 = std::pow(std::fabs(std::cos(theta)), n2), t2 = std::pow(std::fabs(std::sin(theta)), n3);
  const double r0 = radius(in);
  const double r = w * ((rnd * uniform(in) + (1.0 - rnd) * r0) - holes) * std::pow(t1 + t2, -1.0 / n1) / r0;
  return {r * in.x, r * in.y};
}
FlamePoint flower(const VariationInput& in, double w) {
  const double petals = in.param[0], holes = in.param[1];
  const double r = w * (uniform(in) - holes) * std::cos(petals * angleYx(in)) / radius(in);
  return {r * in.x, r * in.y};
}
FlamePoint conic(const VariationInput& in, double w) {
  const double eccentricity = in.param[0], holes = in.param[1];
  const double r0 = radius(in), ct = in.x / r0;
  const double r = w * (uniform(in) - holes) * eccentricity / (1.0 + eccentricity * ct) / r0;
  return {r * in.x, r * in.y};
}
FlamePoint parabola(const VariationInput& in, double w) {
  const double height = in.param[0], width = in.param[1];
  const double r = radius(in), s = std::sin(r), c = std::cos(r);
  const double u = uniform(in), v = uniform(in);
  return {height * w * s * s * u, width * w * c * v};
}
FlamePoint boarders(const VariationInput& in, double w) {
  const double rx = std::nearbyint(in.x), ry = std::nearbyint(in.y), ox = in.x - rx, oy = in.y - ry;
  if (uniform(in) >= 0.75) return scaled(w, ox * 0.5 + rx, oy * 0.5 + ry);
  if (std::fabs(ox) >= std::fabs(oy)) {
    if (ox >= 0.0) return scaled(w, ox * 0.5 + rx + 0.25, oy * 0.5 + ry + 0.25 * oy / ox);
    return scaled(w, ox * 0.5 + rx - 0.25, oy * 0.5 + ry - 0.25 * oy / ox);
  }
  if (oy >= 0.0) return scaled(w, ox * 0.5 + rx + ox / oy * 0.25, oy * 0.5 + ry + 0.25);
  return scaled(w, ox * 0.5 + rx - ox / oy * 0.25, oy * 0.5 + ry - 0.25);
}
FlamePoint cpow(const VariationInput& in, double w) {
  const double cr = in.param[0], ci = in.param[1], power = in.param[2];
  const double a = angleYx(in), lnr = 0.5 * std::log(sumsq(in));
  const double va = 2.0 * kPi / power, vc = cr / power, vd = ci / power;
  const double ang = vc * a + vd * lnr + va * std::floor(power * uniform(in));
  const double m = w * std::exp(vc * lnr - vd * a);
  return {m * std::cos(ang), m * std::sin(ang)};
}
FlamePoint wedgeJulia(const VariationInput& in, double w) {
  const double ang = in.param[0], count = in.param[1], power = in.param[2], dist = in.param[3];
  const double cf = 1.0 - ang * count / kPi * 0.5, rN = std::fabs(power), cn = dist / power / 2.0;
  const double r = w * std::pow(sumsq(in), cn);
  const int t = int(rN * uniform(in));
  double a = (angleYx(in) + 2.0 * kPi * t) / power;
  const double c = std::floor((count * a + kPi) / kPi * 0.5);
  a = a * cf + c * ang;
  return {r * std::cos(a), r * std::sin(a)};
}
/// pre_blur moves the point by a pseudo-Gaussian step (flam3 applies it after the pre-affine map,
/// before every other variation); its returned offset is added to the input by evaluateVariations.
FlamePoint preBlur(const VariationInput& in, double w) {
  const double g = w * pseudoGaussian(in), a = uniform(in) * 2.0 * kPi;
  return {g * std::cos(a), g * std::sin(a)};
}

}  // namespace

double variationUniform(std::uint64_t& state) {
  // The chaos kernel's generator (render/chaos_kernel.h Rng::next), 53 bits into [0, 1).
  state += 0xA0761D6478BD642Full;
  const unsigned __int128 m = (unsigned __int128)state * (state ^ 0xE7037ED1A0B428DBull);
  const std::uint64_t bits = std::uint64_t(m >> 64) ^ std::uint64_t(m);
  return double(bits >> 11) * 0x1.0p-53;
}

const std::vector<FlameVariation>& flameVariations() {
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
    flatten |= v.apply == flatten_;
  }
  if (flatten) sum.z = 0.0;
  return sum;
}

}  // namespace gridifs
