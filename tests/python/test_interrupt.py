"""Ctrl-C (KeyboardInterrupt) stops every long call of the module, not only renders: loading a
large mesh, the depth sort, its explanation and the hidden-line drawing of it; the scene and the
module stay usable."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import hikari


@pytest.fixture(scope="module")
def large_mesh(tmp_path_factory):
    """A binary PLY of a 1000 x 1000 grid (two million triangles): seconds of loading and of
    depth sorting, long enough to be interrupted on any machine."""
    n = 1000
    xs, ys = np.meshgrid(np.arange(n + 1, dtype=np.float32), np.arange(n + 1, dtype=np.float32))
    vertices = np.stack([xs.ravel(), ys.ravel(), np.zeros(xs.size, np.float32)], 1)
    corner = (np.arange(n)[None, :] + (n + 1) * np.arange(n)[:, None]).ravel()
    a, b, c, d = corner, corner + 1, corner + n + 1, corner + n + 2
    faces = np.concatenate([np.stack([a, b, d], 1), np.stack([a, d, c], 1)])
    records = np.zeros(len(faces), dtype=[("count", "u1"), ("indices", "<i4", 3)])
    records["count"] = 3
    records["indices"] = faces
    path = tmp_path_factory.mktemp("mesh") / "grid.ply"
    with open(path, "wb") as f:
        f.write((f"ply\nformat binary_little_endian 1.0\nelement vertex {len(vertices)}\n"
                 "property float x\nproperty float y\nproperty float z\n"
                 f"element face {len(faces)}\nproperty list uchar int vertex_indices\n"
                 "end_header\n").encode())
        f.write(vertices.astype("<f4").tobytes())
        f.write(records.tobytes())
    return str(path)


def interrupted_after(seconds, call):
    """Sends SIGINT `seconds` into `call`; how long after it KeyboardInterrupt came."""
    sent = {}

    def interrupt():
        sent["at"] = time.monotonic()
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(seconds, interrupt)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            call()
    finally:
        timer.cancel()
    return time.monotonic() - sent["at"]


def test_ctrl_c_stops_loading_and_the_next_load_runs(large_mesh):
    assert interrupted_after(0.05, lambda: hikari.Scene.load(large_mesh)) < 5.0
    assert hikari.Scene.load(large_mesh).info["triangles"] == 2_000_000


def test_ctrl_c_stops_an_explanation_a_depth_sort_and_hidden_lines(large_mesh):
    scene = hikari.Scene.load(large_mesh)
    assert interrupted_after(0.3, lambda: hikari.explain(scene, "depthsort", width=32,
                                                         height=24)) < 5.0
    assert interrupted_after(0.3, lambda: scene.render("depthsort", width=32, height=24)) < 5.0
    assert interrupted_after(0.3, lambda: scene.render("hiddenline", width=32, height=24)) < 5.0
    assert scene.render("zbuffer", width=16).shape == (12, 16, 3)
