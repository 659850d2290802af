#!/usr/bin/env python3
"""p.render() in the Python module against the `gridifs render` process on the same job.

usage: tests/bench/bench_python.py [BUILD_DIR]   (default: build)   BENCH_REPETITIONS=N (default 3)

For each job it prints wall and CPU seconds (user + system) of both, best of N runs, and the
module's overhead: how much longer p.render() takes than the whole command (process start, image
library and PNG writing included), as a fraction of the command's time; a negative overhead means
the module is faster. Peak memory of the process is printed too. Report with the CPU model
(lscpu), which it prints first.
"""
import os
import resource
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else os.path.join(ROOT, "build")
REPETITIONS = int(os.environ.get("BENCH_REPETITIONS", "3"))
sys.path.insert(0, os.path.join(BUILD, "python"))
import gridifs  # noqa: E402

JOBS = [
    # Nearly no chaos game: what a call costs beyond its samples (set-up, develop, the array).
    ("canonical 1024x768, 1e4 samples", os.path.join(ROOT, "assets", "twisted_functions.gridifs"),
     dict(width=1024, height=768, samples="1e4", seed=1, device="cpu")),
    ("canonical 1024x768, 2e7 samples", os.path.join(ROOT, "assets", "twisted_functions.gridifs"),
     dict(width=1024, height=768, samples="2e7", seed=1, device="cpu")),
    ("canonical 1024x768, 1e8 samples", os.path.join(ROOT, "assets", "twisted_functions.gridifs"),
     dict(width=1024, height=768, samples="1e8", seed=1, device="cpu")),
    ("flame 1024x768, 2e7 samples", os.path.join(ROOT, "assets", "flames", "swirl_spherical.gridifs"),
     dict(width=1024, height=768, samples="2e7", seed=1, mode="flame", device="cpu")),
]


def cpu_model():
    """lscpu's model name, with /proc/cpuinfo's family and model numbers: a hypervisor may show
    every generation of a vendor's server CPUs under one name, and they differ in speed."""
    name = "unknown CPU"
    for line in subprocess.run(["lscpu"], capture_output=True, text=True).stdout.splitlines():
        if line.startswith("Model name"):
            name = line.split(":", 1)[1].strip()
            break
    info = {}
    with open("/proc/cpuinfo") as cpuinfo:
        for line in cpuinfo:
            key, _, value = line.partition(":")
            info.setdefault(key.strip(), value.strip())
    if "cpu family" in info and "model" in info:
        name += " (family %s model %s)" % (info["cpu family"], info["model"])
    return name


def time_module(path, options):
    project = gridifs.Project.load(path)
    best = None
    for _ in range(REPETITIONS):
        before = resource.getrusage(resource.RUSAGE_SELF)
        start = time.perf_counter()
        project.render(**options)
        wall = time.perf_counter() - start
        after = resource.getrusage(resource.RUSAGE_SELF)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        if best is None or wall < best[0]:
            best = (wall, cpu)
    return best


def time_process(path, options, out):
    flags = []
    for key, value in options.items():
        flags += ["--" + key.replace("_", "-"), str(value)]
    best = None
    for _ in range(REPETITIONS):
        start = time.perf_counter()
        child = subprocess.Popen([os.path.join(BUILD, "app", "gridifs"), "render", path, "-o", out, "--quiet", *flags])
        _, status, usage = os.wait4(child.pid, 0)
        wall = time.perf_counter() - start
        if status != 0:
            sys.exit(f"gridifs render failed on {path}")
        cpu = usage.ru_utime + usage.ru_stime
        if best is None or wall < best[0]:
            best = (wall, cpu, usage.ru_maxrss / 1024)
    return best


def main():
    print(f"CPU: {cpu_model()}, {os.cpu_count()} cores; best of {REPETITIONS}")
    print(f"{'job':34} {'module wall':>11} {'cpu':>6} {'process wall':>12} {'cpu':>6} {'peak MB':>7} "
          f"{'overhead wall':>13} {'cpu':>6}")
    with tempfile.TemporaryDirectory() as folder:
        out = os.path.join(folder, "out.png")
        for name, path, options in JOBS:
            process = time_process(path, options, out)
            module = time_module(path, options)
            print(f"{name:34} {module[0]:10.3f}s {module[1]:5.2f}s {process[0]:11.3f}s {process[1]:5.2f}s "
                  f"{process[2]:7.0f} {100 * (module[0] / process[0] - 1):+12.1f}% "
                  f"{100 * (module[1] / process[1] - 1):+5.1f}%")


if __name__ == "__main__":
    main()
