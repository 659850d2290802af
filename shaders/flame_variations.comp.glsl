// The flame variations on the GPU (Draves & Reckase 2003, §3 and the appendix's catalogue; flam3
// 3.1's variations.c for the later ones), in float: the formulas, 3D forms and parameter orders of
// core/variations/flame_variations.cpp, which stays the reference. Prepended to chaos_game.comp.glsl
// when the IFS has variations, after the host's defines:
//   V_<name>    each variation's index in flameVariations() (the C++ table is the one numbering);
//   USE_<name>  1 for the variations this IFS uses, else 0: the program is specialised to them, so
//               the switches hold only their cases (llvmpipe, measured on a three-function IFS:
//               compile 1.8 s instead of 6.8 s and 2.3 times the points per second).
// A function's variation stage is f(p) = post(Σ w_i V_i(g(p))), g its grid map extrapolated beyond
// X; the stages live in `stages` (gpu/variation_stage.h documents the layout). Planar variations
// return (x, y, ·) and the stage carries w·z for them; the term's flags say which write z.

layout(std430, binding = 9) readonly buffer Stages { uvec4 stages[]; };

uint nextRandom(inout uvec4 s);  // the chain's stream (chaos_game.comp.glsl)

const float kPi = 3.14159265358979;
const float kEps = 1e-10;  // flam3's guard against division by zero

float uniform01(inout uvec4 rng) { return float(nextRandom(rng) >> 8) * (1.0 / 16777216.0); }
// C's atan2: GLSL leaves atan(0, 0) undefined.
float atan2(float y, float x) { return (x == 0.0 && y == 0.0) ? 0.0 : atan(y, x); }
// C's fmod truncates the quotient; GLSL's mod floors it.
float fmodC(float x, float y) { return x - y * trunc(x / y); }
float log10f(float x) { return log(x) * 0.43429448190325182; }
// Whether x is finite and |x| ≤ bound, on the bits (immune to a compiler that assumes no NaN).
bool finiteWithin(float x, float bound) { return (floatBitsToUint(x) & 0x7FFFFFFFu) <= floatBitsToUint(bound); }

float sumsq(vec3 p) { return dot(p.xy, p.xy); }
float radius(vec3 p) { return sqrt(sumsq(p)); }
float angle(vec3 p) { return atan2(p.x, p.y); }  // flam3 measures it from the y axis
float angleYx(vec3 p) { return atan2(p.y, p.x); }
vec2 polarPoint(float r, float a) { return r * vec2(cos(a), sin(a)); }

