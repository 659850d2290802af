#!/usr/bin/env python3
"""Regenerates the example projects of assets/figures/: the papers' figures that no plate project
already makes (docs/FIGURES.md lists every figure and its project). The committed .gridifs files
are the source of truth; this script records how they were built. Run: scripts/make-figure-examples.py
(the flame projects import assets/flames/swirl_spherical.flame with build/app/gridifs, or GRIDIFS_EXE)."""
import copy, json, math, os, subprocess, tempfile

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
OUT = os.path.join(ROOT, "assets", "figures")
# Looking straight down the z axis, orthographic: the papers' 2D figures (x right, y up).
TOP = {"yaw": -90.0, "pitch": 90.0, "distance": 2.4, "target": [0.0, 0.0, 0.0], "fov": 53.13010235415598, "ortho": True}
FLAME = {"palette": "gray", "brightness": 4.0, "gamma": 1.0, "gamma_threshold": 0.01, "vibrancy": 0.0,
         "highlight_power": 1.0, "supersample": 1, "estimator_radius": 9.0, "estimator_minimum": 0.0,
         "estimator_curve": 0.4, "filter_radius": 0.5}


def fn(name, color, pal, translate=(0, 0, 0), rotate=(0, 0, 0), scale=(0.5, 0.5, 0.5), ops=(), res=(2, 2, 2), weight=1.0,
       color_speed=0.5):
    return {"name": name, "resolution": list(res), "weight": weight, "color": list(color), "palette_index": pal,
            "color_speed": color_speed, "muted": False,
            "placement": {"translate": list(translate), "rotate": list(rotate), "scale": list(scale)}, "ops": list(ops)}


def project(fns, camera=TOP, mode="zbuffer", flame=None, width=512, height=512, samples=2000000, background=(0.02, 0.02, 0.03), **extra):
    render = {"width": width, "height": height, "samples": samples, "seed": 1, "skip": 20,
              "background": list(background), "depth_cue": 0.0, "mode": mode, "flame": dict(flame or FLAME)}
    p = {"format": "gridifs", "version": 1, "camera": dict(camera), "render": render, "functions": fns}
    p.update(extra)
    return p


def write(name, p):
    with open(os.path.join(OUT, name + ".gridifs"), "w") as f:
        json.dump(p, f, indent=1)
        f.write("\n")


COL = [(1.0, 0.55, 0.15), (0.2, 0.65, 1.0), (0.35, 0.9, 0.35), (0.95, 0.3, 0.5)]
CORNERS = [(-0.5, -0.5), (0.5, -0.5), (0.0, 0.5)]  # the triangle's corners, halfway in


def gasket(ops0=(), res0=(2, 2, 2)):
    # Three maps p -> (p + corner)/2 in the plane z = 0 (z halved too, so the attractor is flat).
    return [fn("f%d" % (i + 1), COL[i], i / 2, translate=(c[0], c[1], 0.0), scale=(0.5, 0.5, 0.5),
               ops=ops0 if i == 0 else (), res=res0 if i == 0 else (2, 2, 2)) for i, c in enumerate(CORNERS)]


def sierpinski():
    # Gröller & Wegenkittl figure 1 and Draves & Reckase figure 2: the Sierpinski triangle.
    write("sierpinski_triangle", project(gasket()))
    # Gröller & Wegenkittl figure 3: f1 replaced by a nonlinear function defined by grid distortion.
    bend = {"type": "bend", "axis": "x", "toward": "y", "k": 0.6, "center": "grid", "selection": []}
    write("sierpinski_one_nonlinear", project(gasket([bend], (6, 6, 2))))


def op(kind, **kw):
    o = {"type": kind}
    o.update(kw)
    return o


