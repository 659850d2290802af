#!/usr/bin/env python3
"""Renders every .gridifs project of a folder to PNG (or EXR with --hdr), as `gridifs render`
would, with one progress line per project; projects GridIFS refuses are reported and skipped.

usage: batch_render.py FOLDER OUT_FOLDER [--width 640 --height 480 --samples 4e6]
"""
import argparse
import glob
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.environ.get("GRIDIFS_PYTHON_DIR", os.path.join(ROOT, "build", "python")))
import gridifs  # noqa: E402


def save_png(pixels, path):
    """Writes H x W x 4 uint8 pixels as PNG with matplotlib (Pillow underneath)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.image

    matplotlib.image.imsave(path, pixels)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folder")
    parser.add_argument("out")
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=480)
    parser.add_argument("--samples", default="4e6")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    projects = sorted(glob.glob(os.path.join(args.folder, "*.gridifs")))
    failed = 0
    for i, path in enumerate(projects):
        name = os.path.splitext(os.path.basename(path))[0]

        def progress(fraction):
            print(f"\r[{i + 1}/{len(projects)}] {name}: {100 * fraction:5.1f}%", end="", file=sys.stderr)

        try:
            pixels = gridifs.Project.load(path).render(
                width=args.width, height=args.height, samples=args.samples, progress=progress
            )
        except gridifs.Error as e:
            print(f"\n{name}: skipped: {e}", file=sys.stderr)
            failed += 1
            continue
        save_png(pixels, os.path.join(args.out, name + ".png"))
        print(file=sys.stderr)
    print(f"{len(projects) - failed} of {len(projects)} projects rendered into {args.out}")
    return 1 if failed == len(projects) and projects else 0


if __name__ == "__main__":
    sys.exit(main())
