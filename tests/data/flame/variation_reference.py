#!/usr/bin/env python3
"""Independent reference values for the flame variations (tests/core/test_variation_reference.cpp).

Every formula below is written from flam3 3.1's variations.c and Draves & Reckase, "The Fractal
Flame Algorithm" (appendix), not from GridIFS's C++; the 3D forms follow the documented 3D forms of
core/variations/flame_variations.h (planar variations carry w·z; linear, linear3D, spherical, bubble and
eyefish act on the whole point; zscale, ztranslate, zcone and flatten are Apophysis 7X's z
variations). Standard library only.

Conventions (flam3): the point is (tx, ty); r² = tx² + ty²; flam3's "precalc_atan" is
atan2(tx, ty) (the paper's θ, measured from the y axis), "precalc_atanyx" is atan2(ty, tx),
precalc_sina = tx / r, precalc_cosa = ty / r, EPS = 1e-10. The affine coefficients are
x' = a x + b y + c, y' = d x + e y + f, i.e. flam3's c[0][0] = a, c[1][0] = b, c[2][0] = c,
c[0][1] = d, c[1][1] = e, c[2][1] = f.

Random variations: their first four moments of x and y at one point, computed by quadrature over
the uniform draws they make (exact sums over discrete choices, the Irwin–Hall density for flam3's
pseudo-Gaussian U1 + U2 + U3 + U4 - 2, midpoint rules for continuous draws), and the branches of
the multi-valued ones (julia, julian, juliascope, wedge_julia, cpow) with their frequencies.

Run: python3 tests/data/flame/variation_reference.py  (writes variation_reference.json beside it)
"""
import json
import math
import os

EPS = 1e-10
PI = math.pi


# ---------------------------------------------------------------------------------------------
# Deterministic variations: flam3's 2D formulas, f(x, y, w, params, coefs) -> (x, y)
# ---------------------------------------------------------------------------------------------

def atan_xy(x, y):  # flam3 precalc_atan
    return math.atan2(x, y)


def atan_yx(x, y):  # flam3 precalc_atanyx
    return math.atan2(y, x)


def v_linear(x, y, w, p, c):
    return w * x, w * y


def v_sinusoidal(x, y, w, p, c):
    return w * math.sin(x), w * math.sin(y)


def v_spherical(x, y, w, p, c):
    k = w / (x * x + y * y + EPS)
    return k * x, k * y


def v_swirl(x, y, w, p, c):
    r2 = x * x + y * y
    s, co = math.sin(r2), math.cos(r2)
    return w * (s * x - co * y), w * (co * x + s * y)


def v_horseshoe(x, y, w, p, c):
    k = w / (math.hypot(x, y) + EPS)
    return k * (x - y) * (x + y), k * 2.0 * x * y


def v_polar(x, y, w, p, c):
    return w * atan_xy(x, y) / PI, w * (math.hypot(x, y) - 1.0)


def v_handkerchief(x, y, w, p, c):
    a, r = atan_xy(x, y), math.hypot(x, y)
    return w * r * math.sin(a + r), w * r * math.cos(a - r)


def v_heart(x, y, w, p, c):
    r = math.hypot(x, y)
    a = r * atan_xy(x, y)
    return w * r * math.sin(a), -w * r * math.cos(a)


def v_disc(x, y, w, p, c):
    a = atan_xy(x, y) / PI
    r = PI * math.hypot(x, y)
    return w * a * math.sin(r), w * a * math.cos(r)


def v_spiral(x, y, w, p, c):
    r0 = math.hypot(x, y)
    sina, cosa = x / r0, y / r0
    r = r0 + EPS
    return w / r * (cosa + math.sin(r)), w / r * (sina - math.cos(r))


def v_hyperbolic(x, y, w, p, c):
    r0 = math.hypot(x, y)
    sina, cosa = x / r0, y / r0
    r = r0 + EPS
    return w * sina / r, w * cosa * r


def v_diamond(x, y, w, p, c):
    r = math.hypot(x, y)
    return w * (x / r) * math.cos(r), w * (y / r) * math.sin(r)


def v_ex(x, y, w, p, c):
    a, r = atan_xy(x, y), math.hypot(x, y)
    n0, n1 = math.sin(a + r), math.cos(a - r)
    m0, m1 = n0 ** 3 * r, n1 ** 3 * r
    return w * (m0 + m1), w * (m0 - m1)


def v_bent(x, y, w, p, c):
    nx = 2.0 * x if x < 0 else x
    ny = y / 2.0 if y < 0 else y
    return w * nx, w * ny


def v_waves(x, y, w, p, co):
    a, b, c, d, e, f = co
    return w * (x + b * math.sin(y / (c * c + EPS))), w * (y + e * math.sin(x / (f * f + EPS)))


def v_fisheye(x, y, w, p, c):
    # flam3 swaps the axes here (p0 gets ty, p1 gets tx): Draves & Reckase's "(y, x)" form.
    k = 2.0 * w / (math.hypot(x, y) + 1.0)
    return k * y, k * x


def v_popcorn(x, y, w, p, co):
    a, b, c, d, e, f = co
    return w * (x + c * math.sin(math.tan(3.0 * y))), w * (y + f * math.sin(math.tan(3.0 * x)))


def v_exponential(x, y, w, p, c):
    m = w * math.exp(x - 1.0)
    return m * math.cos(PI * y), m * math.sin(PI * y)


def v_power(x, y, w, p, c):
    r0 = math.hypot(x, y)
    sina, cosa = x / r0, y / r0
    r = w * r0 ** sina
    return r * cosa, r * sina


def v_cosine(x, y, w, p, c):
    return w * math.cos(PI * x) * math.cosh(y), -w * math.sin(PI * x) * math.sinh(y)


def v_rings(x, y, w, p, co):
    c = co[2]
    dx = c * c + EPS
    r0 = math.hypot(x, y)
    r = w * (math.fmod(r0 + dx, 2.0 * dx) - dx + r0 * (1.0 - dx))
    return r * (y / r0), r * (x / r0)


