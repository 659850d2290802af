"""gridifs as a Python module: renders equal to the command line's files, parameters through their
paths with the file reader's checks, refusals that change nothing, threads, progress and Ctrl+C."""
import _thread
import glob
import json
import os
import re
import threading
import time

import numpy as np
import pytest

from conftest import EXE, asset, gridifs, read_image, run_cli

# Small, fixed jobs: the same options go to `gridifs render` and to render().
JOB = dict(width=48, height=36, samples=200000, seed=7, threads=2)

# Every display mode, and the projects that need their own path through the renderer: a median
# project (set iteration) and an animated one whose tracks are evaluated at the asked time.
CASES = [
    ("zbuffer", asset("twisted_functions.gridifs"), {}),
    ("flame", asset("flames", "swirl_spherical.gridifs"), {"mode": "flame"}),
    ("flame-options", asset("twisted_functions.gridifs"), {"mode": "flame", "hue": 0.25, "supersample": 2}),
    ("shaded", asset("shaded_tetrahedron.gridifs"), {"mode": "shaded"}),
    ("volume", asset("volumes", "cloud_creature.gridifs"), {"mode": "volume", "resolution": 32}),
    ("median", asset("volumes", "rotated_median.gridifs"), {}),
    ("animated", asset("animation", "breathing_twist.gridifs"), {"time": 0.75}),
    ("motion-blur", asset("animation", "breathing_twist.gridifs"), {"time": 0.5, "motion_blur": 3}),
]


def cli_flags(options):
    flags = []
    for key, value in options.items():
        flags += ["--" + key.replace("_", "-"), str(value)]
    return flags


@pytest.mark.parametrize("name,path,options", CASES, ids=[c[0] for c in CASES])
def test_render_equals_the_command_line_png_and_exr(tmp, name, path, options):
    job = dict(JOB)
    if options.get("mode") == "volume":
        job.pop("samples")  # the volume's own sample count
    project = gridifs.Project.load(path)
    for ext, hdr in (("png", False), ("exr", True)):
        out = tmp / f"{name}.{ext}"
        code, err = run_cli("render", path, "-o", out, "--quiet", *cli_flags(job), *cli_flags(options))
        assert code == 0, err
        written = read_image(out)
        pixels = project.render(**job, **options, hdr=hdr)
        assert pixels.shape == (36, 48, 4)
        channels = written.shape[2]
        if hdr:
            assert pixels.dtype == np.float32
            np.testing.assert_allclose(pixels[..., :min(4, channels)], written[..., :4], rtol=1e-6, atol=1e-8)
        else:
            assert pixels.dtype == np.uint8
            # RGB files: alpha 255; RGBA files (the volume mode): the file's alpha.
            assert np.array_equal(pixels[..., :channels], written), f"{name}: render() differs from the PNG"
            if channels == 3:
                assert (pixels[..., 3] == 255).all()
        assert pixels.any(), f"{name}: an empty picture proves nothing"


def test_transparent_flame_keeps_the_files_alpha(tmp):
    path = asset("flames", "swirl_spherical.gridifs")
    out = tmp / "t.png"
    code, err = run_cli("render", path, "-o", out, "--quiet", "--mode", "flame", "--transparent", *cli_flags(JOB))
    assert code == 0, err
    written = read_image(out)
    pixels = gridifs.Project.load(path).render(**JOB, mode="flame", transparent=True)
    assert written.shape[2] == 4
    assert np.array_equal(pixels, written)
    assert (pixels[..., 3] < 255).any()


def example_projects():
    found = sorted(glob.glob(asset("*.gridifs")) + glob.glob(asset("*", "*.gridifs")))
    assert len(found) > 20
    return found


def perturbed(value):
    return value * 0.5 if value != 0 else 0.25