def grids():
    # Gröller & Wegenkittl figures 5–10, 13 and 14: single grid distortions in 2D (grids of Nx × Ny × 2
    # nodes). `gridifs nodes --function NAME` lists each; the figures show the grid from above.
    s = dict(center="grid", selection=[])
    fns = [
        fn("taper", COL[0], 0.0, scale=(1, 1, 1), res=(9, 9, 2), ops=[op("taper", axis="y", profile="linear", k=0.6, omega=3.14159, **s)]),
        fn("twist", COL[1], 0.1, scale=(1, 1, 1), res=(6, 2, 2), ops=[op("scale", factors=[1, 0.3, 0.3], **s), op("twist", axis="x", profile="linear", k=1.2, omega=1.0, **s)]),
        fn("bend", COL[2], 0.2, scale=(1, 1, 1), res=(9, 9, 2), ops=[op("bend", axis="y", toward="x", k=0.9, **s)]),
        # The magnet and the morph's points sit in the grid's bottom layer (z = -1), the one drawn.
        fn("magnet", COL[3], 0.3, scale=(1, 1, 1), res=(11, 11, 2), ops=[op("magnet", point=[0.2, 0.2, -1.0], dmax=1.2, strength=0.5, falloff=1.5)]),
        fn("before_morph", COL[0], 0.4, scale=(1, 1, 1), res=(9, 9, 2)),
        fn("morph", COL[1], 0.5, scale=(1, 1, 1), res=(9, 9, 2), ops=[op("morph", pairs=[[[-0.5, -0.5, -1], [-0.1, -0.7, -1]], [[0.5, -0.3, -1], [0.7, 0.2, -1]], [[0.0, 0.6, -1], [-0.4, 0.3, -1]]], strength=1.0)]),
        fn("taper_linear", COL[2], 0.6, scale=(1, 1, 1), res=(9, 9, 2), ops=[op("taper", axis="y", profile="linear", k=0.5, omega=3.14159, **s)]),
        fn("taper_sine", COL[3], 0.7, scale=(1, 1, 1), res=(9, 9, 2), ops=[op("taper", axis="y", profile="sine", k=0.4, omega=3.14159, **s)]),
        fn("taper_pingpong", COL[0], 0.8, scale=(1, 1, 1), res=(9, 9, 2), ops=[op("taper", axis="y", profile="pingpong", k=0.4, omega=3.14159, **s)]),
    ]
    calc = op("calculator", x="x*cos(v1*sqrt(x^2+y^2)) - y*sin(v1*sqrt(x^2+y^2))", y="x*sin(v1*sqrt(x^2+y^2)) + y*cos(v1*sqrt(x^2+y^2))", z="z",
              vars={"v1": {"value": 0.2, "min": -1, "max": 1}, "v2": {"value": 0, "min": -1, "max": 1}, "v3": {"value": 0, "min": -1, "max": 1}}, seed=7, **s)
    # Figure 14's expression with v1 = 0.2 on a grid of ±5 units, as the paper's (d reaches ~7).
    fns.append(fn("calculator", COL[1], 0.9, scale=(1, 1, 1), res=(11, 11, 2), ops=[op("scale", factors=[5, 5, 1], **s), calc, op("scale", factors=[0.2, 0.2, 1], **s)]))
    write("grid_operations", project(fns))


def measures():
    # Sokolov & Gentil figure 3: one IFS of four maps onto the quarters of a square, rendered as its
    # measure (log density, grey): equal probabilities give an even square, {0.30, 0.20, 0.25, 0.25}
    # a multifractal measure.
    quarters = [(-0.5, -0.5), (0.5, -0.5), (-0.5, 0.5), (0.5, 0.5)]
    for name, weights in (("measure_equal", (1, 1, 1, 1)), ("measure_unequal", (0.30, 0.20, 0.25, 0.25))):
        fns = [fn("q%d" % i, (1, 1, 1), 0.0, translate=(q[0], q[1], 0.0), weight=w) for i, (q, w) in enumerate(zip(quarters, weights))]
        write(name, project(fns, mode="flame", flame=dict(FLAME, brightness=1.5, gamma=2.0), background=(0, 0, 0)))


def native_swirl():
    """The swirl/spherical genome imported with its variations kept (as assets/flames/
    swirl_spherical.gridifs is); needs a built gridifs."""
    exe = os.environ.get("GRIDIFS_EXE", os.path.join(ROOT, "build", "app", "gridifs"))
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "swirl.gridifs")
        subprocess.run([exe, "import-flame", os.path.join(ROOT, "assets", "flames", "swirl_spherical.flame"), "-o", out], check=True)
        return json.load(open(out))


def flame_refinements(src):
    # Draves & Reckase figure 3 c–f on the swirl/spherical flame: grey log density, colour, gamma 4,
    # vibrancy 1 (a and b are the grey one with --density-display binary and linear).
    base = src["render"]["flame"]
    for name, change in (("flame_grey", dict(palette="gray", gamma=1.0, vibrancy=0.0)),
                         ("flame_color", dict(gamma=1.0, vibrancy=0.0)),
                         ("flame_gamma", dict(gamma=4.0, vibrancy=0.0)),
                         ("flame_vibrant", dict(gamma=4.0, vibrancy=1.0))):
        p = copy.deepcopy(src)
        p["render"]["flame"] = dict(base, **change)
        write(name, p)
    # Figure 5: symmetry by added rotations about the view axis (weight = the others' sum). With
    # colour speed 0 the rotations keep the colours; with the others' speed they wash out (5d).
    total = sum(f["weight"] for f in src["functions"])
    for name, speed in (("flame_symmetry", 0.0), ("flame_symmetry_washed", 0.5)):
        p = copy.deepcopy(src)
        for k, angle in enumerate((120.0, 240.0)):
            p["functions"].append(fn("rot%d" % int(angle), (1, 1, 1), 0.0, rotate=(0, 0, angle), scale=(1, 1, 1), weight=total, color_speed=speed))
        write(name, p)


