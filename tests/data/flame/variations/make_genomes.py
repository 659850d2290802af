#!/usr/bin/env python3
"""Writes the flame genomes of the variation cross-check (tests/cli/test_flam3_variations.cpp):
one genome per group of flam3's variations, every variation of the group used by some xform.
Each xform blends one or two variations of the group with linear on a contractive pre-affine
map, so that the attractor stays in view. Fixed seed: the files are reproducible."""
import random

GROUPS = {
    "appendix": ["sinusoidal", "spherical", "swirl", "horseshoe", "polar", "handkerchief", "heart", "disc",
                 "spiral", "hyperbolic", "diamond", "ex", "bent", "fisheye", "exponential", "power", "cosine",
                 "eyefish", "bubble", "cylinder", "tangent", "cross", "secant2"],
    "dependent": ["waves", "popcorn", "rings", "fan"],
    "parametric": ["blob", "pdj", "fan2", "rings2", "perspective", "ngon", "curl", "rectangles", "disc2",
                   "super_shape", "flower", "conic", "parabola", "bent2", "bipolar", "cell", "cpow", "curve",
                   "escher", "lazysusan", "modulus", "oscilloscope", "popcorn2", "separation", "split", "splits",
                   "stripes", "wedge", "wedge_julia", "wedge_sph", "whorl", "waves2", "auger", "flux", "mobius"],
    "random": ["julia", "noise", "julian", "juliascope", "blur", "gaussian_blur", "radial_blur", "pie", "arch",
               "square", "rays", "blade", "twintrian", "boarders", "pre_blur"],
    "plugin": ["butterfly", "edisc", "elliptic", "foci", "loonie", "polar2", "scry", "exp", "log", "sin", "cos",
               "tan", "sec", "csc", "cot", "sinh", "cosh", "tanh", "sech", "csch", "coth"],
}

# Parameters of the parametric and random variations: values that keep the maps tame.
PARAMS = {
    "blob": {"blob_low": 0.3, "blob_high": 1.1, "blob_waves": 4},
    "pdj": {"pdj_a": 1.2, "pdj_b": -1.7, "pdj_c": 0.8, "pdj_d": 2.1},
    "fan2": {"fan2_x": 0.6, "fan2_y": 0.4},
    "rings2": {"rings2_val": 0.5},
    "perspective": {"perspective_angle": 0.4, "perspective_dist": 2.5},
    "ngon": {"ngon_sides": 5, "ngon_power": 2, "ngon_circle": 1, "ngon_corners": 0.5},
    "curl": {"curl_c1": 0.4, "curl_c2": 0.1},
    "rectangles": {"rectangles_x": 0.6, "rectangles_y": 0.4},
    "disc2": {"disc2_rot": 0.7, "disc2_twist": 1.3},
    "super_shape": {"super_shape_rnd": 0.3, "super_shape_m": 5, "super_shape_n1": 2, "super_shape_n2": 1.5,
                    "super_shape_n3": 1.5, "super_shape_holes": 0.1},
    "flower": {"flower_petals": 5, "flower_holes": 0.2},
    "conic": {"conic_eccentricity": 0.7, "conic_holes": 0.1},
    "parabola": {"parabola_height": 0.8, "parabola_width": 0.6},
    "bent2": {"bent2_x": 0.6, "bent2_y": 1.4},
    "bipolar": {"bipolar_shift": 0.3},
    "cell": {"cell_size": 0.7},
    "cpow": {"cpow_r": 1.5, "cpow_i": 0.3, "cpow_power": 2},
    "curve": {"curve_xamp": 0.4, "curve_yamp": 0.3, "curve_xlength": 0.8, "curve_ylength": 1.2},
    "escher": {"escher_beta": 0.6},
    "lazysusan": {"lazysusan_x": 0.2, "lazysusan_y": -0.1, "lazysusan_spin": 0.8, "lazysusan_space": 0.3,
                  "lazysusan_twist": 0.5},
    "modulus": {"modulus_x": 0.8, "modulus_y": 0.6},
    "oscilloscope": {"oscilloscope_separation": 0.5, "oscilloscope_frequency": 1.5, "oscilloscope_amplitude": 0.6,
                     "oscilloscope_damping": 0.2},
    "popcorn2": {"popcorn2_x": 0.2, "popcorn2_y": 0.15, "popcorn2_c": 2.5},
    "separation": {"separation_x": 0.3, "separation_xinside": 0.1, "separation_y": 0.2, "separation_yinside": 0.05},
    "split": {"split_xsize": 0.6, "split_ysize": 0.4},
    "splits": {"splits_x": 0.2, "splits_y": 0.15},
    "stripes": {"stripes_space": 0.3, "stripes_warp": 0.5},
    "wedge": {"wedge_angle": 0.6, "wedge_hole": 0.1, "wedge_count": 3, "wedge_swirl": 0.2},
    "wedge_julia": {"wedge_julia_angle": 0.5, "wedge_julia_count": 2, "wedge_julia_power": 3,
                    "wedge_julia_dist": 1},
    "wedge_sph": {"wedge_sph_angle": 0.5, "wedge_sph_hole": 0.1, "wedge_sph_count": 3, "wedge_sph_swirl": 0.2},
    "whorl": {"whorl_inside": 0.6, "whorl_outside": 0.4},
    "waves2": {"waves2_freqx": 2, "waves2_scalex": 0.2, "waves2_freqy": 3, "waves2_scaley": 0.15},
    "auger": {"auger_freq": 3, "auger_weight": 0.4, "auger_sym": 0.3, "auger_scale": 0.8},
    "flux": {"flux_spread": 0.3},
    "mobius": {"mobius_re_a": 0.8, "mobius_im_a": 0.2, "mobius_re_b": 0.1, "mobius_im_b": -0.3,
               "mobius_re_c": 0.2, "mobius_im_c": 0.1, "mobius_re_d": 1.0, "mobius_im_d": 0.1},
    "julian": {"julian_power": 4, "julian_dist": 1},
    "juliascope": {"juliascope_power": 3, "juliascope_dist": 0.8},
    "radial_blur": {"radial_blur_angle": 0.4},
    "pie": {"pie_slices": 5, "pie_rotation": 0.3, "pie_thickness": 0.6},
}