def test_every_parameter_path_of_every_example_round_trips():
    checked = 0
    for path in example_projects():
        p = gridifs.Project.load(path)
        paths = p.paths()
        assert paths, path
        # The paths are a function of the project's content: listed again only when it changed
        # (a project of thousands of numbers would otherwise list them thousands of times).
        listed_for, present = p.to_json(), set(paths)
        for name in paths:
            if name not in present:
                continue  # gone with an earlier value (a shutter without motion blur)
            value = p.get(name)
            p.set(name, value)  # the same value
            assert p.get(name) == value
            # Setting one number of an animated project also puts every keyed number at its
            # track's value (the modeller's rule), so compare with the project just before.
            original = p.to_json()
            if original != listed_for:
                listed_for, present = original, set(p.paths())
            try:
                p.set(name, perturbed(value))
            except gridifs.Error as e:
                # Refused (a range, a whole number, a rule between fields): the project is as it was.
                # "FILE: the JSON path at fault: what is wrong." (a rule may name another field)
                assert re.fullmatch(r".+\.gridifs: [a-z_]+[a-z_\[\]0-9.]*: .+\.", str(e)), str(e)
                assert p.to_json() == original, f"{path}: a refused {name} changed the project"
                continue
            try:
                got = p.get(name)
            except gridifs.Error:
                got = None  # a number written only while it differs from its default may go
            if got is not None:
                assert got == pytest.approx(perturbed(value), abs=0.51), f"{path}: {name}"
            assert p.undo()
            assert p.to_json() == original, f"{path}: undo after {name} left a difference"
            checked += 1
    assert checked > 500


def test_set_is_one_undo_step_and_redo_brings_it_back():
    p = gridifs.Project.load(asset("twisted_functions.gridifs"))
    before = p.to_json()
    p.set("functions[0].weight", 0.25)
    p.set("camera.yaw", 45)
    after = p.to_json()
    assert p.undo() and p.undo()
    assert p.to_json() == before
    assert not p.undo()
    assert p.redo() and p.redo()
    assert p.to_json() == after


def test_setting_a_keyframed_number_keys_it_at_the_projects_time():
    p = gridifs.Project.load(asset("animation", "breathing_twist.gridifs"))
    data = json.loads(p.to_json())
    keyed = sorted(data["tracks"])[0]
    value = p.get(keyed)
    p.set(keyed, value * 0.9)
    tracks = json.loads(p.to_json())["tracks"]
    times = [k["t"] for k in tracks[keyed]["keys"]] if "keys" in tracks[keyed] else None
    assert tracks != data["tracks"], "the track should hold the new key"
    assert times is None or data.get("time", 0.0) in times


def file_reader_sentence(tmp, edit):
    """The sentence `gridifs info` prints for twisted_functions.gridifs changed by `edit`."""
    data = json.load(open(asset("twisted_functions.gridifs")))
    edit(data)
    bad = tmp / "bad.gridifs"
    bad.write_text(json.dumps(data))
    code, err = run_cli("info", bad)
    assert code == 2
    return err.strip().removeprefix("gridifs: ").split(": ", 1)[1]


@pytest.mark.parametrize(
    "path,value,edit",
    [
        ("functions[0].weight", -1.0, lambda d: d["functions"][0].__setitem__("weight", -1.0)),
        ("render.width", 0, lambda d: d["render"].__setitem__("width", 0)),
        ("render.width", 64.5, lambda d: d["render"].__setitem__("width", 64.5)),
        ("functions[1].ops[0].k", 1e300, lambda d: d["functions"][1]["ops"][0].__setitem__("k", 1e300)),
    ],
)
def test_a_refused_value_has_the_file_readers_sentence_and_changes_nothing(tmp, path, value, edit):
    p = gridifs.Project.load(asset("twisted_functions.gridifs"))
    before = p.to_json()
    with pytest.raises(gridifs.Error) as refused:
        p.set(path, value)
    assert p.to_json() == before
    expected = file_reader_sentence(tmp, edit)
    assert str(refused.value).split(": ", 1)[1] == expected


