#pragma once
// The pieces of the _hikari extension, one file per concept (Scene, images, methods), and the
// conversions between hikari's images and NumPy arrays they share.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "hikari/core/image.h"
#include "hikari/frame/framebuffer.h"

namespace hikari::python {

namespace py = pybind11;

/// hikari.Scene: a render session (session/session.h).
void bind_scene(py::module_& m);
/// to_srgb8, write, read, compare.
void bind_images(py::module_& m);
/// set_max_memory, max_memory: the memory limit (--max-memory).
void bind_memory(py::module_& m);
/// methods(): the registry, with each method's options and AOVs.
void bind_methods(py::module_& m);

/// The buffer `aov` of a finished render as a NumPy array owned by NumPy (no copy for colour,
/// depth and normals): float32, (H, W, 3) for colour and normals, (H, W) for depth and ids.
py::array framebuffer_array(Framebuffer&& fb, Aov aov);

/// `image` as a float32 (H, W, 3) array, moved, not copied.
py::array image_array(Image&& image);

/// A float array of shape (H, W, 3) or (H, W) (grey, repeated in every channel) as an Image;
/// TypeError / ValueError for anything else.
Image array_image(const py::array& array);

}  // namespace hikari::python
