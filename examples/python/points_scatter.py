#!/usr/bin/env python3
"""A project's attractor as points in numpy, shown as a matplotlib 3D scatter in their own colours.

usage: points_scatter.py [PROJECT] [-n 20000] [-o scatter.png]   (no -o: opens a window)
"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.environ.get("GRIDIFS_PYTHON_DIR", os.path.join(ROOT, "build", "python")))
import gridifs  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("project", nargs="?", default=os.path.join(ROOT, "assets", "sierpinski_tetrahedron.gridifs"))
    parser.add_argument("-n", "--points", type=int, default=20000)
    parser.add_argument("-o", "--output")
    args = parser.parse_args()

    import matplotlib

    if args.output:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    positions, colours = gridifs.Project.load(args.project).points(args.points, seed=1)
    print(f"{len(positions)} points, bounds {positions.min(axis=0)} .. {positions.max(axis=0)}", file=sys.stderr)
    figure = plt.figure(figsize=(6, 6))
    ax = figure.add_subplot(projection="3d")
    ax.scatter(positions[:, 0], positions[:, 1], positions[:, 2], c=colours, s=0.5, depthshade=False)
    ax.set_xlim(-1, 1), ax.set_ylim(-1, 1), ax.set_zlim(-1, 1)
    ax.set_box_aspect((1, 1, 1))
    ax.set_title(os.path.basename(args.project))
    if args.output:
        figure.savefig(args.output, dpi=120)
        print(args.output)
    else:
        plt.show()


if __name__ == "__main__":
    main()