@pytest.mark.parametrize(
    "call,words",
    [
        (lambda p: p.set("functions[9].weight", 1), "names nothing this project holds"),
        (lambda p: p.set("functions[0].name", 1), "is not a number"),
        (lambda p: p.set("functions[0]..weight", 1), "is not a parameter path"),
        (lambda p: p.set("functions[0].weight", float("nan")), "functions[0].weight"),
        (lambda p: p.get("camera.nothing"), "names nothing"),
        (lambda p: p.render(width=0, height=36, samples=1000), "at least 1×1 pixel"),
        (lambda p: p.render(samples="lots"), "samples"),
        (lambda p: p.render(mode="sideways"), "--mode must be"),
        (lambda p: p.render(colour="red"), "render() has no option colour"),
        (lambda p: p.render(width="wide"), "width must be an int"),
        (lambda p: p.render(resolution=32), "resolution applies to mode='volume'"),
        (lambda p: p.render(hue=0.5), "apply to --mode flame only"),
        (lambda p: p.points(0), "n must be between"),
        (lambda p: p.volume(3), "resolution must be between"),
        (lambda p: p.mesh(99), "depth"),
    ],
)
def test_every_refusal_is_a_gridifs_error_and_leaves_the_project(call, words):
    p = gridifs.Project.load(asset("twisted_functions.gridifs"))
    before = p.to_json()
    with pytest.raises(gridifs.Error) as refused:
        call(p)
    assert words in str(refused.value)
    assert str(refused.value).endswith(".")
    assert p.to_json() == before


def test_bad_files_and_json_are_errors_with_the_cli_sentence(tmp):
    bad = tmp / "broken.gridifs"
    bad.write_text('{"version": 1, "functions": [')
    code, err = run_cli("info", bad)
    with pytest.raises(gridifs.Error) as refused:
        gridifs.Project.load(str(bad))
    assert "gridifs: " + str(refused.value) == err.strip()
    with pytest.raises(gridifs.Error):
        gridifs.Project.from_json('{"functions": 3}')
    with pytest.raises(gridifs.Error) as missing:
        gridifs.Project.load(str(tmp / "nothing.gridifs"))
    assert "cannot read" in str(missing.value)


def test_progress_lies_in_0_1_and_ends_at_1():
    seen = []
    p = gridifs.Project.load(asset("twisted_functions.gridifs"))
    p.render(width=64, height=48, samples=3_000_000, seed=1, threads=2, progress=seen.append)
    assert seen, "progress was never called"
    assert all(0.0 <= f <= 1.0 for f in seen)
    assert seen == sorted(seen)
    assert seen[-1] == 1.0
    seen.clear()
    p.points(200_000, seed=3, progress=seen.append)
    assert seen and all(0.0 <= f <= 1.0 for f in seen)


def test_python_threads_run_during_a_render():
    p = gridifs.Project.load(asset("twisted_functions.gridifs"))
    ticks = 0
    stop = threading.Event()

    def count():
        nonlocal ticks
        while not stop.is_set():
            ticks += 1
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    start = time.monotonic()
    p.render(width=256, height=256, samples=100_000_000, seed=1, threads=1)
    elapsed = time.monotonic() - start
    stop.set()
    counter.join()
    assert elapsed > 0.2, "the render was too short to tell"
    # With the GIL held for the whole render the counter would not have run at all.
    assert ticks > 20 * elapsed


def test_separate_projects_render_at_once_from_threads_as_they_do_alone():
    paths = [asset("twisted_functions.gridifs"), asset("tapered_functions.gridifs"), asset("bended_functions.gridifs")]
    alone = [gridifs.Project.load(p).render(**JOB) for p in paths]
    together = [None] * len(paths)

    def work(i):
        together[i] = gridifs.Project.load(paths[i]).render(**JOB)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(len(paths))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for a, b in zip(alone, together):
        assert np.array_equal(a, b)


