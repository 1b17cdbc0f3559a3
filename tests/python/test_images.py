"""Images from Python: 8-bit sRGB values, files in every format, comparisons, Jupyter."""

import numpy as np
import pytest

import hikari
from conftest import read_pfm


def test_to_srgb8_is_what_a_png_holds(tmp_path):
    image = hikari.Scene.default().render(width=32, height=32)
    values = hikari.to_srgb8(image)
    assert values.dtype == np.uint8 and values.shape == (32, 32, 3)
    hikari.write(str(tmp_path / "a.png"), image)
    read_back = hikari.to_srgb8(hikari.read(str(tmp_path / "a.png")))
    assert np.array_equal(values, read_back)
    assert hikari.to_srgb8(image, exposure=1).sum() > values.sum()


def test_write_keeps_float_values(tmp_path):
    image = np.random.default_rng(1).random((5, 7, 3), dtype=np.float32) * 4
    hikari.write(str(tmp_path / "a.pfm"), image)
    assert np.array_equal(read_pfm(tmp_path / "a.pfm"), image)
    with pytest.raises(hikari.InputError):
        hikari.write(str(tmp_path / "a.bmp"), image)
    with pytest.raises(hikari.InputError):
        hikari.write(str(tmp_path / "a.png"), np.zeros((4, 4, 2), np.float32))


def test_compare_reports_psnr_and_where_images_differ():
    a = np.zeros((8, 8, 3), np.float32)
    b = a.copy()
    b[2, 3] = 0.5
    same = hikari.compare(a, a)
    assert same["psnr"] == float("inf") and same["differing_pixels"] == 0
    d = hikari.compare(a, b)
    assert d["differing_pixels"] == 1 and d["max_at"] == (3, 2)
    assert d["difference"].shape == (8, 8, 3)


def test_images_show_themselves_and_convert():
    image = hikari.Scene.default().render(width=16, height=16)
    assert image._repr_png_().startswith(b"\x89PNG")
    depth = hikari.Scene.default().render("zbuffer", width=16, height=16, aov="depth")
    assert depth._repr_png_().startswith(b"\x89PNG")
    assert isinstance(np.asarray(image), np.ndarray)


def test_methods_come_from_the_registry():
    methods = {m["name"]: m for m in hikari.methods()}
    assert {"raytrace", "path", "zbuffer", "scanline", "depthsort", "wireframe",
            "hiddenline"} <= set(methods)
    spp = next(o for o in methods["path"]["options"] if o["name"] == "spp")
    assert spp["kind"] == "integer" and spp["min"] == 1
    shadows = next(o for o in methods["zbuffer"]["options"] if o["name"] == "shadows")
    assert "pcf" in shadows["choices"]
    assert "spans" in methods["scanline"]["aovs"] and "spans" not in methods["zbuffer"]["aovs"]


def test_write_linear_encoding_is_255_times_the_value(tmp_path):
    image = np.array([[[0.8, 0.3, 0.2], [1.5, -0.2, 0.5]]], np.float32)
    hikari.write(str(tmp_path / "linear.ppm"), image, encoding="linear")
    hikari.write(str(tmp_path / "srgb.ppm"), image)
    linear = (tmp_path / "linear.ppm").read_bytes()[-6:]
    assert list(linear) == [204, 77, 51, 255, 0, 128]
    assert list((tmp_path / "srgb.ppm").read_bytes()[-6:-3]) == [231, 149, 124]
    with pytest.raises(hikari.InputError):
        hikari.write(str(tmp_path / "a.png"), image, encoding="gamma")