// Draves & Reckase 2003, appendix: variations 0–30 and the later deterministic ones of flam3.
vec2 vSwirl(vec3 p) {
  const float r2 = sumsq(p), s = sin(r2), c = cos(r2);
  return vec2(s * p.x - c * p.y, c * p.x + s * p.y);
}
vec2 vHorseshoe(vec3 p, float w) {
  const float r = w / (radius(p) + kEps);
  return vec2((p.x - p.y) * (p.x + p.y) * r, 2.0 * p.x * p.y * r);
}
vec2 vHandkerchief(vec3 p) {
  const float a = angle(p), r = radius(p);
  return vec2(r * sin(a + r), r * cos(a - r));
}
vec2 vHeart(vec3 p, float w) {
  const float a = radius(p) * angle(p), r = w * radius(p);
  return vec2(r * sin(a), -r * cos(a));
}
vec2 vDisc(vec3 p) {
  const float a = angle(p) / kPi, r = kPi * radius(p);
  return vec2(sin(r) * a, cos(r) * a);
}
vec2 vSpiral(vec3 p, float w) {
  const float r0 = radius(p), r = r0 + kEps, r1 = w / r;
  return vec2(r1 * (p.y / r0 + sin(r)), r1 * (p.x / r0 - cos(r)));
}
vec2 vHyperbolic(vec3 p) {
  const float r0 = radius(p), r = r0 + kEps;
  return vec2(p.x / r0 / r, p.y / r0 * r);
}
vec2 vDiamond(vec3 p) {
  const float r = radius(p);
  return vec2(p.x / r * cos(r), p.y / r * sin(r));
}
vec2 vEx(vec3 p) {
  const float a = angle(p), r = radius(p);
  const float n0 = sin(a + r), n1 = cos(a - r);
  const float m0 = n0 * n0 * n0 * r, m1 = n1 * n1 * n1 * r;
  return vec2(m0 + m1, m0 - m1);
}
vec2 vBent(vec3 p) { return vec2(p.x < 0.0 ? 2.0 * p.x : p.x, p.y < 0.0 ? p.y / 2.0 : p.y); }
// The dependent variations read the affine coefficients a b c d (c0) e f (c1.xy) of the grid map.
vec2 vWaves(vec3 p, vec4 c0, vec2 c1) {
  const float dx2 = 1.0 / (c0.z * c0.z + kEps), dy2 = 1.0 / (c1.y * c1.y + kEps);
  return vec2(p.x + c0.y * sin(p.y * dx2), p.y + c1.x * sin(p.x * dy2));
}
vec2 vPopcorn(vec3 p, vec4 c0, vec2 c1) {
  return vec2(p.x + c0.z * sin(tan(3.0 * p.y)), p.y + c1.y * sin(tan(3.0 * p.x)));
}
vec2 vExponential(vec3 p, float w) { return polarPoint(w * exp(p.x - 1.0), kPi * p.y); }
vec2 vPower(vec3 p, float w) {
  const float r0 = radius(p), s = p.x / r0, c = p.y / r0, r = w * pow(r0, s);
  return vec2(r * c, r * s);
}
vec2 vCosine(vec3 p) {
  const float a = p.x * kPi;
  return vec2(cos(a) * cosh(p.y), -sin(a) * sinh(p.y));
}
vec2 vRings(vec3 p, float w, vec4 c0) {
  const float dx = c0.z * c0.z + kEps, r0 = radius(p);
  const float r = w * (fmodC(r0 + dx, 2.0 * dx) - dx + r0 * (1.0 - dx));
  return vec2(r * p.y / r0, r * p.x / r0);
}
vec2 vFan(vec3 p, float w, vec4 c0, vec2 c1) {
  const float dx = kPi * (c0.z * c0.z + kEps), dy = c1.y, half_ = 0.5 * dx;
  float a = angle(p);
  a += fmodC(a + dy, dx) > half_ ? -half_ : half_;
  return polarPoint(w * radius(p), a);
}
vec2 vBlob(vec3 p, vec4 q) {
  const float r0 = radius(p), r = r0 * (q.x + (q.y - q.x) * (0.5 + 0.5 * sin(q.z * angle(p))));
  return vec2(p.x / r0 * r, p.y / r0 * r);
}
vec2 vPdj(vec3 p, vec4 q) { return vec2(sin(q.x * p.y) - cos(q.y * p.x), sin(q.z * p.x) - cos(q.w * p.y)); }
vec2 vFan2(vec3 p, float w, vec4 q) {
  const float dx = kPi * (q.x * q.x + kEps), half_ = 0.5 * dx;
  float a = angle(p);
  const float t = a + q.y - dx * trunc((a + q.y) / dx);
  a += t > half_ ? -half_ : half_;
  const float r = w * radius(p);
  return vec2(r * sin(a), r * cos(a));
}
vec2 vRings2(vec3 p, vec4 q) {
  const float dx = q.x * q.x + kEps, r0 = radius(p);
  const float r = r0 - 2.0 * dx * trunc((r0 + dx) / (2.0 * dx)) + r0 * (1.0 - dx);
  return vec2(p.x / r0 * r, p.y / r0 * r);
}
vec2 vPerspective(vec3 p, float w, vec4 q) {
  const float ang = q.x * kPi / 2.0, dist = q.y, t = 1.0 / (dist - p.y * sin(ang));
  return vec2(w * dist * p.x * t, w * dist * cos(ang) * p.y * t);
}
vec2 vNgon(vec3 p, vec4 q) {
  const float rFactor = pow(sumsq(p), q.y / 2.0), b = 2.0 * kPi / q.x, a = angleYx(p);
  float phi = a - b * floor(a / b);
  if (phi > b / 2.0) phi -= b;
  const float amp = (q.w * (1.0 / (cos(phi) + kEps) - 1.0) + q.z) / (rFactor + kEps);
  return p.xy * amp;
}
vec2 vCurl(vec3 p, float w, vec4 q) {
  const float re = 1.0 + q.x * p.x + q.y * (p.x * p.x - p.y * p.y), im = q.x * p.y + 2.0 * q.y * p.x * p.y;
  const float r = w / (re * re + im * im);
  return vec2((p.x * re + p.y * im) * r, (p.y * re - p.x * im) * r);
}
vec2 vRectangles(vec3 p, vec4 q) {
  return vec2(q.x == 0.0 ? p.x : (2.0 * floor(p.x / q.x) + 1.0) * q.x - p.x,
              q.y == 0.0 ? p.y : (2.0 * floor(p.y / q.y) + 1.0) * q.y - p.y);
}
vec2 vSecant2(vec3 p, float w) {
  const float cr = cos(w * radius(p)), icr = 1.0 / cr;
  return vec2(w * p.x, cr < 0.0 ? w * (icr + 1.0) : w * (icr - 1.0));
}
vec2 vCross(vec3 p, float w) {
  const float s = p.x * p.x - p.y * p.y, r = w * sqrt(1.0 / (s * s + kEps));
  return p.xy * r;
}
vec2 vDisc2(vec3 p, float w, vec4 q) {
  const float rot = q.x, twist = q.y;
  float sinAdd = sin(twist), cosAdd = cos(twist) - 1.0;
  if (twist > 2.0 * kPi) {
    const float k = 1.0 + twist - 2.0 * kPi;
    cosAdd *= k;
    sinAdd *= k;
  }
  if (twist < -2.0 * kPi) {
    const float k = 1.0 + twist + 2.0 * kPi;
    cosAdd *= k;
    sinAdd *= k;
  }
  const float t = rot * kPi * (p.x + p.y), r = w * angle(p) / kPi;
  return vec2((sin(t) + cosAdd) * r, (cos(t) + sinAdd) * r);
}
vec2 vBipolar(vec3 p, float w, vec4 q) {
  const float x2y2 = sumsq(p), t = x2y2 + 1.0, x2 = 2.0 * p.x;
  float y = 0.5 * atan2(2.0 * p.y, x2y2 - 1.0) - kPi / 2.0 * q.x;
  if (y > kPi / 2.0)
    y = -kPi / 2.0 + fmodC(y + kPi / 2.0, kPi);
  else if (y < -kPi / 2.0)
    y = kPi / 2.0 - fmodC(kPi / 2.0 - y, kPi);
  return vec2(w * 0.25 * (2.0 / kPi) * log((t + x2) / (t - x2)), w * (2.0 / kPi) * y);
}
vec2 vButterfly(vec3 p, float w) {
  const float wx = w * 1.3029400317411197908970256609023, y2 = 2.0 * p.y;  // 4 / sqrt(3π)
  const float r = wx * sqrt(abs(p.y * p.x) / (kEps + p.x * p.x + y2 * y2));
  return vec2(r * p.x, r * y2);
}
vec2 vCell(vec3 p, float w, vec4 q) {
  const float size = q.x, inv = 1.0 / size;
  float x = floor(p.x * inv), y = floor(p.y * inv);
  const float dx = p.x - x * size, dy = p.y - y * size;
  y = y >= 0.0 ? 2.0 * y : -(2.0 * y + 1.0);
  x = x >= 0.0 ? 2.0 * x : -(2.0 * x + 1.0);
  return vec2(w * (dx + x * size), -w * (dy + y * size));
}
vec2 vCurve(vec3 p, vec4 q) {
  const float xlen = max(q.z * q.z, 1e-20), ylen = max(q.w * q.w, 1e-20);
  return vec2(p.x + q.x * exp(-p.y * p.y / xlen), p.y + q.y * exp(-p.x * p.x / ylen));
}
// edisc and elliptic: xmax ≥ 1 and |x / xmax| ≤ 1 exactly; float rounding may step past them,
// which double rarely does, so the roots and acos are clamped.
vec2 vEdisc(vec3 p, float w) {
  const float tmp = sumsq(p) + 1.0, tmp2 = 2.0 * p.x;
  const float xmax = 0.5 * (sqrt(tmp + tmp2) + sqrt(max(tmp - tmp2, 0.0)));
  const float a1 = log(xmax + sqrt(max(xmax - 1.0, 0.0))), a2 = -acos(clamp(p.x / xmax, -1.0, 1.0));
  const float k = w / 11.57034632;
  const float snv = p.y > 0.0 ? -sin(a1) : sin(a1);
  return vec2(k * cosh(a2) * cos(a1), k * sinh(a2) * snv);
}
vec2 vElliptic(vec3 p, float w) {
  const float tmp = sumsq(p) + 1.0, x2 = 2.0 * p.x;
  const float xmax = 0.5 * (sqrt(tmp + x2) + sqrt(max(tmp - x2, 0.0)));
  const float a = p.x / xmax, b = sqrt(max(0.0, 1.0 - a * a)), s = sqrt(max(0.0, xmax - 1.0));
  const float ww = w / (kPi / 2.0), l = log(xmax + s);
  return vec2(ww * atan2(a, b), p.y > 0.0 ? ww * l : -ww * l);
}
vec2 vEscher(vec3 p, float w, vec4 q) {
  const float a = angleYx(p), lnr = 0.5 * log(sumsq(p));
  const float vc = 0.5 * (1.0 + cos(q.x)), vd = 0.5 * sin(q.x);
  return polarPoint(w * exp(vc * lnr - vd * a), vc * a + vd * lnr);
}
vec2 vFoci(vec3 p, float w) {
  const float ex = 0.5 * exp(p.x), enx = 0.25 / ex, t = w / (ex + enx - cos(p.y));
  return vec2(t * (ex - enx), t * sin(p.y));
}
vec2 vLazysusan(vec3 p, float w, vec4 q, vec4 q2) {
  const float lx = q.x, ly = q.y, spin = q.z, space = q.w, twist = q2.x;
  const float x = p.x - lx, y = p.y + ly;
  float r = sqrt(x * x + y * y);
  if (r < w) {
    const float a = atan2(y, x) + spin + twist * (w - r);
    r = w * r;
    return vec2(r * cos(a) + lx, r * sin(a) - ly);
  }
  r = w * (1.0 + space / r);
  return vec2(r * x + lx, r * y - ly);
}
vec2 vLoonie(vec3 p, float w) {
  const float r2 = sumsq(p), w2 = w * w;
  if (r2 < w2 && r2 > 0.0) return p.xy * (w * sqrt(w2 / r2 - 1.0));
  return w * p.xy;
}
float modulusAxis(float t, float m) {
  if (t > m) return -m + fmodC(t + m, 2.0 * m);
  if (t < -m) return m - fmodC(m - t, 2.0 * m);
  return t;
}
vec2 vOscilloscope(vec3 p, float w, vec4 q) {
  const float c = cos(2.0 * kPi * q.y * p.x);
  const float t = (q.w == 0.0 ? q.z * c : q.z * exp(-abs(p.x) * q.w) * c) + q.x;
  return vec2(w * p.x, abs(p.y) <= t ? -w * p.y : w * p.y);
}
vec2 vPolar2(vec3 p, float w) {
  const float k = w / kPi;
  return vec2(k * angle(p), k / 2.0 * log(sumsq(p)));
}
vec2 vScry(vec3 p, float w) {
  const float t = sumsq(p), r = 1.0 / (sqrt(t) * (t + 1.0 / (w + kEps)));
  return p.xy * r;
}
float separationAxis(float t, float s, float inside) {
  const float root = sqrt(t * t + s * s);
  return t > 0.0 ? root - t * inside : -(root + t * inside);
}
vec2 vSplit(vec3 p, float w, vec4 q) {
  return vec2(cos(p.y * q.y * kPi) >= 0.0 ? w * p.x : -w * p.x, cos(p.x * q.x * kPi) >= 0.0 ? w * p.y : -w * p.y);
}
vec2 vStripes(vec3 p, float w, vec4 q) {
  const float rx = floor(p.x + 0.5), ox = p.x - rx;
  return vec2(w * (ox * (1.0 - q.x) + rx), w * (p.y + ox * ox * q.y));
}
// wedge and wedge_sph: q = angle, hole, count, swirl.
vec2 wedgeWith(float r, float baseAngle, float w, vec4 q) {
  float a = baseAngle + q.w * r;
  const float c = floor((q.z * a + kPi) / kPi * 0.5), comp = 1.0 - q.x * q.z / kPi * 0.5;
  a = a * comp + c * q.x;
  return polarPoint(w * (r + q.y), a);
}
vec2 vWhorl(vec3 p, float w, vec4 q) {
  const float r = radius(p), a = angleYx(p) + (r < w ? q.x : q.y) / (w - r);
  return w * polarPoint(r, a);
}
vec2 vAuger(vec3 p, float w, vec4 q) {
  const float s = sin(q.x * p.x), t = sin(q.x * p.y);
  const float dy = p.y + q.y * (q.w * s / 2.0 + abs(p.y) * s);
  const float dx = p.x + q.y * (q.w * t / 2.0 + abs(p.x) * t);
  return vec2(w * (p.x + q.z * (dx - p.x)), w * dy);
}
vec2 vFlux(vec3 p, float w, vec4 q) {
  const float xpw = p.x + w, xmw = p.x - w, y2 = p.y * p.y;
  const float r = w * (2.0 + q.x) * sqrt(sqrt(y2 + xpw * xpw) / sqrt(y2 + xmw * xmw));
  return polarPoint(r, (atan2(p.y, xmw) - atan2(p.y, xpw)) * 0.5);
}
vec2 vMobius(vec3 p, float w, vec4 q, vec4 q2) {
  const float ru = q.x * p.x - q.y * p.y + q.z, iu = q.x * p.y + q.y * p.x + q.w;
  const float rv = q2.x * p.x - q2.y * p.y + q2.z, iv = q2.x * p.y + q2.y * p.x + q2.w;
  const float k = w / (rv * rv + iv * iv);
  return vec2(k * (ru * rv + iu * iv), k * (iu * rv - ru * iv));
}