def polar():
    # Sokolov & Gentil figure 10: f1 a condensation set (the comma, turned into the plane z = 0)
    # and f2(r, θ) = (r/√2, 2θ), written without atan2 as ((x² − y²), 2xy) / (√2 r) on an even grid
    # (no node at r = 0). The chaos game's density is the measure attractor.
    s = dict(center="grid", selection=[])
    f2 = fn("polar", (1, 1, 1), 1.0, scale=(1, 1, 1), res=(32, 32, 2), ops=[op("calculator",
            x="(x^2 - y^2) / (sqrt(2) * sqrt(x^2 + y^2))", y="2 * x * y / (sqrt(2) * sqrt(x^2 + y^2))", z="z * 0.5",
            vars={"v1": {"value": 0, "min": -1, "max": 1}, "v2": {"value": 0, "min": -1, "max": 1}, "v3": {"value": 0, "min": -1, "max": 1}}, seed=7, **s)])
    f1 = {"name": "comma", "kind": "condensation", "weight": 1.0,
          "set": {"mesh": "../volumes/comma.obj", "fill": "solid",
                  "placement": {"translate": [0.3, 0.2, 0.0], "rotate": [90.0, 0.0, 0.0], "scale": [0.7, 0.7, 0.7]}},
          "color": [1.0, 1.0, 1.0], "palette_index": 0.0, "color_speed": 0.5, "muted": False}
    write("polar_condensation", project([f1, f2], camera=dict(TOP, distance=1.5), mode="flame", flame=dict(FLAME, brightness=0.6, gamma=2.0), background=(0, 0, 0)))


def motion(src):
    # Draves & Reckase figure 7: the flame turning under the camera (its yaw keyed, 120° a second)
    # with a long shutter (a whole frame interval at 4 frames a second), so that one frame's time
    # samples spread over 30°.
    p = copy.deepcopy(src)
    p["animation"] = {"fps": 4.0, "start": 0.0, "end": 1.0, "loop": False, "shutter": 1.0}
    yaw = p["camera"]["yaw"]
    p["tracks"] = {"camera.yaw": [{"t": 0.0, "v": yaw, "interp": "linear"}, {"t": 1.0, "v": yaw + 120.0, "interp": "linear"}]}
    write("flame_motion", p)


def field_steps():
    # Colonna figure 2: the field after the first 1, 2, 3 and all 12 meshes (bicubic), seen from
    # above as the square it lifts, brighter where higher (the z-buffer's depth cue).
    src = json.load(open(os.path.join(ROOT, "assets", "animation", "earthquake.gridifs")))
    for octaves in (1, 2, 3, 12):
        p = copy.deepcopy(src)
        p.pop("animation", None)
        p["final"]["ops"][0].update(octaves=octaves, interpolation="cubic", amplitude=[0.0, 0.0, 0.8])
        p["camera"] = dict(TOP, distance=2.4)
        for f in p["functions"]:
            f["color"] = [1.0, 1.0, 1.0]
        p["final"]["color"] = [1.0, 1.0, 1.0]
        p["render"].update(mode="zbuffer", width=512, height=512, samples=4000000, depth_cue=1.0, background=[0.0, 0.0, 0.0])
        write("field_octaves_%d" % octaves, p)


BEZIER_LEFT = [[1, 0, 0, 0], [0.5, 0.5, 0, 0], [0.25, 0.5, 0.25, 0], [0.125, 0.375, 0.375, 0.125]]
BEZIER_RIGHT = [[0.125, 0.375, 0.375, 0.125], [0, 0.25, 0.5, 0.25], [0, 0, 0.5, 0.5], [0, 0, 0, 1]]


def kron(a, b):
    n = len(b)
    return [[a[i][k] * b[j][l] for k in range(len(a)) for l in range(n)] for i in range(len(a)) for j in range(n)]