def v_fan(x, y, w, p, co):
    c, f = co[2], co[5]
    dx = PI * (c * c + EPS)
    half = dx / 2.0
    a = atan_xy(x, y)
    a += -half if math.fmod(a + f, dx) > half else half
    r = w * math.hypot(x, y)
    return r * math.cos(a), r * math.sin(a)


def v_blob(x, y, w, p, c):
    low, high, waves = p
    r0 = math.hypot(x, y)
    a = atan_xy(x, y)
    r = r0 * (low + (high - low) * (0.5 + 0.5 * math.sin(waves * a)))
    return w * (x / r0) * r, w * (y / r0) * r


def v_pdj(x, y, w, p, c):
    pa, pb, pc, pd = p
    return w * (math.sin(pa * y) - math.cos(pb * x)), w * (math.sin(pc * x) - math.cos(pd * y))


def v_fan2(x, y, w, p, c):
    fx, fy = p
    dx = PI * (fx * fx + EPS)
    half = dx / 2.0
    a = atan_xy(x, y)
    t = a + fy - dx * math.trunc((a + fy) / dx)
    a = a - half if t > half else a + half
    r = w * math.hypot(x, y)
    return r * math.sin(a), r * math.cos(a)


def v_rings2(x, y, w, p, c):
    val = p[0]
    r0 = math.hypot(x, y)
    dx = val * val + EPS
    r = r0 - 2.0 * dx * math.trunc((r0 + dx) / (2.0 * dx)) + r0 * (1.0 - dx)
    return w * (x / r0) * r, w * (y / r0) * r


def v_eyefish(x, y, w, p, c):
    k = 2.0 * w / (math.hypot(x, y) + 1.0)
    return k * x, k * y


def v_bubble(x, y, w, p, c):
    k = w / (0.25 * (x * x + y * y) + 1.0)
    return k * x, k * y


def v_cylinder(x, y, w, p, c):
    return w * math.sin(x), w * y


def v_perspective(x, y, w, p, c):
    angle, dist = p
    ang = angle * PI / 2.0
    t = 1.0 / (dist - y * math.sin(ang))
    return w * dist * x * t, w * dist * math.cos(ang) * y * t


def v_ngon(x, y, w, p, c):
    sides, power, circle, corners = p
    rf = (x * x + y * y) ** (power / 2.0)
    theta = atan_yx(x, y)
    b = 2.0 * PI / sides
    phi = theta - b * math.floor(theta / b)
    if phi > b / 2.0:
        phi -= b
    amp = (corners * (1.0 / (math.cos(phi) + EPS) - 1.0) + circle) / (rf + EPS)
    return w * x * amp, w * y * amp


def v_curl(x, y, w, p, c):
    c1, c2 = p
    re = 1.0 + c1 * x + c2 * (x * x - y * y)
    im = c1 * y + 2.0 * c2 * x * y
    k = w / (re * re + im * im)
    return k * (x * re + y * im), k * (y * re - x * im)


def v_rectangles(x, y, w, p, c):
    rx, ry = p
    nx = x if rx == 0 else (2.0 * math.floor(x / rx) + 1.0) * rx - x
    ny = y if ry == 0 else (2.0 * math.floor(y / ry) + 1.0) * ry - y
    return w * nx, w * ny


def v_tangent(x, y, w, p, c):
    return w * math.sin(x) / math.cos(y), w * math.tan(y)


def v_secant2(x, y, w, p, c):
    cr = math.cos(w * math.hypot(x, y))
    return w * x, w * (1.0 / cr + 1.0) if cr < 0 else w * (1.0 / cr - 1.0)


def v_cross(x, y, w, p, c):
    s = x * x - y * y
    k = w * math.sqrt(1.0 / (s * s + EPS))
    return k * x, k * y


def v_disc2(x, y, w, p, c):
    rot, twist = p
    sinadd, cosadd = math.sin(twist), math.cos(twist) - 1.0
    if twist > 2.0 * PI:
        k = 1.0 + twist - 2.0 * PI
        sinadd, cosadd = sinadd * k, cosadd * k
    if twist < -2.0 * PI:
        k = 1.0 + twist + 2.0 * PI
        sinadd, cosadd = sinadd * k, cosadd * k
    t = rot * PI * (x + y)
    r = w * atan_xy(x, y) / PI
    return (math.sin(t) + cosadd) * r, (math.cos(t) + sinadd) * r


def v_bent2(x, y, w, p, c):
    bx, by = p
    nx = x * bx if x < 0 else x
    ny = y * by if y < 0 else y
    return w * nx, w * ny


def v_bipolar(x, y, w, p, c):
    shift = p[0]
    r2 = x * x + y * y
    t = r2 + 1.0
    v = 0.5 * math.atan2(2.0 * y, r2 - 1.0) - PI / 2.0 * shift
    if v > PI / 2.0:
        v = -PI / 2.0 + math.fmod(v + PI / 2.0, PI)
    elif v < -PI / 2.0:
        v = PI / 2.0 - math.fmod(PI / 2.0 - v, PI)
    return w * 0.25 * (2.0 / PI) * math.log((t + 2.0 * x) / (t - 2.0 * x)), w * (2.0 / PI) * v


def v_butterfly(x, y, w, p, c):
    wx = w * 4.0 / math.sqrt(3.0 * PI)
    y2 = 2.0 * y
    r = wx * math.sqrt(abs(x * y) / (EPS + x * x + y2 * y2))
    return r * x, r * y2


def v_cell(x, y, w, p, c):
    size = p[0]
    ix, iy = math.floor(x / size), math.floor(y / size)
    dx, dy = x - ix * size, y - iy * size
    ix = 2 * ix if ix >= 0 else -(2 * ix + 1)
    iy = 2 * iy if iy >= 0 else -(2 * iy + 1)
    return w * (dx + ix * size), -w * (dy + iy * size)


def v_curve(x, y, w, p, c):
    xamp, yamp, xlen, ylen = p
    xl, yl = max(xlen * xlen, 1e-20), max(ylen * ylen, 1e-20)
    return w * (x + xamp * math.exp(-y * y / xl)), w * (y + yamp * math.exp(-x * x / yl))


