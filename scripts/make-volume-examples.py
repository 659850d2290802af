#!/usr/bin/env python3
"""Builds the closed OBJ meshes of assets/volumes/ (the examples of Sokolov & Gentil's vapour
volumes): a comma and a letter L (fig. 9's two-set morph, in 3D), a pine tree (fig. 4's constant
condensation), and a cloud creature's sketch with balls placed inside it (fig. 13-14).
Every mesh is a union of closed, consistently oriented parts, so it can be filled."""
import math
import os
import random

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "assets", "volumes")


class Mesh:
    def __init__(self):
        self.v, self.f = [], []

    def add(self, verts, faces):
        base = len(self.v)
        self.v += verts
        self.f += [[base + i for i in face] for face in faces]

    def write(self, name, comment):
        with open(os.path.join(HERE, name), "w") as out:
            out.write("# %s\n# made by scripts/make-volume-examples.py\n" % comment)
            for x, y, z in self.v:
                out.write("v %.5f %.5f %.5f\n" % (x, y, z))
            for face in self.f:
                out.write("f " + " ".join(str(i + 1) for i in face) + "\n")


def ring_solid(mesh, centres, radii, frames, segments=16):
    """A closed tube through `centres` with circular sections of `radii` (capped at both ends)."""
    verts, faces = [], []
    for c, r, (u, w) in zip(centres, radii, frames):
        for s in range(segments):
            a = 2 * math.pi * s / segments
            verts.append(tuple(c[d] + r * (math.cos(a) * u[d] + math.sin(a) * w[d]) for d in range(3)))
    n = len(centres)
    for i in range(n - 1):
        for s in range(segments):
            t = (s + 1) % segments
            faces.append([i * segments + s, i * segments + t, (i + 1) * segments + t, (i + 1) * segments + s])
    start, end = len(verts), len(verts) + 1
    verts.append(centres[0])
    verts.append(centres[-1])
    for s in range(segments):
        t = (s + 1) % segments
        faces.append([start, t, s])
        faces.append([end, (n - 1) * segments + s, (n - 1) * segments + t])
    mesh.add(verts, faces)


def sphere(mesh, c, r, rings=10, segments=16, scale=(1, 1, 1)):
    centres, radii, frames = [], [], []
    for i in range(rings + 1):
        phi = math.pi * i / rings
        centres.append((c[0], c[1], c[2] - r * scale[2] * math.cos(phi)))
        radii.append(max(r * math.sin(phi), 1e-4))
        frames.append(((scale[0], 0, 0), (0, scale[1], 0)))
    ring_solid(mesh, centres, radii, frames, segments)


def cylinder_z(mesh, c, r, z0, z1, r1=None, segments=16):
    ring_solid(mesh, [(c[0], c[1], z0), (c[0], c[1], z1)], [r, r if r1 is None else r1],
               [((1, 0, 0), (0, 1, 0))] * 2, segments)


def box(mesh, lo, hi):
    verts = [(hi[0] if v & 1 else lo[0], hi[1] if v & 2 else lo[1], hi[2] if v & 4 else lo[2]) for v in range(8)]
    faces = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    mesh.add(verts, faces)


def comma():
    m = Mesh()
    sphere(m, (0, 0, 0.15), 0.32)
    # The tail: a tube curling down and to the left, thinning to a point.
    centres, radii, frames = [], [], []
    steps = 14
    for i in range(steps + 1):
        t = i / steps
        a = -0.2 - 1.9 * t
        centres.append((0.15 * math.cos(a) + 0.1, 0.0, 0.15 * math.sin(a) - 0.05 - 0.45 * t))
        radii.append(0.2 * (1 - t) + 0.02)
        frames.append(((1, 0, 0), (0, 1, 0)))
    ring_solid(m, centres, radii, frames)
    m.write("comma.obj", "a comma, fig. 9's first set")


def letter_l():
    m = Mesh()
    box(m, (-0.3, -0.15, -0.6), (-0.05, 0.15, 0.6))
    box(m, (-0.3, -0.15, -0.6), (0.35, 0.15, -0.35))
    m.write("letter_l.obj", "the letter L, fig. 9's second set")


def pine_tree():
    m = Mesh()
    cylinder_z(m, (0, 0), 0.08, -1.0, -0.6)
    for z0, r, h in ((-0.7, 0.55, 0.7), (-0.3, 0.42, 0.6), (0.1, 0.3, 0.6)):
        cylinder_z(m, (0, 0), r, z0, z0 + h, r1=0.001, segments=24)
    m.write("pine_tree.obj", "a pine tree, fig. 4's condensation set")


def creature():
    sketch = Mesh()
    parts = []
    body = ((0, 0, 0.1), 0.5, (1.0, 0.55, 0.5))
    head = ((0.62, 0, 0.3), 0.22, (1, 1, 1))
    sphere(sketch, body[0], body[1], scale=body[2])
    sphere(sketch, head[0], head[1])
    for x in (-0.3, 0.3):
        for y in (-0.15, 0.15):
            cylinder_z(sketch, (x, y), 0.08, -0.7, 0.0)
    cylinder_z(sketch, (-0.5, 0), 0.04, 0.1, 0.5, r1=0.01)  # the tail
    sketch.write("creature_sketch.obj", "a four-legged cloud creature, the sketch of fig. 13")
    balls = Mesh()
    rng = random.Random(7)
    inside = 0
    while inside < 28:
        p = (rng.uniform(-0.5, 0.5), rng.uniform(-0.27, 0.27), rng.uniform(-0.15, 0.35))
        q = [(p[d] - body[0][d]) / (body[1] * body[2][d]) for d in range(3)]
        if sum(c * c for c in q) < 0.7:
            sphere(balls, p, rng.uniform(0.05, 0.11), rings=6, segments=10)
            inside += 1
    sphere(balls, (0.64, 0, 0.3), 0.12, rings=6, segments=10)
    for x in (-0.3, 0.3):
        for y in (-0.15, 0.15):
            sphere(balls, (x, y, -0.45), 0.07, rings=6, segments=10)
    balls.write("creature_balls.obj", "balls placed inside the creature, the second model of fig. 13")




