"""The memory limit from Python (issue 41): hikari.set_max_memory and the max_memory keyword mean
what --max-memory means, and a refusal is a hikari.InputError, never an abort."""

import math

import pytest

import hikari

from conftest import scene_path

# Between a mirror, a glass pane and a second mirror: the ray tree doubles every two
# levels.
RAY_TREE = {
    "camera": {"eye": [0, 0, 0], "look_at": [0, 0, -1], "width": 32, "height": 24},
    "materials": {"mirror": {"kd": [0, 0, 0], "reflectivity": 0.9},
                  "glass": {"kd": [0, 0, 0], "reflectivity": 0.5, "transparency": 0.5,
                            "ior": 1.5}},
    "lights": [{"type": "point", "position": [0, 0, 0], "intensity": [1, 1, 1]}],
    "objects": [
        {"type": "plane", "point": [0, 0, -1], "normal": [0, 0, 1], "material": "mirror"},
        {"type": "plane", "point": [0, 0, 0.5], "normal": [0, 0, 1], "material": "glass"},
        {"type": "plane", "point": [0, 0, 2], "normal": [0, 0, -1], "material": "mirror"}],
}


@pytest.fixture
def limit_restored():
    before = hikari.max_memory()
    yield
    hikari.set_max_memory(before)


def test_an_image_over_the_limit_is_refused_before_it_is_made(limit_restored):
    scene = hikari.Scene.default()
    before = hikari.max_memory()
    with pytest.raises(hikari.InputError, match=r"a 8000x8000 image needs about .*max_memory="):
        scene.render("zbuffer", width=8000, height=8000, max_memory=0.25)
    assert hikari.max_memory() == before  # the keyword holds for the one call
    assert scene.render("zbuffer", width=32, height=24, max_memory=0.25).shape == (24, 32, 3)


def test_the_ray_tree_counts_against_the_limit(limit_restored):
    scene = hikari.Scene.from_dict(RAY_TREE)
    with pytest.raises(hikari.InputError, match="the ray tree"):
        scene.render("raytrace", max_depth=48, max_memory=0.25)
    with pytest.raises(hikari.InputError, match="65536 rays per camera ray"):
        hikari.explain(scene, "raytrace", pixel=(0, 0), width=1, height=1, max_depth=48)
    assert scene.render("raytrace", max_depth=12, max_memory=0.25).shape == (24, 32, 3)


def test_the_ray_tree_listing_counts_against_the_limit(limit_restored):
    # Under the breadth cap, a 32x24 mirror/glass scene's tree at depth 30 lists 65534 rays
    # (40 MB of text): refused under 0.05 GiB, explained under 0.25.
    scene = hikari.Scene.from_dict(RAY_TREE)
    with pytest.raises(hikari.InputError, match="listing the ray tree .*max_memory="):
        hikari.explain(scene, "raytrace", pixel=(16, 12), max_depth=30, max_memory=0.05)
    assert "#65533" in str(hikari.explain(scene, "raytrace", pixel=(16, 12), max_depth=30,
                                          max_memory=0.25))


def test_set_max_memory_holds_for_every_later_call(limit_restored):
    hikari.set_max_memory(1 / 1024)
    assert math.isclose(hikari.max_memory(), 1 / 1024)
    with pytest.raises(hikari.InputError, match="max_memory="):
        hikari.Scene.load(scene_path("models/teapot.obj"))
    with pytest.raises(hikari.InputError, match="max_memory="):
        hikari.Scene.default().render("raytrace", width=640, height=480)


@pytest.mark.parametrize("gib", [0, -1, float("nan"), float("inf")])
def test_the_limit_must_be_a_positive_number_of_gib(limit_restored, gib):
    before = hikari.max_memory()
    with pytest.raises(hikari.InputError, match="max_memory: expected a positive number of GiB"):
        hikari.set_max_memory(gib)
    assert hikari.max_memory() == before
