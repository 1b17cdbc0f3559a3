"""Shared helpers of the Python module's tests: the repository, the CLI, PFM files."""

import os
import subprocess

import numpy as np
import pytest

SOURCE = os.environ.get("HIKARI_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
CLI = os.environ.get("HIKARI_CLI", os.path.join(SOURCE, "build", "hikari"))


def scene_path(name):
    return os.path.join(SOURCE, "scenes", name)


def read_pfm(path):
    """A PFM file as float32 (H, W, 3), row 0 at the top (PFM stores the bottom row first)."""
    with open(path, "rb") as f:
        kind = f.readline().strip()
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    channels = 3 if kind == b"PF" else 1
    return data.reshape(height, width, channels)[::-1].astype(np.float32)


@pytest.fixture
def cli_render(tmp_path):
    """Renders with the command line into a PFM and returns the pixels."""

    def render(*args):
        out = tmp_path / "cli.pfm"
        subprocess.run([CLI, "render", *args, "-o", str(out), "--quiet"], check=True)
        return read_pfm(out)

    return render