// The complex functions (exp, log, sin, …) of z = x + iy.
vec2 cExp(float x, float y) { return exp(x) * vec2(cos(y), sin(y)); }
vec2 cLog(float x, float y) { return vec2(0.5 * log(x * x + y * y), atan2(y, x)); }
vec2 cSin(float x, float y) { return vec2(sin(x) * cosh(y), cos(x) * sinh(y)); }
vec2 cCos(float x, float y) { return vec2(cos(x) * cosh(y), -sin(x) * sinh(y)); }
vec2 cTan(float x, float y) { return vec2(sin(2.0 * x), sinh(2.0 * y)) / (cos(2.0 * x) + cosh(2.0 * y)); }
vec2 cSec(float x, float y) {
  return 2.0 / (cos(2.0 * x) + cosh(2.0 * y)) * vec2(cos(x) * cosh(y), sin(x) * sinh(y));
}
vec2 cCsc(float x, float y) {
  return 2.0 / (cosh(2.0 * y) - cos(2.0 * x)) * vec2(sin(x) * cosh(y), -cos(x) * sinh(y));
}
vec2 cCot(float x, float y) { return vec2(sin(2.0 * x), -sinh(2.0 * y)) / (cosh(2.0 * y) - cos(2.0 * x)); }
vec2 cSinh(float x, float y) { return vec2(sinh(x) * cos(y), cosh(x) * sin(y)); }
vec2 cCosh(float x, float y) { return vec2(cosh(x) * cos(y), sinh(x) * sin(y)); }
vec2 cTanh(float x, float y) { return vec2(sinh(2.0 * x), sin(2.0 * y)) / (cos(2.0 * y) + cosh(2.0 * x)); }
vec2 cSech(float x, float y) {
  return 2.0 / (cos(2.0 * y) + cosh(2.0 * x)) * vec2(cos(y) * cosh(x), -sin(y) * sinh(x));
}
vec2 cCsch(float x, float y) {
  return 2.0 / (cosh(2.0 * x) - cos(2.0 * y)) * vec2(sinh(x) * cos(y), -cosh(x) * sin(y));
}
vec2 cCoth(float x, float y) { return vec2(sinh(2.0 * x), sin(2.0 * y)) / (cosh(2.0 * x) - cos(2.0 * y)); }

