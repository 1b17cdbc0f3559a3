"""hikari.Scene.render: the command line's images, as NumPy arrays, for every method."""

import re
import threading

import numpy as np
import pytest

import hikari
from conftest import scene_path

METHODS = [m["name"] for m in hikari.methods()]


def test_every_method_gives_the_command_lines_pixels(cli_render):
    scene = hikari.Scene.load(scene_path("teapot.json"))
    for method in METHODS:
        options = {"spp": 2} if method == "path" else {}
        image = scene.render(method, width=48, height=36, **options)
        assert image.dtype == np.float32 and image.shape == (36, 48, 3)
        assert image.flags["C_CONTIGUOUS"]
        expected = cli_render(scene_path("teapot.json"), "-m", method, "--width", "48",
                              "--height", "36", *(["--spp", "2"] if options else []))
        assert np.array_equal(image, expected), method


@pytest.mark.parametrize("aov,shape", [("depth", (24, 32)), ("id", (24, 32)),
                                       ("normal", (24, 32, 3)), ("diffuse", (24, 32, 3))])
def test_aovs_are_the_command_lines(cli_render, aov, shape):
    scene = hikari.Scene.default()
    image = scene.render("zbuffer", width=32, height=24, aov=aov)
    assert image.shape == shape
    expected = cli_render("-m", "zbuffer", "--width", "32", "--height", "24", "--aov", aov)
    if len(shape) == 2:
        expected = expected[..., 0]
    assert np.array_equal(image, expected.reshape(shape))


@pytest.mark.parametrize("method,aov", [("zbuffer", "overdraw"), ("depthsort", "overdraw"),
                                        ("depthsort", "paint-order")])
def test_counts_are_the_command_lines_numbers(cli_render, method, aov):
    scene = hikari.Scene.load(scene_path("teapot.json"))
    counts = scene.render(method, width=32, height=24, aov=aov)
    assert counts.shape == (24, 32)
    expected = cli_render(scene_path("teapot.json"), "-m", method, "--width", "32",
                          "--height", "24", "--aov", aov)
    assert np.array_equal(counts, expected[..., 0])
    assert counts.max() >= 2  # the teapot over the floor: more than one paint somewhere


def test_method_options_and_camera():
    scene = hikari.Scene.load(scene_path("teapot.json"))
    lit = scene.render("zbuffer", width=40, shadows="none")
    shadowed = scene.render("zbuffer", width=40, shadows="map")
    assert lit.shape == (30, 40, 3) and not np.array_equal(lit, shadowed)
    moved = scene.render("raytrace", width=40, camera={"eye": [3, 2, 3], "fov_y": 30})
    assert not np.array_equal(moved, scene.render("raytrace", width=40))
    lines = scene.render("wireframe", width=40, line_color=(0.1, 0.1, 0.2), line_width=2)
    assert lines.shape == (30, 40, 3)


def test_a_dict_scene_and_set():
    scene = hikari.Scene.from_dict({
        "camera": {"width": 32, "height": 32},
        "materials": {"clay": {"kd": [0.8, 0.3, 0.2], "ks": [0.5, 0.5, 0.5], "shininess": 40}},
        "lights": [{"type": "directional", "direction": [1, -1, -1], "intensity": [1, 1, 1]}],
        "objects": [{"type": "sphere", "center": [0, 0, -3], "radius": 1, "material": "clay"}],
    })
    before = scene.render()
    scene.set("materials.clay.shininess", 5)
    after = scene.render()
    assert before.shape == (32, 32, 3) and not np.array_equal(before, after)
    assert scene.info["spheres"] == 1


def test_bad_input_raises_input_error():
    scene = hikari.Scene.default()
    for call in [lambda: scene.render("raytracer"),
                 lambda: scene.render("zbuffer", shadows="sometimes"),
                 lambda: scene.render("zbuffer", spp=0),
                 lambda: scene.render("raytrace", interp="flat"),
                 lambda: scene.render(aov="colour"),
                 lambda: scene.render("path", aov="diffuse"),
                 lambda: scene.render(camera={"fov": 30}),
                 lambda: scene.render(width=0),
                 lambda: scene.set("materials.clay.shininess", -1),
                 lambda: hikari.Scene.load("no-such-scene.json"),
                 lambda: hikari.Scene.from_dict({"objects": 3})]:
        with pytest.raises(hikari.InputError):
            call()
    assert issubclass(hikari.InputError, ValueError)


