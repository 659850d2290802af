"""The python tier: the module from build/python against the gridifs executable of the same build.

GRIDIFS_PYTHON_DIR and GRIDIFS_EXE (set by ctest) name the build's module folder and executable;
run by hand, they default to build/ under the source tree.
"""
import os
import re
import subprocess
import sys

import numpy as np
import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PYTHON_DIR = os.environ.get("GRIDIFS_PYTHON_DIR", os.path.join(ROOT, "build", "python"))
EXE = os.environ.get("GRIDIFS_EXE", os.path.join(ROOT, "build", "app", "gridifs"))
sys.path.insert(0, PYTHON_DIR)

import gridifs  # noqa: E402  (after the path above)


def asset(*parts):
    return os.path.join(ROOT, "assets", *parts)


def run_cli(*args):
    """Runs gridifs with `args`; returns (exit code, stderr)."""
    done = subprocess.run([EXE, *map(str, args)], capture_output=True, text=True)
    return done.returncode, done.stderr


_PIXEL = re.compile(r"Pixel \((\d+), (\d+)\): ([^(\n]*)")


def read_image(path):
    """The pixels an image file stores, as oiiotool reads them: H x W x C, uint8 for 8-bit files
    (the stored integers, straight colour where there is alpha, as PNG keeps it), float32
    otherwise."""
    text = subprocess.run(["oiiotool", "--iconfig", "oiio:UnassociatedAlpha", "1", "--dumpdata", str(path)],
                          capture_output=True, text=True, check=True).stdout
    header = text.splitlines()[0]
    size = re.search(r"(\d+) x\s+(\d+), (\d+) channel, (\w+)", header)
    width, height, channels, kind = int(size[1]), int(size[2]), int(size[3]), size[4]
    dtype = np.uint8 if kind == "uint8" else np.float32
    image = np.zeros((height, width, channels), dtype=dtype)
    for x, y, values in _PIXEL.findall(text):
        image[int(y), int(x)] = np.array(values.split(), dtype=np.float64).astype(dtype)
    return image


@pytest.fixture
def tmp(tmp_path):
    return tmp_path
