#include "io/flame_variations.h"

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
double param(const VariationInput& in, const char* name, double fallback) {
  return variationParameter(in, name, fallback);
}

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
FlamePoint sinusoidal(const VariationInput& in, double w) { return scaled(w, std::sin(in.x), std::sin(in.y)); }
FlamePoint spherical(const VariationInput& in, double w) {
  const double r2 = w / (sumsq(in) + kEps);
  return {r2 * in.x, r2 * in.y};
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
  const double dx2 = 1.0 / (in.coefs.c * in.coefs.c + kEps), dy2 = 1.0 / (in.coefs.f * in.coefs.f + kEps);
  return scaled(w, in.x + in.coefs.b * std::sin(in.y * dx2), in.y + in.coefs.e * std::sin(in.x * dy2));
}
FlamePoint fisheye(const VariationInput& in, double w) {
  const double r = 2.0 * w / (radius(in) + 1.0);
  return {r * in.y, r * in.x};  // the appendix notes the reversed order
}
FlamePoint popcorn(const VariationInput& in, double w) {
  return scaled(w, in.x + in.coefs.c * std::sin(std::tan(3.0 * in.y)),
                in.y + in.coefs.f * std::sin(std::tan(3.0 * in.x)));
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
  const double dx = in.coefs.c * in.coefs.c + kEps, r0 = radius(in);
  const double r = w * (std::fmod(r0 + dx, 2.0 * dx) - dx + r0 * (1.0 - dx));
  return {r * cosA(in), r * sinA(in)};
}
FlamePoint fan(const VariationInput& in, double w) {
  const double dx = kPi * (in.coefs.c * in.coefs.c + kEps), dy = in.coefs.f, half = 0.5 * dx;
  double a = angle(in);
  const double r = w * radius(in);
  a += std::fmod(a + dy, dx) > half ? -half : half;
  return {r * std::cos(a), r * std::sin(a)};
}
FlamePoint blob(const VariationInput& in, double w) {
  const double low = param(in, "blob_low", 0.0), high = param(in, "blob_high", 1.0),
               wavesCount = param(in, "blob_waves", 1.0);
  const double r = radius(in) * (low + (high - low) * (0.5 + 0.5 * std::sin(wavesCount * angle(in))));
  return scaled(w, sinA(in) * r, cosA(in) * r);
}
FlamePoint pdj(const VariationInput& in, double w) {
  const double a = param(in, "pdj_a", 0.0), b = param(in, "pdj_b", 0.0), c = param(in, "pdj_c", 0.0),
               d = param(in, "pdj_d", 0.0);
  return scaled(w, std::sin(a * in.y) - std::cos(b * in.x), std::sin(c * in.x) - std::cos(d * in.y));
}
FlamePoint fan2(const VariationInput& in, double w) {
  const double fx = param(in, "fan2_x", 0.0), dy = param(in, "fan2_y", 0.0);
  const double dx = kPi * (fx * fx + kEps), half = 0.5 * dx;
  double a = angle(in);
  const double r = w * radius(in);
  const double t = a + dy - dx * std::trunc((a + dy) / dx);
  a += t > half ? -half : half;
  return {r * std::sin(a), r * std::cos(a)};
}
FlamePoint rings2(const VariationInput& in, double w) {
  const double v = param(in, "rings2_val", 0.0), dx = v * v + kEps;
  double r = radius(in);
  r += -2.0 * dx * std::trunc((r + dx) / (2.0 * dx)) + r * (1.0 - dx);
  return scaled(w, sinA(in) * r, cosA(in) * r);
}
FlamePoint eyefish(const VariationInput& in, double w) {
  const double r = 2.0 * w / (radius(in) + 1.0);
  return {r * in.x, r * in.y};
}
FlamePoint bubble(const VariationInput& in, double w) {
  const double r = w / (0.25 * sumsq(in) + 1.0);
  return {r * in.x, r * in.y};
}
FlamePoint cylinder(const VariationInput& in, double w) { return scaled(w, std::sin(in.x), in.y); }
FlamePoint perspective(const VariationInput& in, double w) {
  const double ang = param(in, "perspective_angle", 0.0) * kPi / 2.0, dist = param(in, "perspective_dist", 0.0);
  const double t = 1.0 / (dist - in.y * std::sin(ang));
  return {w * dist * in.x * t, w * dist * std::cos(ang) * in.y * t};
}
FlamePoint ngon(const VariationInput& in, double w) {
  const double pw = param(in, "ngon_power", 3.0), sides = param(in, "ngon_sides", 5.0),
               corners = param(in, "ngon_corners", 2.0), circle = param(in, "ngon_circle", 1.0);
  const double rFactor = std::pow(sumsq(in), pw / 2.0), b = 2.0 * kPi / sides;
  double phi = angleYx(in) - b * std::floor(angleYx(in) / b);
  if (phi > b / 2.0) phi -= b;
  const double amp = (corners * (1.0 / (std::cos(phi) + kEps) - 1.0) + circle) / (rFactor + kEps);
  return scaled(w, in.x * amp, in.y * amp);
}
FlamePoint curl(const VariationInput& in, double w) {
  const double c1 = param(in, "curl_c1", 0.0), c2 = param(in, "curl_c2", 0.0);
  const double re = 1.0 + c1 * in.x + c2 * (in.x * in.x - in.y * in.y), im = c1 * in.y + 2.0 * c2 * in.x * in.y;
  const double r = w / (re * re + im * im);
  return {(in.x * re + in.y * im) * r, (in.y * re - in.x * im) * r};
}
FlamePoint rectangles(const VariationInput& in, double w) {
  const double rx = param(in, "rectangles_x", 0.0), ry = param(in, "rectangles_y", 0.0);
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
  const double rot = param(in, "disc2_rot", 0.0), twist = param(in, "disc2_twist", 0.0);
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
  const double x = in.x < 0.0 ? in.x * param(in, "bent2_x", 1.0) : in.x;
  const double y = in.y < 0.0 ? in.y * param(in, "bent2_y", 1.0) : in.y;
  return scaled(w, x, y);
}
FlamePoint bipolar(const VariationInput& in, double w) {
  const double x2y2 = sumsq(in), t = x2y2 + 1.0, x2 = 2.0 * in.x;
  double y = 0.5 * std::atan2(2.0 * in.y, x2y2 - 1.0) - kPi / 2.0 * param(in, "bipolar_shift", 0.0);
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
  const double size = param(in, "cell_size", 1.0), inv = 1.0 / size;
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
  const double xl = param(in, "curve_xlength", 1.0), yl = param(in, "curve_ylength", 1.0);
  const double xlen = std::max(xl * xl, 1e-20), ylen = std::max(yl * yl, 1e-20);
  return scaled(w, in.x + param(in, "curve_xamp", 0.0) * std::exp(-in.y * in.y / xlen),
                in.y + param(in, "curve_yamp", 0.0) * std::exp(-in.x * in.x / ylen));
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
  return scaled(w, modulusAxis(in.x, param(in, "modulus_x", 1.0)), modulusAxis(in.y, param(in, "modulus_y", 1.0)));
}
FlamePoint oscilloscope(const VariationInput& in, double w) {
  const double sep = param(in, "oscilloscope_separation", 1.0), freq = param(in, "oscilloscope_frequency", kPi),
               amp = param(in, "oscilloscope_amplitude", 1.0), damp = param(in, "oscilloscope_damping", 0.0);
  const double c = std::cos(2.0 * kPi * freq * in.x);
  const double t = (damp == 0.0 ? amp * c : amp * std::exp(-std::fabs(in.x) * damp) * c) + sep;
  return {w * in.x, std::fabs(in.y) <= t ? -w * in.y : w * in.y};
}
FlamePoint polar2(const VariationInput& in, double w) {
  const double p = w / kPi;
  return {p * angle(in), p / 2.0 * std::log(sumsq(in))};
}
FlamePoint popcorn2(const VariationInput& in, double w) {
  const double c = param(in, "popcorn2_c", 0.0);
  return scaled(w, in.x + param(in, "popcorn2_x", 0.0) * std::sin(std::tan(in.y * c)),
                in.y + param(in, "popcorn2_y", 0.0) * std::sin(std::tan(in.x * c)));
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
  return scaled(w, separationAxis(in.x, param(in, "separation_x", 0.0), param(in, "separation_xinside", 0.0)),
                separationAxis(in.y, param(in, "separation_y", 0.0), param(in, "separation_yinside", 0.0)));
}
FlamePoint split(const VariationInput& in, double w) {
  const double xs = param(in, "split_xsize", 0.0), ys = param(in, "split_ysize", 0.0);
  return {std::cos(in.y * ys * kPi) >= 0.0 ? w * in.x : -w * in.x,
          std::cos(in.x * xs * kPi) >= 0.0 ? w * in.y : -w * in.y};
}
FlamePoint splits(const VariationInput& in, double w) {
  const double sx = param(in, "splits_x", 0.0), sy = param(in, "splits_y", 0.0);
  return scaled(w, in.x >= 0.0 ? in.x + sx : in.x - sx, in.y >= 0.0 ? in.y + sy : in.y - sy);
}
FlamePoint stripes(const VariationInput& in, double w) {
  const double space = param(in, "stripes_space", 0.0), warp = param(in, "stripes_warp", 0.0);
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
  return wedgeWith(radius(in), angleYx(in), w, param(in, "wedge_angle", 0.0), param(in, "wedge_hole", 0.0),
                   param(in, "wedge_count", 1.0), param(in, "wedge_swirl", 0.0));
}
FlamePoint wedgeSph(const VariationInput& in, double w) {
  return wedgeWith(1.0 / (radius(in) + kEps), angleYx(in), w, param(in, "wedge_sph_angle", 0.0),
                   param(in, "wedge_sph_hole", 0.0), param(in, "wedge_sph_count", 1.0),
                   param(in, "wedge_sph_swirl", 0.0));
}
FlamePoint whorl(const VariationInput& in, double w) {
  const double r = radius(in);
  const double a = angleYx(in) + (r < w ? param(in, "whorl_inside", 1.0) : param(in, "whorl_outside", 1.0)) / (w - r);
  return scaled(w, r * std::cos(a), r * std::sin(a));
}
FlamePoint waves2(const VariationInput& in, double w) {
  return scaled(w, in.x + param(in, "waves2_scalex", 0.0) * std::sin(in.y * param(in, "waves2_freqx", 0.0)),
                in.y + param(in, "waves2_scaley", 0.0) * std::sin(in.x * param(in, "waves2_freqy", 0.0)));
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
  const double freq = param(in, "auger_freq", 1.0), aw = param(in, "auger_weight", 0.5),
               sym = param(in, "auger_sym", 0.0), sc = param(in, "auger_scale", 1.0);
  const double s = std::sin(freq * in.x), t = std::sin(freq * in.y);
  const double dy = in.y + aw * (sc * s / 2.0 + std::fabs(in.y) * s);
  const double dx = in.x + aw * (sc * t / 2.0 + std::fabs(in.x) * t);
  return {w * (in.x + sym * (dx - in.x)), w * dy};
}
FlamePoint flux(const VariationInput& in, double w) {
  const double spread = param(in, "flux_spread", 0.0), xpw = in.x + w, xmw = in.x - w, y2 = in.y * in.y;
  const double r = w * (2.0 + spread) * std::sqrt(std::sqrt(y2 + xpw * xpw) / std::sqrt(y2 + xmw * xmw));
  const double a = (std::atan2(in.y, xmw) - std::atan2(in.y, xpw)) * 0.5;
  return {r * std::cos(a), r * std::sin(a)};
}
FlamePoint mobius(const VariationInput& in, double w) {
  const double ra = param(in, "mobius_re_a", 1.0), ia = param(in, "mobius_im_a", 0.0),
               rb = param(in, "mobius_re_b", 0.0), ib = param(in, "mobius_im_b", 0.0),
               rc = param(in, "mobius_re_c", 0.0), ic = param(in, "mobius_im_c", 0.0),
               rd = param(in, "mobius_re_d", 1.0), id = param(in, "mobius_im_d", 0.0);
  const double ru = ra * in.x - ia * in.y + rb, iu = ra * in.y + ia * in.x + ib;
  const double rv = rc * in.x - ic * in.y + rd, iv = rc * in.y + ic * in.x + id;
  const double k = w / (rv * rv + iv * iv);
  return {k * (ru * rv + iu * iv), k * (iu * rv - ru * iv)};
}
FlamePoint escher(const VariationInput& in, double w) {
  const double beta = param(in, "escher_beta", 0.0), a = angleYx(in), lnr = 0.5 * std::log(sumsq(in));
  const double vc = 0.5 * (1.0 + std::cos(beta)), vd = 0.5 * std::sin(beta);
  const double m = w * std::exp(vc * lnr - vd * a), n = vc * a + vd * lnr;
  return {m * std::cos(n), m * std::sin(n)};
}

