#!/usr/bin/env python3
"""Writes the 2D flam3 cross-check pairs: each linear IFS both as a .gridifs project
(affine 2x2x2 grids seen straight down the z axis through an orthographic camera) and as a flam3
genome with the same size, quality, palette and tone-mapping settings.

A GridIFS function is a grid; an affine map p -> A p + t is a 2x2x2 grid whose 8 nodes sit at
A u + t (trilinear interpolation reproduces it exactly), written as one `nodes` op moving each
node u by A u + t - u. z is collapsed to 0, so the attractor lies in the z = 0 plane.

Camera: pitch 90 (looking down -z), yaw -90 (image x = world x, image up = world +y), ortho,
distance 2, fov 2*atan(0.5) = 53.13 deg -> the view is [-1, 1]^2 and pixels_per_unit = H/2.
flam3's image rows go down with y, so its genome flips y (coefficients conjugated by y -> -y).

Run from this folder: python3 make_crosscheck.py
"""
import json
import math

SIZE = 160          # pixels (square)
# The view centre is offset by a fraction of a pixel: with a dyadic view the attractors' edges
# (y = 0.6875, ...) fall exactly on pixel boundaries, where float (GridIFS) and double (flam3)
# rounding put a few samples on different sides, and the density estimator then blurs them.
CENTER = (0.0123, 0.0071)
QUALITY = 200       # samples per output pixel -> samples = QUALITY * SIZE^2
PALETTE = 15        # flam3 palette number (GridIFS "flam3:15")
# brightness 1 and gamma 2 (instead of flam3's 4 and 4) keep most of the attractor below alpha
# saturation (alpha = min(1, density^(1/gamma))), so the compared alpha still measures density.
SETTINGS = dict(brightness=1.0, gamma=2.0, gamma_threshold=0.01, vibrancy=1.0, highlight_power=1.0,
                supersample=1, estimator_radius=9.0, estimator_minimum=0.0, estimator_curve=0.4,
                filter_radius=0.5)

# (weight, color index, A = [[a, b], [c, d]], t) for x' = a x + b y + tx, y' = c x + d y + ty
SIERPINSKI = [
    (1.0, 0.0, [[0.5, 0.0], [0.0, 0.5]], [-0.45, -0.4]),
    (1.0, 0.5, [[0.5, 0.0], [0.0, 0.5]], [0.45, -0.4]),
    (1.0, 1.0, [[0.5, 0.0], [0.0, 0.5]], [0.0, 0.45]),
]

def fern():
    # Barnsley's fern, conjugated into [-1, 1]^2: q = s (p - c).
    s, cx, cy = 0.18, 0.24, 5.0
    maps = [
        (0.01, 0.0, [[0.0, 0.0], [0.0, 0.16]], [0.0, 0.0]),
        (0.85, 0.33, [[0.85, 0.04], [-0.04, 0.85]], [0.0, 1.6]),
        (0.07, 0.66, [[0.2, -0.26], [0.23, 0.22]], [0.0, 1.6]),
        (0.07, 1.0, [[-0.15, 0.28], [0.26, 0.24]], [0.0, 0.44]),
    ]
    out = []
    for w, col, A, t in maps:
        # f'(q) = A q + s (A c + t - c)
        acx = A[0][0] * cx + A[0][1] * cy
        acy = A[1][0] * cx + A[1][1] * cy
        out.append((w, col, A, [s * (acx + t[0] - cx), s * (acy + t[1] - cy)]))
    return out

def gridifs_project(name, maps):
    functions = []
    for n, (w, col, A, t) in enumerate(maps):
        moves = []
        for k in (0, 1):
            for j in (0, 1):
                for i in (0, 1):
                    u = [(-1.0, 1.0)[i], (-1.0, 1.0)[j], (-1.0, 1.0)[k]]
                    x = A[0][0] * u[0] + A[0][1] * u[1] + t[0]
                    y = A[1][0] * u[0] + A[1][1] * u[1] + t[1]
                    moves.append([i, j, k, [round(x - u[0], 12), round(y - u[1], 12), round(0.0 - u[2], 12)]])
        functions.append({"name": "f%d" % (n + 1), "resolution": [2, 2, 2], "weight": w,
                          "color": [1, 1, 1], "palette_index": col, "color_speed": 0.5,
                          "ops": [{"type": "nodes", "moves": moves}]})
    flame = dict(SETTINGS)
    flame["palette"] = "flam3:%d" % PALETTE
    return {"format": "gridifs", "version": 1,
            "camera": {"yaw": -90, "pitch": 90, "distance": 2.0, "target": [CENTER[0], CENTER[1], 0],
                       "fov": 2 * math.degrees(math.atan(0.5)), "ortho": True},
            "render": {"width": SIZE, "height": SIZE, "samples": QUALITY * SIZE * SIZE, "seed": 1, "skip": 20,
                       "background": [0, 0, 0], "depth_cue": 0.0, "mode": "flame", "flame": flame},
            "functions": functions}

def flam3_genome(name, maps):
    s = SETTINGS
    lines = ['<flame name="%s" size="%d %d" center="%g %g" scale="%g" zoom="0" oversample="%d" filter="%g" '
             'filter_shape="gaussian" quality="%d" background="0 0 0" brightness="%g" gamma="%g" '
             'gamma_threshold="%g" vibrancy="%g" highlight_power="%g" estimator_radius="%g" '
             'estimator_minimum="%g" estimator_curve="%g" palette="%d" palette_mode="linear" hue="0">'
             % (name, SIZE, SIZE, CENTER[0], -CENTER[1], SIZE / 2.0, s["supersample"], s["filter_radius"], QUALITY, s["brightness"],
                s["gamma"], s["gamma_threshold"], s["vibrancy"], s["highlight_power"], s["estimator_radius"],
                s["estimator_minimum"], s["estimator_curve"], PALETTE)]
    for w, col, A, t in maps:
        # y -> -y: A' = F A F, t' = F t with F = diag(1, -1). flam3 coefs: a d b e c f for
        # x' = a x + b y + c, y' = d x + e y + f.
        a, b, c, d = A[0][0], -A[0][1], -A[1][0], A[1][1]
        lines.append('   <xform weight="%g" color="%g" color_speed="0.5" linear="1" coefs="%.12g %.12g %.12g %.12g %.12g %.12g"/>'
                     % (w, col, a, c, b, d, t[0], -t[1]))
    lines.append('</flame>')
    return "\n".join(lines) + "\n"

for name, maps in (("sierpinski2d", SIERPINSKI), ("fern2d", fern())):
    with open(name + ".gridifs", "w") as f:
        json.dump(gridifs_project(name, maps), f, indent=1)
        f.write("\n")
    with open(name + ".flam3", "w") as f:
        f.write(flam3_genome(name, maps))