def v_edisc(x, y, w, p, c):
    tmp = x * x + y * y + 1.0
    r1, r2 = math.sqrt(tmp + 2.0 * x), math.sqrt(tmp - 2.0 * x)
    xmax = (r1 + r2) / 2.0
    a1 = math.log(xmax + math.sqrt(xmax - 1.0))
    a2 = -math.acos(x / xmax)
    ww = w / 11.57034632
    snv, csv = math.sin(a1), math.cos(a1)
    if y > 0:
        snv = -snv
    return ww * math.cosh(a2) * csv, ww * math.sinh(a2) * snv


def v_elliptic(x, y, w, p, c):
    tmp = x * x + y * y + 1.0
    xmax = 0.5 * (math.sqrt(tmp + 2.0 * x) + math.sqrt(tmp - 2.0 * x))
    a = x / xmax
    b = math.sqrt(max(1.0 - a * a, 0.0))
    ssx = math.sqrt(max(xmax - 1.0, 0.0))
    ww = w / (PI / 2.0)
    ny = ww * math.log(xmax + ssx)
    return ww * math.atan2(a, b), ny if y > 0 else -ny


def v_escher(x, y, w, p, c):
    beta = p[0]
    a = atan_yx(x, y)
    lnr = 0.5 * math.log(x * x + y * y)
    vc, vd = 0.5 * (1.0 + math.cos(beta)), 0.5 * math.sin(beta)
    m = w * math.exp(vc * lnr - vd * a)
    n = vc * a + vd * lnr
    return m * math.cos(n), m * math.sin(n)


def v_foci(x, y, w, p, c):
    ex = 0.5 * math.exp(x)
    enx = 0.25 / ex
    k = w / (ex + enx - math.cos(y))
    return k * (ex - enx), k * math.sin(y)


def v_lazysusan(x, y, w, p, c):
    lx, ly, spin, space, twist = p
    xx, yy = x - lx, y + ly
    r = math.hypot(xx, yy)
    if r < w:
        a = math.atan2(yy, xx) + spin + twist * (w - r)
        return w * r * math.cos(a) + lx, w * r * math.sin(a) - ly
    k = w * (1.0 + space / r)
    return k * xx + lx, k * yy - ly


def v_loonie(x, y, w, p, c):
    r2, w2 = x * x + y * y, w * w
    if r2 < w2:
        k = w * math.sqrt(w2 / r2 - 1.0)
        return k * x, k * y
    return w * x, w * y


def v_modulus(x, y, w, p, c):
    mx, my = p

    def one(v, m):
        if v > m:
            return -m + math.fmod(v + m, 2.0 * m)
        if v < -m:
            return m - math.fmod(m - v, 2.0 * m)
        return v

    return w * one(x, mx), w * one(y, my)


def v_oscilloscope(x, y, w, p, c):
    sep, freq, amp, damp = p
    tpf = 2.0 * PI * freq
    if damp == 0.0:
        t = amp * math.cos(tpf * x) + sep
    else:
        t = amp * math.exp(-abs(x) * damp) * math.cos(tpf * x) + sep
    return w * x, -w * y if abs(y) <= t else w * y


def v_polar2(x, y, w, p, c):
    k = w / PI
    return k * atan_xy(x, y), k / 2.0 * math.log(x * x + y * y)


def v_popcorn2(x, y, w, p, c):
    px, py, pc = p
    return w * (x + px * math.sin(math.tan(y * pc))), w * (y + py * math.sin(math.tan(x * pc)))


def v_scry(x, y, w, p, c):
    t = x * x + y * y
    k = 1.0 / (math.sqrt(t) * (t + 1.0 / (w + EPS)))
    return k * x, k * y


def v_separation(x, y, w, p, c):
    sx, sxi, sy, syi = p
    nx = math.sqrt(x * x + sx * sx) - x * sxi if x > 0 else -(math.sqrt(x * x + sx * sx) + x * sxi)
    ny = math.sqrt(y * y + sy * sy) - y * syi if y > 0 else -(math.sqrt(y * y + sy * sy) + y * syi)
    return w * nx, w * ny


def v_split(x, y, w, p, c):
    xs, ys = p
    ny = w * y if math.cos(x * xs * PI) >= 0 else -w * y
    nx = w * x if math.cos(y * ys * PI) >= 0 else -w * x
    return nx, ny


def v_splits(x, y, w, p, c):
    sx, sy = p
    return w * (x + sx if x >= 0 else x - sx), w * (y + sy if y >= 0 else y - sy)


def v_stripes(x, y, w, p, c):
    space, warp = p
    rx = math.floor(x + 0.5)
    ox = x - rx
    return w * (ox * (1.0 - space) + rx), w * (y + ox * ox * warp)


def wedge_common(a, r, angle, hole, count, w):
    c = math.floor((count * a + PI) / PI / 2.0)
    a = a * (1.0 - angle * count / PI / 2.0) + c * angle
    r = w * (r + hole)
    return r * math.cos(a), r * math.sin(a)


def v_wedge(x, y, w, p, c):
    angle, hole, count, swirl = p
    r = math.hypot(x, y)
    return wedge_common(atan_yx(x, y) + swirl * r, r, angle, hole, count, w)


def v_wedge_sph(x, y, w, p, c):
    angle, hole, count, swirl = p
    r = 1.0 / (math.hypot(x, y) + EPS)
    return wedge_common(atan_yx(x, y) + swirl * r, r, angle, hole, count, w)


def v_whorl(x, y, w, p, c):
    inside, outside = p
    r = math.hypot(x, y)
    a = atan_yx(x, y) + (inside if r < w else outside) / (w - r)
    return w * r * math.cos(a), w * r * math.sin(a)


def v_waves2(x, y, w, p, c):
    fx, sx, fy, sy = p
    return w * (x + sx * math.sin(y * fx)), w * (y + sy * math.sin(x * fy))


# The complex functions (cothe): each is w·F(x + iy) with F the named function.
def v_exp(x, y, w, p, c):
    return w * math.exp(x) * math.cos(y), w * math.exp(x) * math.sin(y)


def v_log(x, y, w, p, c):
    return w * 0.5 * math.log(x * x + y * y), w * atan_yx(x, y)


def v_sin(x, y, w, p, c):
    return w * math.sin(x) * math.cosh(y), w * math.cos(x) * math.sinh(y)