def test_an_exception_in_progress_stops_the_render_and_is_raised():
    p = gridifs.Project.load(asset("twisted_functions.gridifs"))

    class Enough(Exception):
        pass

    def stop(fraction):
        raise Enough()

    start = time.monotonic()
    with pytest.raises(Enough):
        p.render(width=256, height=256, samples=500_000_000, threads=2, progress=stop)
    assert time.monotonic() - start < 10


def test_ctrl_c_stops_a_long_render():
    p = gridifs.Project.load(asset("twisted_functions.gridifs"))
    timer = threading.Timer(0.5, _thread.interrupt_main)
    timer.start()
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        p.render(width=256, height=256, samples=2_000_000_000, threads=2)
    timer.join()
    assert time.monotonic() - start < 10


def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode()
    count = int(header.split("element vertex ")[1].split()[0])
    record = np.dtype([("xyz", "<f4", 3), ("rgb", "u1", 3)])
    return np.frombuffer(data[end:], dtype=record, count=count)


def test_points_are_the_points_export_points_writes(tmp):
    path = asset("twisted_functions.gridifs")
    out = tmp / "p.ply"
    code, err = run_cli("export-points", path, "-o", out, "--samples", 50000, "--seed", 5, "--threads", 2,
                        "--device", "cpu", "--quiet")
    assert code == 0, err
    written = read_ply(out)
    xyz, rgb = gridifs.Project.load(path).points(50000, seed=5, threads=2)
    # Points that leave the cube or turn non-finite are not exported, by either.
    assert 49000 < len(written) <= 50000
    assert xyz.shape == (len(written), 3) and xyz.dtype == np.float32 and rgb.dtype == np.float32
    assert np.array_equal(xyz, written["xyz"])
    assert np.abs(rgb * 255 - written["rgb"]).max() <= 1.0
    assert (rgb >= 0).all() and (rgb <= 1).all()


def test_volume_and_mesh_come_back_as_arrays():
    p = gridifs.Project.load(asset("sierpinski_tetrahedron.gridifs"))
    v = p.volume(32, samples=200000, seed=1)
    assert v.shape == (32, 32, 32) and v.dtype == np.float32
    assert v.max() == 1.0 and v.min() == 0.0
    vertices, faces = p.mesh(2)
    assert vertices.dtype == np.float32 and vertices.shape[1] == 3
    assert faces.dtype == np.int32 and faces.shape[1] == 3
    assert faces.max() < len(vertices)
    # F^2 of a cube under 4 maps: 16 copies of 6 quads, 2 triangles each.
    assert len(faces) == 16 * 6 * 2


def test_import_flame_renders_like_the_imported_file(tmp):
    flame = asset("flames", "swirl_spherical.flame")
    p = gridifs.import_flame(flame, palette_file=str(tmp / "swirl.palette.json"))
    assert "functions[0].weight" in p.paths()
    out = tmp / "swirl.gridifs"
    code, err = run_cli("import-flame", flame, "-o", out)
    assert code == 0, err
    assert json.loads(p.to_json()) == json.loads(out.read_text())
    image = p.render(**JOB)
    assert image.any()
    with pytest.raises(gridifs.Error):
        gridifs.import_flame(str(tmp / "none.flame"))


def test_save_writes_what_to_json_says_and_loads_back(tmp):
    p = gridifs.Project.load(asset("twisted_functions.gridifs"))
    p.set("functions[2].weight", 0.5)
    out = tmp / "saved.gridifs"
    p.save(str(out))
    assert out.read_text() == p.to_json()
    again = gridifs.Project.load(str(out))
    assert again.get("functions[2].weight") == 0.5
    code, err = run_cli("info", out)
    assert code == 0, err


def test_help_reads_like_a_manual():
    text = gridifs.Project.__doc__ + gridifs.Project.render.__doc__ + gridifs.Project.set.__doc__
    assert "gridifs render" in text and "undo" in text
    assert gridifs.Error.__doc__
