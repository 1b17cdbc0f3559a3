#include "python_json.h"

#include <cmath>

#include <fmt/format.h>

#include "hikari/core/error.h"

namespace hikari::python {

namespace py = pybind11;

namespace {

[[noreturn]] void fail(const std::string& what, const std::string& path, const std::string& why) {
    throw InputError(fmt::format("{}{}{}", what.empty() ? "" : what + ": ",
                                 path.empty() ? "" : path + ": ", why));
}

nlohmann::json convert(const py::handle& value, const std::string& what, const std::string& path,
                       int depth) {
    if (depth > k_python_json_depth)  // the path so far is as long: its start says where
        fail(what, path.substr(0, 60) + "...",
             fmt::format("nested deeper than {} levels", k_python_json_depth));
    if (value.is_none()) return nullptr;
    if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
    if (py::isinstance<py::int_>(value)) {
        int overflow = 0;
        const long long whole = PyLong_AsLongLongAndOverflow(value.ptr(), &overflow);
        if (overflow == 0) return whole;
        fail(what, path, "the whole number is out of range");
    }
    if (py::isinstance<py::float_>(value)) {
        const double number = value.cast<double>();
        if (!std::isfinite(number))
            fail(what, path, fmt::format("expected a finite number, got {}", number));
        return number;
    }
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    if (py::isinstance<py::dict>(value)) {
        nlohmann::json object = nlohmann::json::object();
        for (const auto& [key, item] : value.cast<py::dict>()) {
            if (!py::isinstance<py::str>(key))
                fail(what, path,
                     fmt::format(
                         "a key must be a string, not {}",
                         py::str(py::type::handle_of(key).attr("__name__")).cast<std::string>()));
            const std::string name = key.cast<std::string>();
            object[name] = convert(item, what, path.empty() ? name : path + "." + name, depth + 1);
        }
        return object;
    }
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
        nlohmann::json array = nlohmann::json::array();
        size_t index = 0;
        for (const py::handle item : value.cast<py::sequence>())
            array.push_back(convert(item, what, fmt::format("{}[{}]", path, index++), depth + 1));
        return array;
    }
    // NumPy scalars and arrays, the values a notebook has at hand, as their Python equivalents.
    if (py::hasattr(value, "tolist") && py::hasattr(value, "dtype"))
        return convert(value.attr("tolist")(), what, path, depth + 1);
    fail(what, path,
         fmt::format("{} values are not scene data (expected numbers, strings, lists and dicts)",
                     py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>()));
}

}  // namespace

nlohmann::json json_of_python(const py::handle& value, const std::string& what,
                              const std::string& path) {
    return convert(value, what, path, 0);
}

}  // namespace hikari::python
