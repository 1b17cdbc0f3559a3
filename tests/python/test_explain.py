"""hikari.explain: the same steps `hikari explain` prints, as text and as nested data."""

import subprocess

import pytest

import hikari
from conftest import CLI, scene_path


def cli_explain(*args):
    return subprocess.run([CLI, "explain", *args], check=True, capture_output=True,
                          text=True).stdout


@pytest.mark.parametrize("method, step, cli_step", [
    ("zbuffer", {"pixel": (40, 30)}, ["--pixel", "40,30"]),
    ("raytrace", {"pixel": (33, 20)}, ["--pixel", "33,20"]),
    ("scanline", {"row": 30}, ["--row", "30"]),
    ("depthsort", {}, []),
])
def test_the_text_is_the_command_lines(method, step, cli_step):
    scene = hikari.Scene.load(scene_path("teapot.json"))
    explanation = hikari.explain(scene, method, width=80, height=60, **step)
    expected = cli_explain(scene_path("teapot.json"), "-m", method, "--width", "80",
                           "--height", "60", *cli_step)
    assert explanation + "\n" == expected or explanation == expected
    assert isinstance(explanation, str)


def test_steps_nest_as_the_ray_tree_does():
    scene = hikari.Scene.default()
    width = scene.camera["width"]
    height = scene.camera["height"]
    explanation = hikari.explain(scene, "raytrace", pixel=(width // 2, height // 2))
    assert explanation.title.startswith("Ray tracing (Alg 4.3")
    camera_ray = next(s for s in explanation.steps if s["text"].startswith("#0 camera ray"))
    children = [s["text"] for s in camera_ray["steps"]]
    assert any(t.startswith("hits sphere") for t in children)
    assert any(t.startswith("shadow ray to light 0") for t in children)
    # Every line of the text is one step, none lost or repeated.
    def count(steps):
        return sum(1 + count(s["steps"]) for s in steps)
    lines = [l for l in explanation.splitlines()[1:] if l.strip()]
    assert count(explanation.steps) == len(lines)


def test_method_options_change_what_is_explained():
    scene = hikari.Scene.load(scene_path("whitted.json"))
    # The centre pixel sees the glass sphere: its mirror and refracted rays are children of the
    # camera ray's step, and max_depth=1 keeps the camera ray alone.
    deep = hikari.explain(scene, "raytrace", pixel=(320, 240), max_depth=5)
    shallow = hikari.explain(scene, "raytrace", pixel=(320, 240), max_depth=1)
    camera_ray = next(s for s in deep.steps if s["text"].startswith("#0 camera ray"))
    spawned = [s["text"] for s in camera_ray["steps"] if s["text"].startswith("#")]
    assert any("mirror ray of #0" in t for t in spawned)
    assert any("refracted ray of #0" in t for t in spawned)
    assert "mirror ray of" not in shallow and "refracted ray of" not in shallow


@pytest.mark.parametrize("arguments, message", [
    ({"method": "zbuffer"}, "needs --pixel"),
    ({"method": "scanline"}, "needs --row"),
    ({"method": "zbuffer", "pixel": (100000, 1)}, "outside"),
    ({"method": "zbuffer", "pixel": "ab"}, "pixel: expected 2 whole numbers"),
    ({"method": "zbuffer", "pixel": (1, 2.5)}, "pixel: expected 2 whole numbers"),
    ({"method": "wireframe"}, "no explain view"),
    ({"method": "nonsense"}, "nonsense"),
    ({"method": "raytrace", "pixel": (1, 1), "max_depth": -3}, "max"),
])
def test_bad_requests_raise_input_error(arguments, message):
    with pytest.raises(hikari.InputError, match=message):
        hikari.explain(hikari.Scene.default(), **arguments)