def free_forms():
    # Thollot et al. figure 5.1's Bézier curve beside the fractal one: the same control points with
    # the de Casteljau matrices at r = 1/2 (their T'0, T'1), which the roughness bends away from.
    curve = json.load(open(os.path.join(ROOT, "assets", "fractal_bezier_curve.gridifs")))
    curve["functions"][0]["matrix"], curve["functions"][1]["matrix"] = BEZIER_LEFT, BEZIER_RIGHT
    write("bezier_curve", curve)
    # Figure 5.3, left: the tensor product of a Bézier curve with a fractal one. The rough patch's
    # matrices q_ij are A_i ⊗ B_j for two rough curves A and B, read back from the rows and columns
    # where the other factor's entry is 1; the Bézier curve replaces A.
    patch = json.load(open(os.path.join(ROOT, "assets", "rough_bicubic_patch.gridifs")))
    m = {f["name"]: f["matrix"] for f in patch["functions"]}
    a = {i: [[m["q%s0" % i][4 * r][4 * c] for c in range(4)] for r in range(4)] for i in "01"}
    b = {j: [[m["q0%s" % j][r][c] for c in range(4)] for r in range(4)] for j in "01"}
    for f in patch["functions"]:
        i, j = f["name"][1], f["name"][2]
        assert max(abs(x - y) for r1, r2 in zip(kron(a[i], b[j]), f["matrix"]) for x, y in zip(r1, r2)) < 1e-9
        f["matrix"] = kron(BEZIER_LEFT if i == "0" else BEZIER_RIGHT, b[j])
    write("bezier_fractal_patch", patch)
    # Figure 5.4, right: the Sierpinski gasket on a bicubic patch (three of the four quarters),
    # deformed fractally: the smooth gasket's Bézier matrices B_i ⊗ B_j become the rough A_i ⊗ B_j.
    gasket = json.load(open(os.path.join(ROOT, "assets", "bent_sierpinski_gasket.gridifs")))
    for f in gasket["functions"]:
        f["matrix"] = kron(a[f["name"][1]], b[f["name"][2]])
    write("rough_sierpinski_gasket", gasket)


def flower():
    # Sokolov & Gentil figure 2: the deterministic algorithm from a flower. A flat five-petal
    # flower (r = 0.6 + 0.3 cos 5θ, a triangle fan) is the start set A0 for `export-mesh --base`;
    # the Sierpinski triangle's maps take it to A1, A2, … and the gasket.
    n = 80
    lines = ["# a flat five-petal flower, the start set of Sokolov & Gentil's figure 2",
             "# made by scripts/make-figure-examples.py", "v 0 0 0"]
    for k in range(n):
        t = 2 * math.pi * k / n
        r = 0.6 + 0.3 * math.cos(5 * t)
        lines.append("v %.5f %.5f 0" % (r * math.cos(t), r * math.sin(t)))
    lines += ["f 1 %d %d" % (k + 2, (k + 1) % n + 2) for k in range(n)]
    with open(os.path.join(OUT, "flower.obj"), "w") as f:
        f.write("\n".join(lines) + "\n")


def pine_series():
    # Sokolov & Gentil figure 4: volumes/pine_trees.gridifs seen from the side, framing the
    # geometric series of trees shrinking toward the contraction's fixed corner.
    p = json.load(open(os.path.join(ROOT, "assets", "volumes", "pine_trees.gridifs")))
    p["camera"].update(yaw=90.0, pitch=8.0, distance=3.4, target=[-0.25, 0.0, -0.2])
    p["functions"][1]["set"]["mesh"] = "../volumes/pine_tree.obj"
    write("pine_tree_series", p)


def terrains():
    # Colonna figure 4: the same fractal terrain with bilinear and with bicubic interpolation, seen
    # from above and lit from the right so that the bilinear one's slope discontinuities show.
    src = json.load(open(os.path.join(ROOT, "assets", "animation", "earthquake.gridifs")))
    for interpolation in ("linear", "cubic"):
        p = copy.deepcopy(src)
        p.pop("animation", None)
        p["final"]["ops"][0].update(interpolation=interpolation, wind=[0.0, 0.0, 0.0])
        p["camera"] = dict(TOP, distance=2.4)
        p["render"].update(mode="shaded", width=512, height=512, samples=8000000, depth_cue=0.0, shading={
            "lights": [{"direction": [1.0, 0.0, 0.6], "color": [1.0, 1.0, 1.0], "intensity": 1.0, "shadows": True}],
            "ambient": 0.15, "specular": 0.1, "shininess": 20.0, "ao": {"radius": 8.0, "strength": 0.5, "directions": 8},
            "fog": {"color": [0.0, 0.0, 0.0], "density": 0.0}, "dof": {"aperture": 0.0}})
        write("terrain_" + interpolation, p)


if __name__ == "__main__":
    os.makedirs(OUT, exist_ok=True)
    sierpinski()
    grids()
    measures()
    swirl = native_swirl()
    flame_refinements(swirl)
    terrains()
    polar()
    motion(swirl)
    field_steps()
    free_forms()
    flower()
    pine_series()
    # Every project in GridIFS's own saved form, byte for byte what the modeller writes (the form
    # the shipped-projects test holds assets/ to).
    resave = os.environ.get("GRIDIFS_RESAVE", os.path.join(ROOT, "build", "tests", "gridifs_resave_project"))
    subprocess.run([resave] + sorted(os.path.join(OUT, f) for f in os.listdir(OUT) if f.endswith(".gridifs")), check=True)
    for f in os.listdir(OUT):  # the backups saving keeps
        if f.endswith(".gridifs~"):
            os.remove(os.path.join(OUT, f))