def v_cos(x, y, w, p, c):
    return w * math.cos(x) * math.cosh(y), -w * math.sin(x) * math.sinh(y)


def v_tan(x, y, w, p, c):
    den = 1.0 / (math.cos(2 * x) + math.cosh(2 * y))
    return w * den * math.sin(2 * x), w * den * math.sinh(2 * y)


def v_sec(x, y, w, p, c):
    den = 2.0 / (math.cos(2 * x) + math.cosh(2 * y))
    return w * den * math.cos(x) * math.cosh(y), w * den * math.sin(x) * math.sinh(y)


def v_csc(x, y, w, p, c):
    den = 2.0 / (math.cosh(2 * y) - math.cos(2 * x))
    return w * den * math.sin(x) * math.cosh(y), -w * den * math.cos(x) * math.sinh(y)


def v_cot(x, y, w, p, c):
    den = 1.0 / (math.cosh(2 * y) - math.cos(2 * x))
    return w * den * math.sin(2 * x), -w * den * math.sinh(2 * y)


def v_sinh(x, y, w, p, c):
    return w * math.sinh(x) * math.cos(y), w * math.cosh(x) * math.sin(y)


def v_cosh(x, y, w, p, c):
    return w * math.cosh(x) * math.cos(y), w * math.sinh(x) * math.sin(y)


def v_tanh(x, y, w, p, c):
    den = 1.0 / (math.cos(2 * y) + math.cosh(2 * x))
    return w * den * math.sinh(2 * x), w * den * math.sin(2 * y)


def v_sech(x, y, w, p, c):
    den = 2.0 / (math.cos(2 * y) + math.cosh(2 * x))
    return w * den * math.cos(y) * math.cosh(x), -w * den * math.sin(y) * math.sinh(x)


def v_csch(x, y, w, p, c):
    den = 2.0 / (math.cosh(2 * x) - math.cos(2 * y))
    return w * den * math.sinh(x) * math.cos(y), -w * den * math.cosh(x) * math.sin(y)


def v_coth(x, y, w, p, c):
    den = 1.0 / (math.cosh(2 * x) - math.cos(2 * y))
    return w * den * math.sinh(2 * x), w * den * math.sin(2 * y)


def v_auger(x, y, w, p, c):
    freq, aw, sym, scale = p
    s, t = math.sin(freq * x), math.sin(freq * y)
    dy = y + aw * (scale * s / 2.0 + abs(y) * s)
    dx = x + aw * (scale * t / 2.0 + abs(x) * t)
    return w * (x + sym * (dx - x)), w * dy


def v_flux(x, y, w, p, c):
    spread = p[0]
    xpw, xmw = x + w, x - w
    avgr = w * (2.0 + spread) * math.sqrt(math.hypot(y, xpw) / math.hypot(y, xmw))
    avga = (math.atan2(y, xmw) - math.atan2(y, xpw)) * 0.5
    return avgr * math.cos(avga), avgr * math.sin(avga)


def v_mobius(x, y, w, p, c):
    ra, ia, rb, ib, rc, ic, rd, idd = p
    # (a z + b) / (c z + d) in complex arithmetic, z = x + iy.
    z = complex(x, y)
    q = (complex(ra, ia) * z + complex(rb, ib)) / (complex(rc, ic) * z + complex(rd, idd))
    return w * q.real, w * q.imag


# ---------------------------------------------------------------------------------------------
# 3D forms (core/variations/flame_variations.h): f3(x, y, z, w, params, coefs) -> (x, y, z)
# ---------------------------------------------------------------------------------------------

def f3_linear(x, y, z, w, p, c):
    return w * x, w * y, w * z


def f3_spherical(x, y, z, w, p, c):
    k = w / (x * x + y * y + z * z + EPS)
    return k * x, k * y, k * z


def f3_bubble(x, y, z, w, p, c):
    k = w / (0.25 * (x * x + y * y + z * z) + 1.0)
    return k * x, k * y, k * z


def f3_eyefish(x, y, z, w, p, c):
    k = 2.0 * w / (math.sqrt(x * x + y * y + z * z) + 1.0)
    return k * x, k * y, k * z


def f3_zscale(x, y, z, w, p, c):
    return 0.0, 0.0, w * z


def f3_ztranslate(x, y, z, w, p, c):
    return 0.0, 0.0, w


def f3_zcone(x, y, z, w, p, c):
    return 0.0, 0.0, w * math.hypot(x, y)


def f3_flatten(x, y, z, w, p, c):
    return 0.0, 0.0, 0.0


def zero2d(x, y, w, p, c):
    return 0.0, 0.0


