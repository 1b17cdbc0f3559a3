"""docs/assignment.md's expected values: each row of its table agrees with the lecture's formulas
worked out here from scenes/assignment.json, and with the pixel hikari renders there."""

import json
import math
import os
import re
import subprocess

import numpy as np

from conftest import CLI, SOURCE, scene_path


def lecture(scene, x, y):
    """D, t, cos α, cos γ and I at pixel (x, y) of the assignment, by the lecture's formulas."""
    cam = scene["camera"]
    w, h = cam["width"], cam["height"]
    half = math.tan(math.radians(cam["fov_y"]) / 2)
    # The assignment's camera: at the origin, looking along -z with y up.
    assert cam["eye"] == [0, 0, 0] and cam["look_at"] == [0, 0, -1] and cam["up"] == [0, 1, 0]
    xs = (2 * (x + 0.5) / w - 1) * half * w / h
    ys = (1 - 2 * (y + 0.5) / h) * half
    e = np.array([xs, ys, -1.0])
    e /= np.linalg.norm(e)
    sphere = scene["objects"][0]
    s, r = np.array(sphere["center"], float), sphere["radius"]
    eye = np.zeros(3)
    a, b, c = e @ e, 2 * e @ (eye - s), (eye - s) @ (eye - s) - r * r
    d = b * b - 4 * a * c
    if d < 0:
        return d, None, None, None, np.array(scene["background"], float)
    t = (-b - math.sqrt(d)) / (2 * a)
    n_vec = (eye + t * e - s) / r
    light = scene["lights"][0]
    l_vec = np.array(light["direction"], float)
    l_vec /= np.linalg.norm(l_vec)
    i0 = np.array(light["intensity"], float)
    m = scene["materials"][sphere["material"]]
    cos_a = -l_vec @ n_vec
    r_vec = l_vec + 2 * cos_a * n_vec
    cos_g = r_vec @ -e
    value = np.array(scene["ambient"], float) * np.array(m["ka"], float)
    if cos_a > 0:
        value = value + i0 * (np.array(m["kd"]) * cos_a + np.array(m["ks"]) * max(cos_g, 0) ** m["shininess"])
    return d, t, cos_a, cos_g, value


def srgb8(v):
    v = min(max(v, 0.0), 1.0)
    return round(255 * (12.92 * v if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055))


def table_rows():
    text = open(os.path.join(SOURCE, "docs", "assignment.md"), encoding="utf-8").read()
    rows = re.findall(r"^\| \((\d+), (\d+)\) \|(.*)$", text, re.M)
    assert len(rows) >= 4, "docs/assignment.md has its table of expected values"
    for x, y, rest in rows:
        cells = [c.strip().replace("−", "-") for c in rest.split("|")[:-1]]
        yield int(x), int(y), cells


def test_expected_values_are_the_lectures_formulas():
    scene = json.load(open(scene_path("assignment.json")))
    for x, y, cells in table_rows():
        d, t, cos_a, cos_g, value = lecture(scene, x, y)
        assert math.isclose(float(cells[0]), d, rel_tol=1e-4, abs_tol=1e-4), (x, y)
        if t is not None:
            assert math.isclose(float(cells[1]), t, rel_tol=1e-4), (x, y)
            assert math.isclose(float(cells[2]), cos_a, abs_tol=1e-4), (x, y)
            assert math.isclose(float(cells[3]), cos_g, abs_tol=1e-4), (x, y)
        linear_i = [float(v) for v in cells[4].strip("()").split(",")]
        assert np.allclose(linear_i, value, atol=1e-4), (x, y)
        assert [int(v) for v in cells[5].split(",")] == [srgb8(v) for v in value], (x, y)
        expected_linear = [round(255 * min(max(v, 0.0), 1.0)) for v in value]
        assert [int(v) for v in cells[6].split(",")] == expected_linear, (x, y)


def test_expected_values_are_the_pixels_hikari_writes(tmp_path):
    for encoding, column in (("srgb", 5), ("linear", 6)):
        out = tmp_path / f"{encoding}.ppm"
        subprocess.run([CLI, "render", scene_path("assignment.json"), "--encoding", encoding,
                        "-o", str(out), "-q"], check=True)
        with open(out, "rb") as f:
            assert f.readline().strip() == b"P6"
            width, height = map(int, f.readline().split())
            f.readline()
            pixels = np.frombuffer(f.read(), np.uint8).reshape(height, width, 3)
        for x, y, cells in table_rows():
            written = [int(v) for v in cells[column].split(",")]
            assert np.abs(pixels[y, x].astype(int) - written).max() <= 1, (encoding, x, y)