def projects():
    """The example projects, in GridIFS's saved form (the key order and number format it writes)."""
    import json
    template = os.path.join(HERE, "..", "..", "tests", "data", "saved", "assets", "sierpinski_tetrahedron.gridifs")
    with open(template) as f:
        base = json.load(f)
    base["render"]["background"] = [0.02, 0.02, 0.03]

    def fn(name, kind, weight, color, set_, palette_index=0.0, rotate=None):
        out = {"name": name, "kind": kind, "weight": weight}
        if kind == "median":
            out["rotate"] = 0.0 if rotate is None else rotate
        out["set"] = set_
        out.update({"color": color, "palette_index": palette_index, "color_speed": 0.5, "muted": False})
        return out

    def mesh(path, translate, scale, fill="solid", rotate=(0.0, 0.0, 0.0)):
        return {"mesh": path, "fill": fill, "placement": {"translate": list(translate), "rotate": list(rotate),
                                                           "scale": list(scale)}}

    def volume(resolution=128, iterations=300, samples=20000000):
        return {"resolution": resolution, "iterations": iterations, "skip": 20, "seed": 1, "samples": samples}

    def write(name, functions, vol, animation=None):
        p = dict(base)
        p["functions"] = functions
        p["volume"] = vol
        if animation:
            p["animation"] = animation
        with open(os.path.join(HERE, name), "w") as out:
            out.write(json.dumps(p, indent=2, ensure_ascii=False) + "\n")

    write("two_sets.gridifs", [
        fn("A", "median", 2.0, [1.0, 0.6, 0.3], {"primitive": "sphere", "center": [-0.45, 0.0, 0.0], "radius": 0.35}),
        fn("B", "median", 1.0, [0.3, 0.6, 1.0], {"primitive": "box", "center": [0.45, 0.0, 0.0], "size": [0.5, 0.5, 0.5]},
           palette_index=1.0)], volume())
    write("comma_to_letter.gridifs", [
        fn("comma", "median", 1.0, [1.0, 0.85, 0.6], mesh("comma.obj", (-0.5, 0.0, 0.05), (0.8, 0.8, 0.8))),
        fn("letter", "median", 1.0, [0.6, 0.8, 1.0], mesh("letter_l.obj", (0.5, 0.0, 0.0), (0.7, 0.7, 0.7)),
           palette_index=1.0)], volume())
    pine = {"name": "half", "resolution": [2, 2, 2], "weight": 1.0, "color": [0.8, 0.9, 0.8], "palette_index": 0.0,
            "color_speed": 0.5, "muted": False,
            "placement": {"translate": [-0.5, 0.0, -0.5], "rotate": [0.0, 0.0, 0.0], "scale": [0.5, 0.5, 0.5]},
            "ops": []}
    write("pine_trees.gridifs", [
        pine, fn("tree", "condensation", 1.0, [0.3, 0.8, 0.4], mesh("pine_tree.obj", (0.35, 0.0, 0.3), (0.6, 0.6, 0.6)),
                 palette_index=1.0)], volume(samples=20000000))
    write("cloud_creature.gridifs", [
        fn("sketch", "median", 2.0 / 3.0, [0.95, 0.95, 1.0], mesh("creature_sketch.obj", (0.0, 0.0, 0.1), (1.0, 1.0, 1.0))),
        fn("balls", "median", 1.0 / 3.0, [0.7, 0.75, 0.9], mesh("creature_balls.obj", (0.0, 0.0, 0.1), (1.0, 1.0, 1.0)),
           palette_index=1.0)], volume())
    # The creature as a cloud that drifts (Colonna's cloud dynamics): a fractal field weights its
    # density, the wind carries the field along x, and the periods close the loop after 4 s
    # (wind 0.25 × 4 s = one period of 1 along x).
    drifting = volume()
    drifting["field"] = {"strength": 1.5, "scale": 0.3, "ratio": 0.5, "octaves": 5, "gain": 0.7,
                         "interpolation": "cubic", "seed": 7, "wind": [0.25, 0.0, 0.0], "period": [1.0, 0.0, 0.0, 4.0]}
    write("drifting_cloud.gridifs", [
        fn("sketch", "median", 2.0 / 3.0, [0.95, 0.95, 1.0], mesh("creature_sketch.obj", (0.0, 0.0, 0.1), (1.0, 1.0, 1.0))),
        fn("balls", "median", 1.0 / 3.0, [0.7, 0.75, 0.9], mesh("creature_balls.obj", (0.0, 0.0, 0.1), (1.0, 1.0, 1.0)),
           palette_index=1.0)], drifting, animation={"fps": 24.0, "start": 0.0, "end": 4.0, "loop": True})


if __name__ == "__main__":
    os.makedirs(HERE, exist_ok=True)
    comma()
    letter_l()
    pine_tree()
    creature()
    projects()