// The random variations, as pure functions of five uniforms u (x y z w) and u4 in [0, 1) that the
// stage draws from the chain's stream for each random term: the distributions of flam3's (and the
// CPU's) draws, not the same numbers. Drawn before the switch, the stream's state stays out of
// its divergent branches.
float pseudoGaussian(vec4 u) { return u.x + u.y + u.z + u.w - 2.0; }  // flam3's: four uniforms, minus 2
vec2 vJulian(vec3 p, float w, vec4 q, float u) {
  const float power = q.x, cn = q.y / power / 2.0, t = trunc(abs(power) * u);
  return polarPoint(w * pow(sumsq(p), cn), (angleYx(p) + 2.0 * kPi * t) / power);
}
vec2 vJuliascope(vec3 p, float w, vec4 q, float u) {
  const float power = q.x, cn = q.y / power / 2.0;
  const int t = int(trunc(abs(power) * u));
  const float a = ((t & 1) == 0 ? 2.0 * kPi * float(t) + angleYx(p) : 2.0 * kPi * float(t) - angleYx(p)) / power;
  return polarPoint(w * pow(sumsq(p), cn), a);
}
vec2 vRadialBlur(vec3 p, float w, vec4 q, vec4 u) {
  const float angleParam = q.x * kPi / 2.0, spin = sin(angleParam), zoom = cos(angleParam);
  const float g = w * pseudoGaussian(u);
  const float a = angleYx(p) + spin * g, rz = zoom * g - 1.0;
  return polarPoint(radius(p), a) + rz * p.xy;
}
vec2 vPie(float w, vec4 q, vec4 u) {
  const int slice = int(u.x * q.x + 0.5);
  const float a = q.y + 2.0 * kPi * (float(slice) + u.y * q.z) / q.x;
  return polarPoint(w * u.z, a);
}
vec2 vTwintrian(vec3 p, float w, float u) {
  const float r = u * w * radius(p), s = sin(r), c = cos(r);
  float diff = log10f(s * s) + c;
  if (!finiteWithin(diff, 1e10)) diff = -30.0;
  return vec2(w * p.x * diff, w * p.x * (diff - s * kPi));
}
vec2 vSuperShape(vec3 p, float w, vec4 q, vec4 q2, float u) {
  const float rnd = q.x, m = q.y, n1 = q.z, n2 = q.w, n3 = q2.x, holes = q2.y;
  const float theta = m / 4.0 * angleYx(p) + kPi / 4.0;
  const float t1 = pow(abs(cos(theta)), n2), t2 = pow(abs(sin(theta)), n3);
  const float r0 = radius(p);
  const float r = w * ((rnd * u + (1.0 - rnd) * r0) - holes) * pow(t1 + t2, -1.0 / n1) / r0;
  return p.xy * r;
}
vec2 vBoarders(vec3 p, float w, float u) {
  const float rx = roundEven(p.x), ry = roundEven(p.y), ox = p.x - rx, oy = p.y - ry;
  vec2 offset;
  if (u >= 0.75)
    offset = vec2(0.0);
  else if (abs(ox) >= abs(oy))
    offset = ox >= 0.0 ? vec2(0.25, 0.25 * oy / ox) : vec2(-0.25, -0.25 * oy / ox);
  else
    offset = oy >= 0.0 ? vec2(ox / oy * 0.25, 0.25) : vec2(-ox / oy * 0.25, -0.25);
  return w * (vec2(ox * 0.5 + rx, oy * 0.5 + ry) + offset);
}
vec2 vCpow(vec3 p, float w, vec4 q, float u) {
  const float a = angleYx(p), lnr = 0.5 * log(sumsq(p));
  const float va = 2.0 * kPi / q.z, vc = q.x / q.z, vd = q.y / q.z;
  const float ang = vc * a + vd * lnr + va * floor(q.z * u);
  return polarPoint(w * exp(vc * lnr - vd * a), ang);
}
vec2 vWedgeJulia(vec3 p, float w, vec4 q, float u) {
  const float ang = q.x, count = q.y, power = q.z, cn = q.w / power / 2.0;
  const float cf = 1.0 - ang * count / kPi * 0.5;
  const float r = w * pow(sumsq(p), cn);
  const int t = int(abs(power) * u);
  float a = (angleYx(p) + 2.0 * kPi * float(t)) / power;
  const float c = floor((count * a + kPi) / kPi * 0.5);
  a = a * cf + c * ang;
  return polarPoint(r, a);
}
// pre_blur, the one pre-variation: a pseudo-Gaussian step of the point before the other variations.
vec2 preBlur(float w, vec4 u, float u4) { return polarPoint(w * pseudoGaussian(u), u4 * 2.0 * kPi); }