const std::vector<const char*>& randomNames() {
  static const std::vector<const char*> names = {"julia", "noise", "julian", "juliascope", "blur", "gaussian_blur",
                                                 "radial_blur", "pie", "arch", "square", "rays", "blade", "twintrian",
                                                 "super_shape", "flower", "conic", "parabola", "boarders", "cpow",
                                                 "pre_blur", "wedge_julia", "lazysusan", "edisc",
                                                 // 3D ones (Apophysis 7X, JWildfire, Fractorium)
                                                 "zblur", "blur3D", "pre_blur3D", "julia3D", "julia3Dz"};
  return names;
}

const std::vector<const char*>& randomParameterPrefixes() {
  static const std::vector<const char*> prefixes = {"julian_",      "juliascope_",  "radial_blur_", "pie_",
                                                    "super_shape_", "flower_",      "conic_",       "parabola_",
                                                    "cpow_",        "wedge_julia_", "julia3D_",     "julia3Dz_"};
  return prefixes;
}

}  // namespace

double variationParameter(const VariationInput& in, const char* name, double fallback) {
  if (!in.params) return fallback;
  const auto it = in.params->find(name);
  return it == in.params->end() ? fallback : it->second;
}

const std::vector<FlameVariation>& flameVariations() {
  static const std::vector<FlameVariation> table = {
      {"linear", {}, linear},
      {"linear3D", {}, linear},
      {"zscale", {}, zscale},
      {"ztranslate", {}, ztranslate},
      {"zcone", {}, zcone},
      {"flatten", {}, flatten},
      {"sinusoidal", {}, sinusoidal},
      {"spherical", {}, spherical},
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
      {"bent", {}, bent},
      {"waves", {}, waves},
      {"fisheye", {}, fisheye},
      {"popcorn", {}, popcorn},
      {"exponential", {}, exponential},
      {"power", {}, power},
      {"cosine", {}, cosine},
      {"rings", {}, rings},
      {"fan", {}, fan},
      {"blob", {{"blob_low", 0.0}, {"blob_high", 1.0}, {"blob_waves", 1.0}}, blob},
      {"pdj", {{"pdj_a", 0.0}, {"pdj_b", 0.0}, {"pdj_c", 0.0}, {"pdj_d", 0.0}}, pdj},
      {"fan2", {{"fan2_x", 0.0}, {"fan2_y", 0.0}}, fan2},
      {"rings2", {{"rings2_val", 0.0}}, rings2},
      {"eyefish", {}, eyefish},
      {"bubble", {}, bubble},
      {"cylinder", {}, cylinder},
      {"perspective", {{"perspective_angle", 0.0}, {"perspective_dist", 0.0}}, perspective},
      {"ngon", {{"ngon_sides", 5.0}, {"ngon_power", 3.0}, {"ngon_circle", 1.0}, {"ngon_corners", 2.0}}, ngon},
      {"curl", {{"curl_c1", 0.0}, {"curl_c2", 0.0}}, curl},
      {"rectangles", {{"rectangles_x", 0.0}, {"rectangles_y", 0.0}}, rectangles},
      {"tangent", {}, tangent},
      {"secant2", {}, secant2},
      {"cross", {}, cross},
      {"disc2", {{"disc2_rot", 0.0}, {"disc2_twist", 0.0}}, disc2},
      {"bent2", {{"bent2_x", 1.0}, {"bent2_y", 1.0}}, bent2},
      {"bipolar", {{"bipolar_shift", 0.0}}, bipolar},
      {"butterfly", {}, butterfly},
      {"cell", {{"cell_size", 1.0}}, cell},
      {"curve", {{"curve_xamp", 0.0}, {"curve_yamp", 0.0}, {"curve_xlength", 1.0}, {"curve_ylength", 1.0}}, curve},
      {"elliptic", {}, elliptic},
      {"escher", {{"escher_beta", 0.0}}, escher},
      {"foci", {}, foci},
      {"loonie", {}, loonie},
      {"modulus", {{"modulus_x", 1.0}, {"modulus_y", 1.0}}, modulus},
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
      {"wedge_sph",
       {{"wedge_sph_angle", 0.0}, {"wedge_sph_hole", 0.0}, {"wedge_sph_count", 1.0}, {"wedge_sph_swirl", 0.0}},
       wedgeSph},
      {"whorl", {{"whorl_inside", 1.0}, {"whorl_outside", 1.0}}, whorl},
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
       {{"mobius_re_a", 1.0},
        {"mobius_im_a", 0.0},
        {"mobius_re_b", 0.0},
        {"mobius_im_b", 0.0},
        {"mobius_re_c", 0.0},
        {"mobius_im_c", 0.0},
        {"mobius_re_d", 1.0},
        {"mobius_im_d", 0.0}},
       mobius},
  };
  return table;
}

const FlameVariation* findFlameVariation(const std::string& name) {
  for (const FlameVariation& v : flameVariations())
    if (name == v.name) return &v;
  return nullptr;
}

bool flameVariationWritesZ(const std::string& name) {
  return name == "linear" || name == "linear3D" || name == "zscale" || name == "ztranslate" || name == "zcone" ||
         name == "flatten";
}

bool isAffineFlameVariation(const std::string& name) {
  return name == "linear" || name == "linear3D" || name == "zscale" || name == "ztranslate" || name == "flatten";
}

bool isRandomFlameVariation(const std::string& name) {
  return std::any_of(randomNames().begin(), randomNames().end(), [&](const char* n) { return name == n; });
}

bool isRandomFlameVariationParameter(const std::string& name) {
  return std::any_of(randomParameterPrefixes().begin(), randomParameterPrefixes().end(),
                     [&](const char* p) { return name.rfind(p, 0) == 0; });
}

}  // namespace gridifs
