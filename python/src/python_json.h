#pragma once
// Python data as JSON: the scene format given as dicts and lists (Scene.from_dict), `--set`
// values and method options. Converted here, in C++, rather than through Python's json module,
// so that every fault names its JSON path as the scene loader's own errors do.

#include <string>

#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

namespace hikari::python {

/// `value` as JSON: None, bools, whole numbers, finite floats, strings, lists and tuples, dicts
/// with string keys. InputError "`what`: `path`: ..." for anything else (sets, objects, bytes,
/// NaN and infinity, which JSON has no words for) and for nesting deeper than
/// k_python_json_depth (a list that holds itself ends there).
nlohmann::json json_of_python(const pybind11::handle& value, const std::string& what,
                              const std::string& path = "");

/// How deeply a Python value may nest: far more than the scene format uses.
inline constexpr int k_python_json_depth = 256;

}  // namespace hikari::python