vec2 randomVariation(uint id, vec3 p, float w, vec4 q, vec4 q2, vec4 u, float u4) {
  vec2 v;
  switch (id) {
    case V_pre_blur: v = vec2(0.0); break;  // as in variation()
#if USE_julia
    case V_julia:  // one of the two square roots at random
      v = polarPoint(w * sqrt(radius(p)), 0.5 * angle(p) + (u.x < 0.5 ? kPi : 0.0));
      break;
#endif
#if USE_noise
    case V_noise: v = p.xy * (w * u.y) * vec2(cos(u.x * 2.0 * kPi), sin(u.x * 2.0 * kPi)); break;
#endif
#if USE_julian
    case V_julian: v = vJulian(p, w, q, u.x); break;
#endif
#if USE_juliascope
    case V_juliascope: v = vJuliascope(p, w, q, u.x); break;
#endif
#if USE_blur
    case V_blur: v = polarPoint(w * u.y, u.x * 2.0 * kPi); break;
#endif
#if USE_gaussian_blur
    case V_gaussian_blur: v = polarPoint(w * pseudoGaussian(u), u4 * 2.0 * kPi); break;
#endif
#if USE_radial_blur
    case V_radial_blur: v = vRadialBlur(p, w, q, u); break;
#endif
#if USE_pie
    case V_pie: v = vPie(w, q, u); break;
#endif
#if USE_arch
    case V_arch: {  // arch, rays, blade and twintrian use the weight inside the map, as flam3 does
      const float a = u.x * w * kPi, s = sin(a);
      v = vec2(w * s, w * s * s / cos(a));
      break;
    }
#endif
#if USE_square
    case V_square: v = w * (u.xy - 0.5); break;
#endif
#if USE_rays
    case V_rays: {
      const float t = w * tan(w * u.x * kPi) * (w / (sumsq(p) + kEps));
      v = vec2(t * cos(p.x), t * sin(p.y));
      break;
    }
#endif
#if USE_blade
    case V_blade: {
      const float r = u.x * w * radius(p), s = sin(r), c = cos(r);
      v = vec2(w * p.x * (c + s), w * p.x * (c - s));
      break;
    }
#endif
#if USE_twintrian
    case V_twintrian: v = vTwintrian(p, w, u.x); break;
#endif
#if USE_super_shape
    case V_super_shape: v = vSuperShape(p, w, q, q2, u.x); break;
#endif
#if USE_flower
    case V_flower: v = p.xy * (w * (u.x - q.y) * cos(q.x * angleYx(p)) / radius(p)); break;
#endif
#if USE_conic
    case V_conic: v = p.xy * (w * (u.x - q.y) * q.x / (1.0 + q.x * p.x / radius(p)) / radius(p)); break;
#endif
#if USE_parabola
    case V_parabola: {
      const float r = radius(p), s = sin(r);
      v = vec2(q.x * w * s * s * u.x, q.y * w * cos(r) * u.y);
      break;
    }
#endif
#if USE_boarders
    case V_boarders: v = vBoarders(p, w, u.x); break;
#endif
#if USE_cpow
    case V_cpow: v = vCpow(p, w, q, u.x); break;
#endif
#if USE_wedge_julia
    case V_wedge_julia: v = vWedgeJulia(p, w, q, u.x); break;
#endif
    default: v = vec2(0.0); break;
  }
  return v;
}

