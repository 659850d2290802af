#!/usr/bin/env python3
"""A parameter sweep as a contact sheet: one project rendered at several values of one parameter,
laid out in a grid with each value written under its picture.

usage: contact_sheet.py [PROJECT] [PATH] [FROM] [TO] [-o sheet.png]
default: assets/twisted_functions.gridifs, the twist of its first function from -2 to 2.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.environ.get("GRIDIFS_PYTHON_DIR", os.path.join(ROOT, "build", "python")))
import gridifs  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("project", nargs="?", default=os.path.join(ROOT, "assets", "twisted_functions.gridifs"))
    parser.add_argument("path", nargs="?", default="functions[0].ops[0].k")
    parser.add_argument("low", nargs="?", type=float, default=-2.0)
    parser.add_argument("high", nargs="?", type=float, default=2.0)
    parser.add_argument("--columns", type=int, default=4)
    parser.add_argument("--rows", type=int, default=3)
    parser.add_argument("--size", type=int, default=240, help="each picture's width in pixels")
    parser.add_argument("--samples", default="2e6")
    parser.add_argument("-o", "--output", default="contact_sheet.png")
    args = parser.parse_args()

    project = gridifs.Project.load(args.project)
    count = args.columns * args.rows
    values = np.linspace(args.low, args.high, count)
    width, height = args.size, args.size * 3 // 4
    figure, axes = plt.subplots(args.rows, args.columns, figsize=(args.columns * 2.4, args.rows * 2.1), dpi=100)
    figure.patch.set_facecolor("black")
    for i, (value, ax) in enumerate(zip(values, axes.ravel())):
        project.set(args.path, float(value))
        image = project.render(width=width, height=height, samples=args.samples, seed=1)
        ax.imshow(image)
        ax.set_title(f"{args.path} = {value:.2f}", color="white", fontsize=7)
        ax.axis("off")
        print(f"{i + 1}/{count}: {args.path} = {value:.3f}", file=sys.stderr)
    figure.tight_layout()
    figure.savefig(args.output, facecolor="black")
    print(args.output)


if __name__ == "__main__":
    main()
