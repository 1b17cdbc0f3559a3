"""hikari from Python: every rendering method of the lecture, images as NumPy arrays.

    import hikari
    scene = hikari.Scene.load("scenes/teapot.json")
    image = scene.render("zbuffer", width=320, shadows="pcf")   # float32 (H, W, 3), linear
    hikari.write("teapot.png", image)

A Scene is a render session: it is loaded once, and later renders reuse what does not depend
on the camera (the BVH, ...). Bad input raises hikari.InputError (a ValueError) with the message
the command line prints; Ctrl-C stops a render (KeyboardInterrupt). See docs/python.md.
"""

import contextlib as _contextlib

import numpy as _np

from . import _hikari
from ._hikari import (InputError, compare, max_memory, methods, read, set_max_memory, to_srgb8,
                      write)

__version__ = _hikari.__version__
__all__ = ["Scene", "Image", "Explanation", "InputError", "methods", "explain", "set_max_memory",
           "max_memory", "to_srgb8",
           "write", "read", "compare"]


@_contextlib.contextmanager
def _memory_limit(gib):
    """The memory limit set to `gib` GiB for one call (None: as it is), as --max-memory sets it
    for one command; the limit before is restored after, whatever happens."""
    if gib is None:
        yield
        return
    before = max_memory()
    set_max_memory(gib)
    try:
        yield
    finally:
        set_max_memory(before)


def _no_bools(**values):
    """TypeError for a bool given as a count (True is 1 to Python, never what was meant)."""
    for name, value in values.items():
        if isinstance(value, (bool, _np.bool_)):
            raise TypeError(f"{name}: expected a whole number, not {value!r}")


class Image(_np.ndarray):
    """A rendered image: a NumPy array (float32, linear values) that shows itself in Jupyter."""

    def _repr_png_(self):
        import os
        import tempfile

        picture = self if self.ndim == 3 else _grey_picture(self)
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "image.png")
            write(path, _np.asarray(picture))
            with open(path, "rb") as f:
                return f.read()


def _grey_picture(values):
    """A depth or id buffer as grey values 0..1 over its finite range (background black)."""
    values = _np.asarray(values, dtype=_np.float32)
    finite = _np.isfinite(values)
    if not finite.any():
        return _np.zeros(values.shape + (3,), _np.float32)
    low, high = values[finite].min(), values[finite].max()
    scaled = _np.where(finite, (values - low) / max(high - low, 1e-30), 0.0)
    return _np.repeat(scaled[..., None], 3, axis=2).astype(_np.float32)


class Explanation(str):
    """What `hikari explain` prints for one step of an algorithm: the text itself (print it), and
    the same text as data: `title` (its first line) and `steps`, a list of
    {"text": line, "steps": [...]} nested as the text indents them (the Z-buffer's fragments,
    the ray tree's rays with their shadow rays, the scanline's edge-table entries, ...)."""

    @property
    def title(self):
        return self.split("\n", 1)[0]

    @property
    def steps(self):
        root = {"text": self.title, "steps": []}
        open_steps = [(-1, root)]  # (indent, step) from the root down to the last line
        for line in self.splitlines()[1:]:
            if not line.strip():
                continue
            indent = len(line) - len(line.lstrip(" "))
            while open_steps[-1][0] >= indent:
                open_steps.pop()
            step = {"text": line.strip(), "steps": []}
            open_steps[-1][1]["steps"].append(step)
            open_steps.append((indent, step))
        return root["steps"]


def explain(scene, method, pixel=None, row=None, width=None, height=None, camera=None,
            max_memory=None, **method_options):
    """One step of `method`'s algorithm on `scene`, as `hikari explain` prints it: pixel=(x, y)
    for zbuffer (the fragments tested there, Alg 4.2) and raytrace (the ray tree, Alg 4.3),
    row=y for scanline (edge table, active edges and spans, Alg 4.1), neither for depthsort
    (Newell's comparisons and the painting order). An Explanation: print it, or read .steps."""
    with _memory_limit(max_memory):
        return Explanation(scene._session.explain(method, pixel, row, width, height, camera,
                                                  **method_options))


class Scene:
    """A scene loaded once and rendered many times (a render session)."""

    def __init__(self, session):
        self._session = session

    @classmethod
    def load(cls, path, max_memory=None, **overrides):
        """Loads a scene file (.json) or a model (.obj .ply .gltf .glb) as `hikari render` does.

        Keywords as the command line's: set={"materials.clay.shininess": 5} (or a list of
        "PATH=VALUE"), ground=True, crease_angle=30, camera_from=(x, y, z), look_at=(x, y, z),
        max_memory=GiB (the limit for this load; see set_max_memory).
        """
        with _memory_limit(max_memory):
            return cls(_hikari.Scene.load(str(path), **overrides))

    @classmethod
    def from_dict(cls, scene, base_dir=".", max_memory=None):
        """A scene from the scene format as Python data (dicts and lists, docs/scene-format.md)."""
        with _memory_limit(max_memory):
            return cls(_hikari.Scene.from_data(scene, str(base_dir), "scene"))

    @classmethod
    def default(cls):
        """The lecture's assignment: a Phong-shaded sphere."""
        return cls(_hikari.Scene.default())

    def set(self, path, value):
        """Changes one value by its JSON path, as --set does: set("materials.clay.shininess", 5)."""
        self._session.set(path, value)

    def render(self, method="raytrace", width=None, height=None, aov="color", camera=None,
               threads=None, progress=None, max_memory=None, **method_options):
        """Renders with `method` (see hikari.methods()): an Image, float32 linear values,
        (H, W, 3) for colour, normals and the spans and culled pictures; (H, W) for depth, ids
        and the counts of overdraw (fragments per pixel) and paint-order (1 + painting position;
        0 for the background).

        camera: a dict with any of eye, look_at, up, fov_y, projection, view_height, width,
        height. progress: called with the fraction done. Method options as keywords:
        spp=16, shadows="pcf", max_depth=3, line_color=(0.1, 0.1, 0.2), ...
        max_memory: the memory limit in GiB for this render, as --max-memory (every buffer it
        makes counts, with the scene's); InputError when it would need more.
        """
        _no_bools(width=width, height=height, threads=threads)
        with _memory_limit(max_memory):
            array = self._session.render(method, width, height, aov, camera, threads, progress,
                                         **method_options)
        return array.view(Image)

    def to_json(self, width=None, height=None, camera=None):
        """The scene as scene-format JSON text with this camera (a dict, as render takes) and
        size: `hikari render` of the saved file renders what render() gives for that view.
        Files are named by absolute paths; `set` values are applied."""
        return self._session.to_json(width, height, camera)

    @property
    def camera(self):
        """The scene's camera as a dict (eye, look_at, up, projection, fov_y, ...)."""
        return self._session.camera

    @property
    def info(self):
        """What the scene holds: triangles, spheres, planes, lights, materials."""
        return self._session.info

    @property
    def warnings(self):
        """What loading had to say, one line each."""
        return self._session.warnings

    @property
    def kept_structures(self):
        """How many camera-independent structures the session keeps built."""
        return self._session.kept_structures