// Draves & Reckase 2003, appendix: the deterministic variations up to perspective.
vec3 classicVariation(uint id, vec3 p, float w, vec4 q, vec4 q2, vec4 c0, vec2 c1) {
  vec3 v;
  switch (id) {
    // Unguarded, so that the switch has a case whatever USE_ leaves (a switch of a default alone
    // does not compile on Mesa).
    case V_linear: v = w * p; break;
#if USE_sinusoidal
    case V_sinusoidal: v = vec3(w * sin(p.xy), 0.0); break;
#endif
#if USE_spherical
    case V_spherical: v = w / (dot(p, p) + kEps) * p; break;
#endif
#if USE_swirl
    case V_swirl: v = vec3(w * vSwirl(p), 0.0); break;
#endif
#if USE_horseshoe
    case V_horseshoe: v = vec3(vHorseshoe(p, w), 0.0); break;
#endif
#if USE_polar
    case V_polar: v = vec3(w * vec2(angle(p) / kPi, radius(p) - 1.0), 0.0); break;
#endif
#if USE_handkerchief
    case V_handkerchief: v = vec3(w * vHandkerchief(p), 0.0); break;
#endif
#if USE_heart
    case V_heart: v = vec3(vHeart(p, w), 0.0); break;
#endif
#if USE_disc
    case V_disc: v = vec3(w * vDisc(p), 0.0); break;
#endif
#if USE_spiral
    case V_spiral: v = vec3(vSpiral(p, w), 0.0); break;
#endif
#if USE_hyperbolic
    case V_hyperbolic: v = vec3(w * vHyperbolic(p), 0.0); break;
#endif
#if USE_diamond
    case V_diamond: v = vec3(w * vDiamond(p), 0.0); break;
#endif
#if USE_ex
    case V_ex: v = vec3(w * vEx(p), 0.0); break;
#endif
#if USE_bent
    case V_bent: v = vec3(w * vBent(p), 0.0); break;
#endif
#if USE_waves
    case V_waves: v = vec3(w * vWaves(p, c0, c1), 0.0); break;
#endif
#if USE_fisheye
    case V_fisheye: v = vec3(2.0 * w / (radius(p) + 1.0) * p.yx, 0.0); break;  // the appendix's reversed order
#endif
#if USE_popcorn
    case V_popcorn: v = vec3(w * vPopcorn(p, c0, c1), 0.0); break;
#endif
#if USE_exponential
    case V_exponential: v = vec3(vExponential(p, w), 0.0); break;
#endif
#if USE_power
    case V_power: v = vec3(vPower(p, w), 0.0); break;
#endif
#if USE_cosine
    case V_cosine: v = vec3(w * vCosine(p), 0.0); break;
#endif
#if USE_rings
    case V_rings: v = vec3(vRings(p, w, c0), 0.0); break;
#endif
#if USE_fan
    case V_fan: v = vec3(vFan(p, w, c0, c1), 0.0); break;
#endif
#if USE_blob
    case V_blob: v = vec3(w * vBlob(p, q), 0.0); break;
#endif
#if USE_pdj
    case V_pdj: v = vec3(w * vPdj(p, q), 0.0); break;
#endif
#if USE_fan2
    case V_fan2: v = vec3(vFan2(p, w, q), 0.0); break;
#endif
#if USE_rings2
    case V_rings2: v = vec3(w * vRings2(p, q), 0.0); break;
#endif
#if USE_eyefish
    case V_eyefish: v = 2.0 * w / (length(p) + 1.0) * p; break;
#endif
#if USE_bubble
    case V_bubble: v = w / (0.25 * dot(p, p) + 1.0) * p; break;
#endif
#if USE_cylinder
    case V_cylinder: v = vec3(w * vec2(sin(p.x), p.y), 0.0); break;
#endif
#if USE_perspective
    case V_perspective: v = vec3(vPerspective(p, w, q), 0.0); break;
#endif
    default: v = vec3(0.0); break;
  }
  return v;
}

