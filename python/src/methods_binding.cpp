// hikari.methods(): the registry as Python data (methods/method_catalog.h), so a script (or a
// notebook's widget) can list every method with its options and buffers, and a new method
// appears without touching Python.
#include "bindings.h"
#include "hikari/methods/method_catalog.h"

namespace hikari::python {

void bind_methods(py::module_& m) {
    m.def(
        "methods",
        [] { return py::module_::import("json").attr("loads")(method_catalog().dump()); },
        "Every rendering method: name, summary, options (name, help, kind, range or choices), "
        "the AOVs it renders and its explain views.");
}

}  // namespace hikari::python