# name -> (2D flam3 formula (None: no flam3 counterpart), 3D form (None: planar, carries w·z),
#          parameter sets in table order (case i uses set i mod len), dependent)
DETERMINISTIC = {
    "linear": (v_linear, f3_linear, [[]], False),
    "sinusoidal": (v_sinusoidal, None, [[]], False),
    "spherical": (v_spherical, f3_spherical, [[]], False),
    "swirl": (v_swirl, None, [[]], False),
    "horseshoe": (v_horseshoe, None, [[]], False),
    "polar": (v_polar, None, [[]], False),
    "handkerchief": (v_handkerchief, None, [[]], False),
    "heart": (v_heart, None, [[]], False),
    "disc": (v_disc, None, [[]], False),
    "spiral": (v_spiral, None, [[]], False),
    "hyperbolic": (v_hyperbolic, None, [[]], False),
    "diamond": (v_diamond, None, [[]], False),
    "ex": (v_ex, None, [[]], False),
    "bent": (v_bent, None, [[]], False),
    "waves": (v_waves, None, [[]], True),
    "fisheye": (v_fisheye, None, [[]], False),
    "popcorn": (v_popcorn, None, [[]], True),
    "exponential": (v_exponential, None, [[]], False),
    "power": (v_power, None, [[]], False),
    "cosine": (v_cosine, None, [[]], False),
    "rings": (v_rings, None, [[]], True),
    "fan": (v_fan, None, [[]], True),
    "blob": (v_blob, None, [[0.2, 1.1, 3.0], [0.4, 0.9, 5.0]], False),
    "pdj": (v_pdj, None, [[1.1, -0.7, 2.3, 0.9]], False),
    "fan2": (v_fan2, None, [[0.6, 0.35], [0.9, -0.2]], False),
    "rings2": (v_rings2, None, [[0.45], [0.8]], False),
    "eyefish": (v_eyefish, f3_eyefish, [[]], False),
    "bubble": (v_bubble, f3_bubble, [[]], False),
    "cylinder": (v_cylinder, None, [[]], False),
    "perspective": (v_perspective, None, [[0.4, 2.2], [0.7, 3.0]], False),
    "ngon": (v_ngon, None, [[5.0, 2.5, 0.8, 1.3], [3.0, 1.0, 1.2, 0.5]], False),
    "curl": (v_curl, None, [[0.4, 0.15], [-0.3, 0.25]], False),
    "rectangles": (v_rectangles, None, [[0.35, 0.6], [0.0, 0.45]], False),
    "tangent": (v_tangent, None, [[]], False),
    "secant2": (v_secant2, None, [[]], False),
    "cross": (v_cross, None, [[]], False),
    "disc2": (v_disc2, None, [[0.7, 0.9], [1.3, 7.1], [-0.4, -6.9]], False),
    "bent2": (v_bent2, None, [[1.7, -0.4]], False),
    "bipolar": (v_bipolar, None, [[0.3], [1.8], [-1.6]], False),
    "butterfly": (v_butterfly, None, [[]], False),
    "cell": (v_cell, None, [[0.45], [0.3]], False),
    "curve": (v_curve, None, [[0.5, -0.3, 0.8, 1.4]], False),
    "edisc": (v_edisc, None, [[]], False),
    "elliptic": (v_elliptic, None, [[]], False),
    "escher": (v_escher, None, [[0.6], [-1.1]], False),
    "foci": (v_foci, None, [[]], False),
    "lazysusan": (v_lazysusan, None, [[0.2, -0.1, 0.5, 0.3, 1.2]], False),
    "loonie": (v_loonie, None, [[]], False),
    "modulus": (v_modulus, None, [[0.6, 0.4], [0.25, 0.7]], False),
    "oscilloscope": (v_oscilloscope, None, [[0.4, 1.3, 0.7, 0.0], [0.6, 0.8, 0.9, 0.5]], False),
    "polar2": (v_polar2, None, [[]], False),
    "popcorn2": (v_popcorn2, None, [[0.3, 0.2, 1.1]], False),
    "scry": (v_scry, None, [[]], False),
    "separation": (v_separation, None, [[0.3, 0.2, 0.5, -0.1]], False),
    "split": (v_split, None, [[0.7, 1.2], [1.9, 0.4]], False),
    "splits": (v_splits, None, [[0.25, -0.15]], False),
    "stripes": (v_stripes, None, [[0.3, 0.8]], False),
    "wedge": (v_wedge, None, [[0.5, 0.1, 3.0, 0.4], [0.3, -0.2, 2.0, 0.0]], False),
    "wedge_sph": (v_wedge_sph, None, [[0.4, 0.2, 2.0, 0.3], [0.6, 0.0, 4.0, -0.2]], False),
    "whorl": (v_whorl, None, [[0.3, 0.6]], False),
    "waves2": (v_waves2, None, [[2.0, 0.3, 1.5, 0.4]], False),
    "exp": (v_exp, None, [[]], False),
    "log": (v_log, None, [[]], False),
    "sin": (v_sin, None, [[]], False),
    "cos": (v_cos, None, [[]], False),
    "tan": (v_tan, None, [[]], False),
    "sec": (v_sec, None, [[]], False),
    "csc": (v_csc, None, [[]], False),
    "cot": (v_cot, None, [[]], False),
    "sinh": (v_sinh, None, [[]], False),
    "cosh": (v_cosh, None, [[]], False),
    "tanh": (v_tanh, None, [[]], False),
    "sech": (v_sech, None, [[]], False),
    "csch": (v_csch, None, [[]], False),
    "coth": (v_coth, None, [[]], False),
    "auger": (v_auger, None, [[2.0, 0.6, 0.4, 1.3], [1.0, 0.5, 0.0, 1.0]], False),
    "flux": (v_flux, None, [[0.35], [0.0]], False),
    "mobius": (v_mobius, None, [[1.1, 0.2, -0.3, 0.4, 0.25, -0.15, 0.9, 0.1]], False),
    "linear3D": (v_linear, f3_linear, [[]], False),
    "zscale": (zero2d, f3_zscale, [[]], False),
    "ztranslate": (zero2d, f3_ztranslate, [[]], False),
    "zcone": (zero2d, f3_zcone, [[]], False),
    "flatten": (zero2d, f3_flatten, [[]], False),
}

# Six input points per variation: three on the z = 0 plane, three off it, away from the
# singular points (origin, branch cuts of atan2 on the axes, floor/fmod steps).
POINTS = [
    (0.31, 0.72, 0.0),
    (-0.47, 0.23, 0.0),
    (0.58, -0.91, 0.0),
    (0.63, -0.38, 0.52),
    (-0.27, -0.81, -0.35),
    (1.13, 0.57, 0.87),
]
WEIGHTS = [0.8, 1.0, 1.25, 0.7, -0.6, 0.45]
# a, b, c, d, e, f of x' = a x + b y + c, y' = d x + e y + f (the dependent variations read them).
COEFS = [0.9, -0.3, 0.7, 0.25, 1.1, -0.4]
# Extra (x, y, z, weight) cases where the common points leave one of a variation's branches untried.
EXTRA_CASES = {
    "fan": [(0.8, 0.06, 0.3, 0.9), (0.55, 0.05, 0.0, 1.1)],  # fmod(a + f, dx) > dx / 2
    "secant2": [(1.3, 1.1, 0.0, 1.25), (-1.4, 0.9, -0.5, 1.2)],  # cos(w r) < 0
    "split": [(0.9, 0.6, 0.2, 0.8)],  # both cosines negative
}