def test_values_json_cannot_hold_are_input_errors_naming_their_path():
    scene = hikari.Scene.default()
    nan = float("nan")
    view = [b - a for a, b in zip(scene.camera["eye"], scene.camera["look_at"])]
    cases = [(lambda: hikari.Scene.from_dict({"camera": {"fov_y": nan}}), "camera.fov_y"),
             (lambda: hikari.Scene.from_dict({"camera": {"eye": {1, 2, 3}}}), "camera.eye"),
             (lambda: hikari.Scene.from_dict({"objects": [{"sphere": object()}]}),
              "objects[0].sphere"),
             (lambda: hikari.Scene.from_dict({1: "x"}), "key must be a string"),
             (lambda: scene.set("materials.0.shininess", float("inf")), "shininess"),
             (lambda: scene.render(camera={"eye": [nan, 0, 3]}), "camera.eye"),
             (lambda: scene.render(camera={"eye": [0, 0, 0], "look_at": [0, 0, 0]}),
              "same point"),
             (lambda: scene.render(camera={"up": view}), "parallel"),
             (lambda: scene.render(camera=5), "camera"),
             (lambda: scene.render("path", clamp=nan), "clamp")]
    for call, named in cases:
        with pytest.raises(hikari.InputError, match=re.escape(named)):
            call()
    for flag in [dict(width=True), dict(height=False), dict(threads=True)]:
        with pytest.raises(TypeError, match="not"):
            scene.render(**flag)
    cyclic = []
    cyclic.append(cyclic)
    with pytest.raises(hikari.InputError, match="nested deeper"):
        hikari.Scene.from_dict({"objects": cyclic})
    # NumPy values, the ones a notebook has at hand, are numbers and lists.
    moved = scene.render(width=16, camera={"eye": np.array([0.0, 0.5, 3.0])})
    assert moved.shape == (16, 16, 3)
    scene.set("camera.fov_y", np.float32(40.0))
    assert scene.camera["fov_y"] == 40.0


def test_threads_sharing_a_scene_take_turns():
    scene = hikari.Scene.load(scene_path("teapot.json"))
    expected = {m: scene.render(m, width=40, height=30, **({"spp": 2} if m == "path" else {}))
                for m in ["raytrace", "zbuffer", "path", "scanline"]}
    failures = []

    def work(method):
        try:
            for _ in range(4):
                image = scene.render(method, width=40, height=30,
                                     **({"spp": 2} if method == "path" else {}))
                if not np.array_equal(image, expected[method]):
                    failures.append(method + " differs")
                scene.set("materials.porcelain.shininess", 80)  # the same value: same image
                assert scene.camera["width"] > 0
        except Exception as e:  # pragma: no cover - reported below
            failures.append(repr(e))

    threads = [threading.Thread(target=work, args=(m,)) for m in expected]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert failures == []


def test_progress_callbacks_are_checked_and_their_errors_raised():
    scene = hikari.Scene.default()
    with pytest.raises(TypeError, match="progress"):
        scene.render(width=16, progress=5)

    def fails(fraction):
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        scene.render(width=16, progress=fails)

    def renders_again(fraction):
        scene.render(width=8)

    with pytest.raises(hikari.InputError, match="busy"):
        scene.render(width=16, progress=renders_again)
    fractions = []
    scene.render(width=8, progress=fractions.append)  # however fast, the end is reported
    assert fractions[-1] == 1.0
    assert scene.render(width=8).shape == (8, 8, 3)


def test_the_gil_is_released_and_progress_is_reported():
    scene = hikari.Scene.load(scene_path("teapot.json"))
    stop = threading.Event()
    counter = {"n": 0}

    def count():  # runs only while the render has let go of the GIL
        while not stop.is_set():
            counter["n"] += 1

    counting = threading.Thread(target=count)
    counting.start()
    fractions = []
    scene.render("path", width=64, height=48, spp=256, progress=fractions.append)
    stop.set()
    counting.join()
    assert counter["n"] > 1000
    assert fractions and all(0.0 <= f <= 1.0 for f in fractions)


def test_ctrl_c_stops_a_render():
    import os
    import signal
    import time

    scene = hikari.Scene.load(scene_path("teapot.json"))
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        scene.render("path", width=64, height=48, spp=1 << 20)
    assert time.monotonic() - start < 5.0
    # The session is still usable.
    assert scene.render(width=16).shape == (12, 16, 3)


def test_no_leak_over_many_renders():
    def resident_pages():
        with open("/proc/self/statm") as f:
            return int(f.read().split()[1])

    scene = hikari.Scene.default()
    for _ in range(50):
        scene.render(width=32, height=32)
    before = resident_pages()
    for _ in range(1000):
        scene.render(width=32, height=32)
    assert (resident_pages() - before) * 4096 < 16 << 20


def test_threads_do_not_change_the_image():
    scene = hikari.Scene.load(scene_path("teapot.json"))
    one = scene.render("zbuffer", width=48, threads=1)
    two = scene.render("zbuffer", width=48, threads=2)
    assert np.array_equal(one, two)


def test_the_scene_as_json_with_a_view_renders_that_view(tmp_path):
    scene = hikari.Scene.load(scene_path("teapot.json"), set={"materials.porcelain.shininess": 7})
    camera = {"eye": [1.8, 1.1, -2.0], "fov_y": 35}
    text = scene.to_json(width=40, height=30, camera=camera)
    (tmp_path / "view.json").write_text(text)
    copy = hikari.Scene.load(str(tmp_path / "view.json"))
    assert copy.camera["width"] == 40 and copy.camera["eye"] == pytest.approx((1.8, 1.1, -2.0))
    expected = scene.render("zbuffer", width=40, height=30, camera=camera)
    assert np.array_equal(copy.render("zbuffer"), expected)