// flam3's later deterministic variations, ngon to waves2.
vec3 laterVariation(uint id, vec3 p, float w, vec4 q, vec4 q2, vec4 c0, vec2 c1) {
  vec3 v;
  switch (id) {
    case V_pre_blur: v = vec3(0.0); break;  // moves the point before the sum (preBlur); unguarded
#if USE_ngon
    case V_ngon: v = vec3(w * vNgon(p, q), 0.0); break;
#endif
#if USE_curl
    case V_curl: v = vec3(vCurl(p, w, q), 0.0); break;
#endif
#if USE_rectangles
    case V_rectangles: v = vec3(w * vRectangles(p, q), 0.0); break;
#endif
#if USE_tangent
    case V_tangent: v = vec3(w * vec2(sin(p.x) / cos(p.y), tan(p.y)), 0.0); break;
#endif
#if USE_secant2
    case V_secant2: v = vec3(vSecant2(p, w), 0.0); break;
#endif
#if USE_cross
    case V_cross: v = vec3(vCross(p, w), 0.0); break;
#endif
#if USE_disc2
    case V_disc2: v = vec3(vDisc2(p, w, q), 0.0); break;
#endif
#if USE_bent2
    case V_bent2: v = vec3(w * vec2(p.x < 0.0 ? p.x * q.x : p.x, p.y < 0.0 ? p.y * q.y : p.y), 0.0); break;
#endif
#if USE_bipolar
    case V_bipolar: v = vec3(vBipolar(p, w, q), 0.0); break;
#endif
#if USE_butterfly
    case V_butterfly: v = vec3(vButterfly(p, w), 0.0); break;
#endif
#if USE_cell
    case V_cell: v = vec3(vCell(p, w, q), 0.0); break;
#endif
#if USE_curve
    case V_curve: v = vec3(w * vCurve(p, q), 0.0); break;
#endif
#if USE_edisc
    case V_edisc: v = vec3(vEdisc(p, w), 0.0); break;
#endif
#if USE_elliptic
    case V_elliptic: v = vec3(vElliptic(p, w), 0.0); break;
#endif
#if USE_escher
    case V_escher: v = vec3(vEscher(p, w, q), 0.0); break;
#endif
#if USE_foci
    case V_foci: v = vec3(vFoci(p, w), 0.0); break;
#endif
#if USE_lazysusan
    case V_lazysusan: v = vec3(vLazysusan(p, w, q, q2), 0.0); break;
#endif
#if USE_loonie
    case V_loonie: v = vec3(vLoonie(p, w), 0.0); break;
#endif
#if USE_modulus
    case V_modulus: v = vec3(w * vec2(modulusAxis(p.x, q.x), modulusAxis(p.y, q.y)), 0.0); break;
#endif
#if USE_oscilloscope
    case V_oscilloscope: v = vec3(vOscilloscope(p, w, q), 0.0); break;
#endif
#if USE_polar2
    case V_polar2: v = vec3(vPolar2(p, w), 0.0); break;
#endif
#if USE_popcorn2
    case V_popcorn2:
      v = vec3(w * (p.xy + q.xy * vec2(sin(tan(p.y * q.z)), sin(tan(p.x * q.z)))), 0.0);
      break;
#endif
#if USE_scry
    case V_scry: v = vec3(vScry(p, w), 0.0); break;
#endif
#if USE_separation
    case V_separation:
      v = vec3(w * vec2(separationAxis(p.x, q.x, q.y), separationAxis(p.y, q.z, q.w)), 0.0);
      break;
#endif
#if USE_split
    case V_split: v = vec3(vSplit(p, w, q), 0.0); break;
#endif
#if USE_splits
    case V_splits:
      v = vec3(w * vec2(p.x >= 0.0 ? p.x + q.x : p.x - q.x, p.y >= 0.0 ? p.y + q.y : p.y - q.y), 0.0);
      break;
#endif
#if USE_stripes
    case V_stripes: v = vec3(vStripes(p, w, q), 0.0); break;
#endif
#if USE_wedge
    case V_wedge: v = vec3(wedgeWith(radius(p), angleYx(p), w, q), 0.0); break;
#endif
#if USE_wedge_sph
    case V_wedge_sph: v = vec3(wedgeWith(1.0 / (radius(p) + kEps), angleYx(p), w, q), 0.0); break;
#endif
#if USE_whorl
    case V_whorl: v = vec3(vWhorl(p, w, q), 0.0); break;
#endif
#if USE_waves2
    case V_waves2: v = vec3(w * (p.xy + q.yw * sin(p.yx * q.xz)), 0.0); break;
#endif
    default: v = vec3(0.0); break;
  }
  return v;
}