def deterministic_cases(name):
    f2, f3, param_sets, dependent = DETERMINISTIC[name]
    cases = []
    points = [(x, y, z, w) for (x, y, z), w in zip(POINTS, WEIGHTS)] + EXTRA_CASES.get(name, [])
    for i, (x, y, z, w) in enumerate(points):
        params = param_sets[i % len(param_sets)]
        if f3 is None:
            nx, ny = f2(x, y, w, params, COEFS)
            out = [nx, ny, w * z]  # planar: carries w·z
        else:
            out = list(f3(x, y, z, w, params, COEFS))
        case = {"p": [x, y, z], "weight": w, "params": params, "expected": out}
        if dependent:
            case["coefs"] = COEFS
        if z == 0.0:
            # flam3's own 2D formula on the z = 0 plane (the 3D form must reduce to it).
            fx, fy = f2(x, y, w, params, COEFS)
            assert abs(fx - out[0]) <= 1e-9 * (1 + abs(fx)) and abs(fy - out[1]) <= 1e-9 * (1 + abs(fy)), name
            case["flam3_xy"] = [fx, fy]
        for v in out:
            assert math.isfinite(v) and abs(v) < 1e6, (name, i, out)
        cases.append(case)
    return cases


# ---------------------------------------------------------------------------------------------
# Random variations: exact moments by quadrature over the draws
# ---------------------------------------------------------------------------------------------

def uniform_nodes(n):
    """Midpoint rule for U(0, 1): n nodes, equal weights."""
    return [((k + 0.5) / n, 1.0 / n) for k in range(n)]


def irwin_hall4_nodes(n):
    """The law of S = U1 + U2 + U3 + U4 on [0, 4] (Irwin–Hall, n = 4): midpoint nodes and
    probabilities, renormalised."""
    def density(s):
        if s < 1:
            return s ** 3 / 6.0
        if s < 2:
            return (-3 * s ** 3 + 12 * s ** 2 - 12 * s + 4) / 6.0
        if s < 3:
            return (3 * s ** 3 - 24 * s ** 2 + 60 * s - 44) / 6.0
        return (4 - s) ** 3 / 6.0

    h = 4.0 / n
    nodes = [((k + 0.5) * h, density((k + 0.5) * h) * h) for k in range(n)]
    total = sum(p for _, p in nodes)
    return [(s, p / total) for s, p in nodes]


def discrete_nodes(n):
    """trunc(n·U) for a positive integer n: each of 0..n-1 with probability 1/n."""
    return [(k, 1.0 / n) for k in range(n)]


def trunc_nodes(rn):
    """trunc(rn·U) (equally floor, rn > 0 not necessarily whole): k with probability
    P(k ≤ rn U < k + 1) = min(1, (k + 1) / rn) − k / rn."""
    return [(k, min(1.0, (k + 1) / rn) - k / rn) for k in range(int(math.ceil(rn)))]


def moments(f, factors):
    """E[x^k], E[y^k] for k = 1..4 of (x, y) = f(*draws), draws independent with the given
    (value, probability) lists; returns mean, variance and fourth central moment of x and y."""
    acc = [[0.0] * 5, [0.0] * 5]
    total = 0.0

    def rec(i, args, prob):
        nonlocal total
        if i == len(factors):
            out = f(*args)
            total += prob
            for axis in range(2):
                v = out[axis]
                vk = 1.0
                for k in range(1, 5):
                    vk *= v
                    acc[axis][k] += prob * vk
            return
        for value, p in factors[i]:
            rec(i + 1, args + [value], prob * p)

    rec(0, [], 1.0)
    result = {"mean": [], "var": [], "m4": []}
    for axis in range(2):
        m1, m2, m3, m4 = (acc[axis][k] / total for k in range(1, 5))
        var = m2 - m1 * m1
        c4 = m4 - 4 * m3 * m1 + 6 * m2 * m1 * m1 - 3 * m1 ** 4
        result["mean"].append(m1)
        result["var"].append(max(var, 0.0))
        result["m4"].append(max(c4, 0.0))
    return result


def branches_of(values):
    return [[x, y] for x, y in values]


