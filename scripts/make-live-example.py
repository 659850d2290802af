#!/usr/bin/env python3
"""Makes assets/live/: a twisted tetrahedron that dances to a short synthesized groove.
beat.wav (8 s, 22.05 kHz mono): a kick on every beat at 120 bpm (the 20-200 Hz band), a chord
that swells over two bars (200-2000 Hz) and off-beat hats (2-10 kHz). The bindings twist the
functions with the kick, turn the camera with the chord and scale the first function's weight
with the hats. Run after a build (it saves through build/python): scripts/make-live-example.py"""
import json
import os
import sys
import wave

import numpy as np

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "assets")
OUT = os.path.join(HERE, "live")
RATE, SECONDS = 22050, 8.0

t = np.arange(int(RATE * SECONDS)) / RATE
beat = 0.5  # seconds
phase = t % beat
kick = np.sin(2 * np.pi * (50 + 90 * np.exp(-phase * 30)) * phase) * np.exp(-phase * 9)
chord = sum(np.sin(2 * np.pi * f * t) for f in (220.0, 277.2, 329.6)) / 3 * (0.5 - 0.5 * np.cos(2 * np.pi * t / 4.0))
off = (t + beat / 2) % beat
hats = np.random.default_rng(7).normal(0, 1, len(t)) * np.exp(-off * 60)
hats = np.convolve(hats, [1, -1], mode="same")  # a first difference: mostly high frequencies
sound = 0.55 * kick + 0.3 * chord + 0.08 * hats
sound = np.clip(sound / np.abs(sound).max() * 0.9, -1, 1)
with wave.open(os.path.join(OUT, "beat.wav"), "wb") as w:
    w.setnchannels(1)
    w.setsampwidth(2)
    w.setframerate(RATE)
    w.writeframes((sound * 32767).astype("<i2").tobytes())

project = json.load(open(os.path.join(HERE, "twisted_functions.gridifs")))
project["render"]["samples"] = 2000000
project["render"]["width"], project["render"]["height"] = 640, 480
project["animation"] = {"start": 0, "end": SECONDS, "fps": 24, "loop": True}
project["audio"] = {"file": "beat.wav", "bands": [[20, 200], [200, 2000], [2000, 10000]]}
project["bindings"] = [
    {"path": "functions[%d].ops[0].k" % i, "source": "audio:0", "min": 0.6 * s, "max": 1.8 * s, "smooth": 0.06}
    for i, s in enumerate((1, -1, 1, -1))
] + [
    {"path": "camera.yaw", "source": "audio:1", "min": 10, "max": 70, "smooth": 0.3},
    {"path": "functions[0].weight", "source": "audio:2", "min": 1, "max": 2.5, "smooth": 0.05},
]
target = os.path.join(OUT, "dancing_twist.gridifs")
with open(target, "w") as f:
    json.dump(project, f, indent=2)
    f.write("\n")
# Saved again by GridIFS itself, so the shipped file is in the form the modeller writes.
sys.path.insert(0, os.path.join(HERE, "..", "build", "python"))
import gridifs  # noqa: E402

gridifs.Project.load(target).save(target)
if os.path.exists(target + "~"):
    os.remove(target + "~")