// The complex functions, auger, flux, mobius and Apophysis 7X's 3D ones (linear3D, the z variations).
vec3 complexOr3dVariation(uint id, vec3 p, float w, vec4 q, vec4 q2, vec4 c0, vec2 c1) {
  vec3 v;
  switch (id) {
    // The z variations of Apophysis 7X's 3D extension; flatten clears z in the stage.
    case V_flatten: v = vec3(0.0); break;  // unguarded: see classicVariation
#if USE_linear3D
    case V_linear3D: v = w * p; break;
#endif
#if USE_zscale
    case V_zscale: v = vec3(0.0, 0.0, w * p.z); break;
#endif
#if USE_ztranslate
    case V_ztranslate: v = vec3(0.0, 0.0, w); break;
#endif
#if USE_zcone
    case V_zcone: v = vec3(0.0, 0.0, w * radius(p)); break;
#endif
    // The complex functions (exp, log, sin, …) of z = x + iy.
#if USE_exp
    case V_exp: v = vec3(w * cExp(p.x, p.y), 0.0); break;
#endif
#if USE_log
    case V_log: v = vec3(w * cLog(p.x, p.y), 0.0); break;
#endif
#if USE_sin
    case V_sin: v = vec3(w * cSin(p.x, p.y), 0.0); break;
#endif
#if USE_cos
    case V_cos: v = vec3(w * cCos(p.x, p.y), 0.0); break;
#endif
#if USE_tan
    case V_tan: v = vec3(w * cTan(p.x, p.y), 0.0); break;
#endif
#if USE_sec
    case V_sec: v = vec3(w * cSec(p.x, p.y), 0.0); break;
#endif
#if USE_csc
    case V_csc: v = vec3(w * cCsc(p.x, p.y), 0.0); break;
#endif
#if USE_cot
    case V_cot: v = vec3(w * cCot(p.x, p.y), 0.0); break;
#endif
#if USE_sinh
    case V_sinh: v = vec3(w * cSinh(p.x, p.y), 0.0); break;
#endif
#if USE_cosh
    case V_cosh: v = vec3(w * cCosh(p.x, p.y), 0.0); break;
#endif
#if USE_tanh
    case V_tanh: v = vec3(w * cTanh(p.x, p.y), 0.0); break;
#endif
#if USE_sech
    case V_sech: v = vec3(w * cSech(p.x, p.y), 0.0); break;
#endif
#if USE_csch
    case V_csch: v = vec3(w * cCsch(p.x, p.y), 0.0); break;
#endif
#if USE_coth
    case V_coth: v = vec3(w * cCoth(p.x, p.y), 0.0); break;
#endif
#if USE_auger
    case V_auger: v = vec3(vAuger(p, w, q), 0.0); break;
#endif
#if USE_flux
    case V_flux: v = vec3(vFlux(p, w, q), 0.0); break;
#endif
#if USE_mobius
    case V_mobius: v = vec3(vMobius(p, w, q, q2), 0.0); break;
#endif
    default: v = vec3(0.0); break;
  }
  return v;
}

// w · V(p): x and y, and z for the variations that write it (linear, the 3D forms, the z
// variations); a planar one's z is ignored (the stage carries w·z). q and q2: the term's
// parameters in table order; c0 c1: the grid map's affine coefficients. The random ones are in
// randomVariation.
vec3 variation(uint id, vec3 p, float w, vec4 q, vec4 q2, vec4 c0, vec2 c1) {
  // Three switches of at most 32 cases, not one of 84, each holding the ids of its range in table
  // order: llvmpipe (Mesa 22) runs a switch as nested masked conditions and silently skipped every
  // case past about the 75th (its condition stack is 80 deep).
  if (id < V_ngon) return classicVariation(id, p, w, q, q2, c0, c1);
  if (id < V_exp) return laterVariation(id, p, w, q, q2, c0, c1);
  return complexOr3dVariation(id, p, w, q, q2, c0, c1);
}

// One function's stage at stages[head]: post rows 0–2, coefficients a b c d, e f; then `terms`
// terms of three words each: (id, weight bits, flags, 0) and 8 parameters; flags: 1 writes z,
// 2 pre-variation, 4 flatten, 8 random. Draves & Reckase 2003, §3: f = post(Σ w_i V_i), the
// pre-variations (pre_blur, the only one) first.
const uint kWritesZ = 1u, kPre = 2u, kFlatten = 4u, kRandom = 8u;
vec3 applyVariationStage(uint head, uint terms, vec3 p, inout uvec4 rng) {
  const vec4 c0 = uintBitsToFloat(stages[head + 3u]);
  const vec2 c1 = uintBitsToFloat(stages[head + 4u].xy);
  for (uint i = 0u; i < terms; ++i) {
    const uvec4 t = stages[head + 5u + 3u * i];
    if ((t.z & kPre) != 0u) {
      const vec4 u = vec4(uniform01(rng), uniform01(rng), uniform01(rng), uniform01(rng));
      p.xy += preBlur(uintBitsToFloat(t.y), u, uniform01(rng));
    }
  }
  vec3 sum = vec3(0.0);
  bool flatten = false;
  for (uint i = 0u; i < terms; ++i) {
    const uvec4 t = stages[head + 5u + 3u * i];
    if ((t.z & kPre) == 0u) {
      vec4 u = vec4(0.0);
      float u4 = 0.0;
      if ((t.z & kRandom) != 0u) {
        u = vec4(uniform01(rng), uniform01(rng), uniform01(rng), uniform01(rng));
        u4 = uniform01(rng);
      }
      const float w = uintBitsToFloat(t.y);
      const uint at = head + 6u + 3u * i;
      const vec4 q = uintBitsToFloat(stages[at]), q2 = uintBitsToFloat(stages[at + 1u]);
      // The random switch beside the deterministic ones, not inside their default: the conditions
      // of nested switches add up (see variation()).
      const vec3 v = (t.z & kRandom) != 0u ? vec3(randomVariation(t.x, p, w, q, q2, u, u4), 0.0)
                                           : variation(t.x, p, w, q, q2, c0, c1);
      sum += vec3(v.xy, (t.z & kWritesZ) != 0u ? v.z : w * p.z);
      flatten = flatten || (t.z & kFlatten) != 0u;
    }
  }
  if (flatten) sum.z = 0.0;
  const vec4 r0 = uintBitsToFloat(stages[head]), r1 = uintBitsToFloat(stages[head + 1u]),
             r2 = uintBitsToFloat(stages[head + 2u]);
  return vec3(dot(r0.xyz, sum) + r0.w, dot(r1.xyz, sum) + r1.w, dot(r2.xyz, sum) + r2.w);
}