def random_cases():
    out = []
    U = uniform_nodes

    def add(name, point, w, params, f, factors, branches=None, analytic=None):
        m = moments(f, factors)
        if analytic:
            for key, axis, value in analytic:
                got = m[key][axis]
                assert abs(got - value) <= 1e-6 * (1 + abs(value)), (name, key, axis, got, value)
        case = {"name": name, "p": list(point), "weight": w, "params": params, **m}
        if branches:
            case["branches"] = branches_of([b for b, _ in branches])
            case["branch_freq"] = [q for _, q in branches]
        out.append(case)

    x, y = 0.43, -0.61
    r2, r = x * x + y * y, math.hypot(x, y)

    # julia (Draves & Reckase): a = θ/2 with θ = atan2(x, y), plus π with probability 1/2.
    w = 0.9
    a = 0.5 * atan_xy(x, y)
    roots = [(w * math.sqrt(r) * math.cos(a + k * PI), w * math.sqrt(r) * math.sin(a + k * PI)) for k in (0, 1)]
    add("julia", (x, y, 0.3), w, [], lambda b: roots[b], [discrete_nodes(2)], [(q, 0.5) for q in roots])
    assert abs(roots[0][0] ** 2 - roots[0][1] ** 2 - w * w * y) < 1e-12  # flam3's θ = atan2(x, y): roots of w²(y + ix)

    # noise: x·(w U2) cos(2π U1), y·(w U2) sin(2π U1): E = 0, E[x²] = x² w² / 6.
    w = 0.7
    add("noise", (x, y, 0.0), w, [],
        lambda u1, u2: (x * w * u2 * math.cos(2 * PI * u1), y * w * u2 * math.sin(2 * PI * u1)),
        [U(1000), U(1000)],
        analytic=[("mean", 0, 0.0), ("var", 0, x * x * w * w / 6), ("var", 1, y * y * w * w / 6)])

    # julian: branch t = trunc(|power| U), angle (atan2(y, x) + 2π t) / power, radius w r2^(dist/power/2).
    def julian_branches(power, dist, w):
        rr = w * r2 ** (dist / power / 2.0)
        return [((rr * math.cos((atan_yx(x, y) + 2 * PI * t) / power),
                  rr * math.sin((atan_yx(x, y) + 2 * PI * t) / power)), q) for t, q in trunc_nodes(abs(power))]

    for w, power, dist in ((0.8, 3.0, 1.5), (0.6, -2.0, 1.0), (0.9, 2.5, 0.7)):
        bj = julian_branches(power, dist, w)
        add("julian", (x, y, -0.4), w, [power, dist], lambda t, bj=bj: bj[t][0], [trunc_nodes(abs(power))], bj)

    # juliascope: as julian, the odd branches mirror the angle: (2π t − atan2(y, x)) / power.
    for w, power, dist in ((0.75, 4.0, 0.8), (0.85, -3.0, 1.3)):
        rr = w * r2 ** (dist / power / 2.0)
        bs = []
        for t, q in trunc_nodes(abs(power)):
            ang = (2 * PI * t + atan_yx(x, y)) / power if t % 2 == 0 else (2 * PI * t - atan_yx(x, y)) / power
            bs.append(((rr * math.cos(ang), rr * math.sin(ang)), q))
        add("juliascope", (x, y, 0.0), w, [power, dist], lambda t, bs=bs: bs[t][0], [trunc_nodes(abs(power))], bs)

    # blur: radius w U2, angle 2π U1: E = 0, E[x²] = w²/6.
    w = 0.9
    add("blur", (x, y, 0.2), w, [],
        lambda u1, u2: (w * u2 * math.cos(2 * PI * u1), w * u2 * math.sin(2 * PI * u1)),
        [U(1000), U(1000)], analytic=[("mean", 0, 0.0), ("var", 0, w * w / 6), ("var", 1, w * w / 6)])

    # gaussian_blur: radius w (S − 2), S ~ Irwin–Hall(4), var(S) = 1/3: E[x²] = w² (1/3) / 2.
    w = 1.1
    add("gaussian_blur", (x, y, 0.0), w, [],
        lambda u1, s: (w * (s - 2) * math.cos(2 * PI * u1), w * (s - 2) * math.sin(2 * PI * u1)),
        [U(1000), irwin_hall4_nodes(2000)],
        analytic=[("mean", 0, 0.0), ("var", 0, w * w / 6), ("var", 1, w * w / 6)])

    # radial_blur: g = w (S − 2); angle atan2(y, x) + sin(angle·π/2) g; zoom cos(angle·π/2) g − 1;
    # (r cos a + rz x, r sin a + rz y).
    w, ang = 0.6, 0.4
    spin, zoom = math.sin(ang * PI / 2), math.cos(ang * PI / 2)

    def radial(s):
        g = w * (s - 2)
        aa = atan_yx(x, y) + spin * g
        rz = zoom * g - 1
        return r * math.cos(aa) + rz * x, r * math.sin(aa) + rz * y

    add("radial_blur", (x, y, 0.5), w, [ang], radial, [irwin_hall4_nodes(20000)])

    # pie: slice int(U1 slices + 0.5) (0 and `slices` half as likely), angle
    # rotation + 2π (slice + U2 thickness) / slices, radius w U3.
    w, slices, rot, thick = 0.85, 5.0, 0.3, 0.4
    ns = int(slices)
    slice_nodes = [(0, 0.5 / ns)] + [(k, 1.0 / ns) for k in range(1, ns)] + [(ns, 0.5 / ns)]

    def pie(sl, u2, u3):
        aa = rot + 2 * PI * (sl + u2 * thick) / slices
        return w * u3 * math.cos(aa), w * u3 * math.sin(aa)

    add("pie", (x, y, 0.0), w, [slices, rot, thick], pie, [slice_nodes, U(400), U(400)])

    # arch (weight used non-standardly): ang = U w π; (w sin ang, w sin² ang / cos ang).
    w = 0.4
    add("arch", (x, y, 0.1), w, [],
        lambda u: (w * math.sin(u * w * PI), w * math.sin(u * w * PI) ** 2 / math.cos(u * w * PI)), [U(200000)])

    # square: w (U1 − 1/2), w (U2 − 1/2): var w²/12.
    w = 1.3
    add("square", (x, y, 0.0), w, [], lambda u1, u2: (w * (u1 - 0.5), w * (u2 - 0.5)), [U(1000), U(1000)],
        analytic=[("mean", 0, 0.0), ("var", 0, w * w / 12), ("var", 1, w * w / 12)])

    # rays: ang = w U π; k = w · tan(ang) · w / (r² + EPS); (k cos x, k sin y).
    w = 0.3

    def rays(u):
        k = w * math.tan(w * u * PI) * w / (r2 + EPS)
        return k * math.cos(x), k * math.sin(y)

    add("rays", (x, y, 0.0), w, [], rays, [U(200000)])

    # blade: s = U w r; (w x (cos s + sin s), w x (cos s − sin s)).
    w = 0.9

    def blade(u):
        s = u * w * r
        return w * x * (math.cos(s) + math.sin(s)), w * x * (math.cos(s) - math.sin(s))

    add("blade", (x, y, -0.2), w, [], blade, [U(200000)])

    # twintrian: s = U w r; diff = log10(sin² s) + cos s (−30 where not finite);
    # (w x diff, w x (diff − π sin s)).
    w = 0.9

    def twintrian(u):
        s = u * w * r
        sn = math.sin(s)
        diff = math.log10(sn * sn) + math.cos(s) if sn != 0 else -30.0
        return w * x * diff, w * x * (diff - PI * sn)

    add("twintrian", (x, y, 0.0), w, [], twintrian, [U(1000000)])

    # super_shape: θ = m/4 · atan2(y, x) + π/4;
    # k = w ((rnd U + (1 − rnd) r) − holes) (|cos θ|^n2 + |sin θ|^n3)^(−1/n1) / r; (k x, k y).
    w, rnd, m_, n1, n2, n3, holes = 0.8, 0.3, 5.0, 2.0, 1.5, 0.8, 0.1
    th = m_ / 4 * atan_yx(x, y) + PI / 4
    shape = (abs(math.cos(th)) ** n2 + abs(math.sin(th)) ** n3) ** (-1.0 / n1)

    def supershape(u):
        k = w * ((rnd * u + (1 - rnd) * r) - holes) * shape / r
        return k * x, k * y

    add("super_shape", (x, y, 0.0), w, [rnd, m_, n1, n2, n3, holes], supershape, [U(20000)])

    # flower: k = w (U − holes) cos(petals atan2(y, x)) / r; (k x, k y).
    w, petals, fholes = 0.9, 3.0, 0.2
    cp = math.cos(petals * atan_yx(x, y))
    add("flower", (x, y, 0.3), w, [petals, fholes],
        lambda u: (w * (u - fholes) * cp / r * x, w * (u - fholes) * cp / r * y), [U(20000)])

    # conic: k = w (U − holes) e / (1 + e x / r) / r; (k x, k y).
    w, ecc, choles = 0.9, 0.6, 0.1
    cf = ecc / (1 + ecc * x / r) / r
    add("conic", (x, y, 0.0), w, [ecc, choles],
        lambda u: (w * (u - choles) * cf * x, w * (u - choles) * cf * y), [U(20000)])

    # parabola: (height w sin² r U1, width w cos r U2).
    w, height, width = 0.9, 0.7, 0.5
    add("parabola", (x, y, 0.0), w, [height, width],
        lambda u1, u2: (height * w * math.sin(r) ** 2 * u1, width * w * math.cos(r) * u2), [U(1000), U(1000)])

    # boarders: with probability 1/4 (U ≥ 0.75) the half-offset point; otherwise pushed a quarter
    # towards the cell edge its offset points at.
    def boarders(bx, by, w, u):
        rx, ry = round_half_even(bx), round_half_even(by)
        ox, oy = bx - rx, by - ry
        if u >= 0.75:
            return w * (ox * 0.5 + rx), w * (oy * 0.5 + ry)
        if abs(ox) >= abs(oy):
            if ox >= 0:
                return w * (ox * 0.5 + rx + 0.25), w * (oy * 0.5 + ry + 0.25 * oy / ox)
            return w * (ox * 0.5 + rx - 0.25), w * (oy * 0.5 + ry - 0.25 * oy / ox)
        if oy >= 0:
            return w * (ox * 0.5 + rx + ox / oy * 0.25), w * (oy * 0.5 + ry + 0.25)
        return w * (ox * 0.5 + rx - ox / oy * 0.25), w * (oy * 0.5 + ry - 0.25)

    # One point per branch: |ox| < |oy| with oy ≥ 0 and < 0, |ox| ≥ |oy| with ox ≥ 0 and < 0.
    for bx, by, w in ((0.33, -1.58, 0.9), (0.1, -1.35, 0.8), (2.3, 0.1, 1.1), (-0.4, 1.15, 0.7)):
        add("boarders", (bx, by, 0.0), w, [], lambda u, bx=bx, by=by, w=w: boarders(bx, by, w, u), [U(1000)],
            branches=[(boarders(bx, by, w, 0.9), 0.25), (boarders(bx, by, w, 0.1), 0.75)])

    # cpow: ang = (c a + d ln r + 2π floor(power U)) / power... with c = re/power, d = im/power,
    # va = 2π / power; modulus w exp(c ln r − d a).
    for w, cre, cim, cpw in ((0.8, 1.3, 0.4, 3.0), (0.7, 0.9, -0.5, 2.5)):
        aa, lnr = atan_yx(x, y), math.log(r)
        vc, vd, va = cre / cpw, cim / cpw, 2 * PI / cpw
        mm = w * math.exp(vc * lnr - vd * aa)
        bc = [((mm * math.cos(vc * aa + vd * lnr + va * k), mm * math.sin(vc * aa + vd * lnr + va * k)), q)
              for k, q in trunc_nodes(cpw)]
        add("cpow", (x, y, 0.0), w, [cre, cim, cpw], lambda k, bc=bc: bc[k][0], [trunc_nodes(cpw)], bc)

    # wedge_julia: t = trunc(|power| U); a = (atan2(y, x) + 2π t) / power;
    # c = floor((count a + π) / 2π); a' = a (1 − angle count / 2π) + c angle; radius w r2^(dist/power/2).
    for w, wangle, wcount, wpower, wdist in ((0.7, 0.4, 2.0, 3.0, 1.2), (0.8, 0.3, 3.0, -2.5, 0.9)):
        rr = w * r2 ** (wdist / wpower / 2.0)
        bw = []
        for t, q in trunc_nodes(abs(wpower)):
            a0 = (atan_yx(x, y) + 2 * PI * t) / wpower
            c = math.floor((wcount * a0 + PI) / PI / 2.0)
            a1 = a0 * (1.0 - wangle * wcount / PI / 2.0) + c * wangle
            bw.append(((rr * math.cos(a1), rr * math.sin(a1)), q))
        add("wedge_julia", (x, y, 0.0), w, [wangle, wcount, wpower, wdist], lambda t, bw=bw: bw[t][0],
            [trunc_nodes(abs(wpower))], bw)

    # pre_blur: moves the point by w (S − 2) (cos 2π U5, sin 2π U5); the moments are those of the
    # displacement (what apply returns): E = 0, E[dx²] = w² / 6.
    w = 0.5
    add("pre_blur", (x, y, 0.0), w, [],
        lambda s, u: (w * (s - 2) * math.cos(2 * PI * u), w * (s - 2) * math.sin(2 * PI * u)),
        [irwin_hall4_nodes(2000), U(1000)], analytic=[("mean", 0, 0.0), ("var", 0, w * w / 6), ("var", 1, w * w / 6)])
    return out


def round_half_even(v):
    """C's rint() in the default rounding mode."""
    return float(round(v))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    data = {
        "about": "Independent reference for GridIFS's flame variations; made by variation_reference.py "
                 "from flam3 3.1's formulas and the documented 3D forms. Do not edit by hand.",
        "eps": EPS,
        "deterministic": [{"name": n, "writes_z": DETERMINISTIC[n][1] is not None, "cases": deterministic_cases(n)}
                          for n in DETERMINISTIC],
        "random": random_cases(),
    }
    with open(os.path.join(here, "variation_reference.json"), "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")
    print(len(data["deterministic"]), "deterministic variations,", len(data["random"]), "random ones")


if __name__ == "__main__":
    main()
