#!/usr/bin/env python3
"""Draws the sketches of assets/volumes/ with ImageMagick's `convert` and writes the 2D example
projects that use them as sets (Sokolov & Gentil's figures 6-14): a comma and a letter L (the two
condensation sets of figures 6-9), bananas (the start set S of figure 8), a four-legged creature
and balls placed inside it (figures 13-14, drawn flat). The projects look down z with an
orthographic camera, so a page of the book of drawings renders as the drawing on its sheet."""
import json
import os
import subprocess

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "assets", "volumes")
GREY = ["-colorspace", "Gray", "-depth", "8", "-strip"]  # no dates: the same bytes every time

SKETCHES = {
    "comma.png": ["-fill", "black", "-draw", "circle 50,90 50,73", "-fill", "none", "-stroke", "black",
                  "-strokewidth", "9", "-draw", "stroke-linecap round ellipse 30,95 36,45 -20,60"],
    "letter_l.png": ["-fill", "none", "-stroke", "black", "-strokewidth", "14", "-draw",
                     "stroke-linecap round stroke-linejoin round polyline 135,55 135,140 172,140"],
    "bananas.png": ["-fill", "black", "-draw", "ellipse 75,60 38,24 0,360", "-fill", "white", "-draw",
                    "ellipse 75,48 38,24 0,360", "-fill", "black", "-draw", "ellipse 125,125 38,24 0,360",
                    "-fill", "white", "-draw", "ellipse 125,113 38,24 0,360"],
    "creature.png": ["-fill", "none", "-stroke", "black", "-strokewidth", "6", "-draw", "ellipse 100,100 55,30 0,360",
                     "-draw", "circle 150,72 150,56", "-draw", "line 65,120 60,160", "-draw", "line 85,125 85,162",
                     "-draw", "line 120,125 122,162", "-draw", "line 140,120 146,160", "-draw", "line 45,95 25,120"],
    "creature_balls.png": ["-fill", "black", "-draw", "circle 75,95 75,82", "-draw", "circle 105,105 105,90",
                           "-draw", "circle 130,92 130,80", "-draw", "circle 150,72 150,62", "-draw",
                           "circle 63,140 63,132", "-draw", "circle 142,140 142,132"],
}


def sketches():
    for name, commands in SKETCHES.items():
        subprocess.run(["convert", "-size", "200x200", "xc:white"] + commands + GREY +
                       ["PNG8:" + os.path.join(HERE, name)], check=True)


# The projects are written in GridIFS's saved form (its key order, every number with a decimal
# point, every field), so that loading and saving one changes nothing.
def drawing(path, thickness=0.04):
    return {"image": path, "threshold": 0.5, "thickness": thickness, "invert": False,
            "placement": {"translate": [0.0, 0.0, 0.0], "rotate": [0.0, 0.0, 0.0], "scale": [1.0, 1.0, 1.0]}}


def median(name, image, weight=1.0, rotate=0.0, palette_index=0.0):
    return {"name": name, "kind": "median", "weight": weight, "rotate": rotate, "set": drawing(image),
            "color": [0.0, 0.0, 0.0], "palette_index": palette_index, "color_speed": 0.5, "muted": False}


def project(name, functions, start=None, mode="zbuffer", background=(1.0, 1.0, 1.0), iterations=300):
    volume = {"resolution": 128, "iterations": iterations, "skip": 20, "seed": 1, "samples": 20000000}
    if start:
        volume["start"] = start
    p = {"format": "gridifs", "version": 1,
         # Looking down z at the z = 0 plane, orthographic, +y up: the paper's sheet of paper.
         "camera": {"yaw": -90.0, "pitch": 89.9, "distance": 3.4, "target": [0.0, 0.0, 0.0], "fov": 35.0,
                    "ortho": True},
         "render": {"width": 512, "height": 512, "samples": 3000000, "seed": 1, "skip": 20,
                    "background": list(background), "depth_cue": 0.0, "mode": mode,
                    "flame": {"palette": "gray", "brightness": 4.0, "gamma": 2.2, "gamma_threshold": 0.01,
                              "vibrancy": 1.0, "highlight_power": 1.0, "supersample": 1, "estimator_radius": 9.0,
                              "estimator_minimum": 0.0, "estimator_curve": 0.4, "filter_radius": 0.5}},
         "functions": functions, "volume": volume}
    with open(os.path.join(HERE, name), "w") as out:
        out.write(json.dumps(p, indent=2) + "\n")


def projects():
    comma_and_l = [median("A", "comma.png"), median("B", "letter_l.png", palette_index=1.0)]
    project("drawings_median.gridifs", comma_and_l, start=drawing("comma.png"))
    project("book_of_drawings.gridifs", comma_and_l, start=drawing("bananas.png"))
    project("rotated_median.gridifs",
            [median("A", "comma.png"), median("B", "letter_l.png", rotate=120.0, palette_index=1.0)],
            mode="flame", background=(0.0, 0.0, 0.0), iterations=2000)
    project("sketch_creature.gridifs",
            [median("A", "creature.png", weight=2.0), median("B", "creature_balls.png", palette_index=1.0)],
            mode="flame", background=(0.0, 0.0, 0.0), iterations=2000)


if __name__ == "__main__":
    sketches()
    projects()