def affine(rng, scale):
    """A contractive pre-affine map: rotation, anisotropic scale, offset ("a d b e c f")."""
    import math
    t = rng.uniform(-math.pi, math.pi)
    sx, sy = scale * rng.uniform(0.6, 1.0), scale * rng.uniform(0.6, 1.0)
    a, b, d, e = sx * math.cos(t), -sy * math.sin(t), sx * math.sin(t), sy * math.cos(t)
    c, f = rng.uniform(-0.6, 0.6), rng.uniform(-0.6, 0.6)
    return " ".join(f"{v:.6f}" for v in (a, d, b, e, c, f))


def genome(name, variations, rng):
    xforms = []
    per = 2
    chunks = [variations[i:i + per] for i in range(0, len(variations), per)]
    for i, chunk in enumerate(chunks):
        weights = {v: round(rng.uniform(0.3, 0.6), 3) for v in chunk}
        attrs = " ".join(f'{v}="{w}"' for v, w in weights.items())
        attrs += f' linear="{round(max(0.1, 1.0 - sum(weights.values())), 3)}"'
        for v in chunk:
            for p, value in PARAMS.get(v, {}).items():
                attrs += f' {p}="{value}"'
        color = round(i / max(1, len(chunks) - 1), 3)
        xforms.append(f'   <xform weight="{round(rng.uniform(0.5, 1.0), 3)}" color="{color}" color_speed="0.5" '
                      f'{attrs} coefs="{affine(rng, 0.7)}"/>')
    # Two linear maps keep the whole attractor connected and in view.
    xforms.append(f'   <xform weight="0.5" color="0.2" color_speed="0.5" linear="1" coefs="{affine(rng, 0.5)}"/>')
    xforms.append(f'   <xform weight="0.5" color="0.8" color_speed="0.5" linear="1" coefs="{affine(rng, 0.5)}"/>')
    head = (f'<flame name="{name}" size="256 256" center="0 0" scale="55" rotate="0" oversample="1" '
            f'filter="0.5" quality="60" background="0 0 0" brightness="4" gamma="2" gamma_threshold="0.01" '
            f'vibrancy="1" highlight_power="1" estimator_radius="9" estimator_minimum="0" '
            f'estimator_curve="0.4" palette="27">')
    return "<flames>\n" + head + "\n" + "\n".join(xforms) + "\n</flame>\n</flames>\n"


if __name__ == "__main__":
    import os
    here = os.path.dirname(os.path.abspath(__file__))
    for name, variations in GROUPS.items():
        rng = random.Random(name)
        with open(os.path.join(here, name + ".flame"), "w") as out:
            out.write(genome(name, variations, rng))
