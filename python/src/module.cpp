// The _hikari extension module: hikari's render session and image tools for Python
// (docs/python.md). The package hikari (python/hikari/__init__.py) wraps it.
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "hikari/core/error.h"
#include "hikari/version.h"

PYBIND11_MODULE(_hikari, m) {
    namespace py = pybind11;
    m.doc() = "hikari: the rendering methods of the lecture, from Python";
    m.attr("__version__") = hikari::k_version;
    // A bad scene, value or option is a ValueError carrying the message the command line prints.
    static py::exception<hikari::InputError> input_error(m, "InputError", PyExc_ValueError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const hikari::InputError& e) {
            input_error(e.what());
        } catch (const hikari::Interrupted&) {
            PyErr_SetNone(PyExc_KeyboardInterrupt);
        }
    });
    hikari::python::bind_scene(m);
    hikari::python::bind_images(m);
    hikari::python::bind_methods(m);
    hikari::python::bind_memory(m);
}
