// hikari.set_max_memory / hikari.max_memory: the command line's --max-memory for Python. The
// limit is the process's (core/memory_budget.h): every load and render after it is checked
// against it, and a refusal raises hikari.InputError saying how much was needed.
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "bindings.h"
#include "hikari/core/error.h"
#include "hikari/core/memory_budget.h"

namespace hikari::python {

namespace {

constexpr double k_gib = double(1 << 30);

void set_max_memory(double gib) {
    // The command line's bounds: a positive, finite number of GiB (a float's range).
    if (!std::isfinite(gib) || gib <= 0 || gib > 3.4e38)
        throw InputError(fmt::format("max_memory: expected a positive number of GiB, not {}", gib));
    set_memory_limit(gib * k_gib);
}

}  // namespace

void bind_memory(py::module_& m) {
    // Refusals name the Python spelling of the limit, not the command line's flag.
    set_memory_limit_hint("max_memory=GIB");
    m.def("set_max_memory", &set_max_memory, py::arg("gib"),
          "Sets the memory limit in GiB, as --max-memory does: a load or render whose buffers "
          "would need more raises InputError before they are made (default: half the machine's "
          "memory).");
    m.def(
        "max_memory", [] { return memory_limit() / k_gib; },
        "The memory limit in GiB (set_max_memory).");
}

}  // namespace hikari::python
