#pragma once
// OBJ text and load errors shared by the OBJ loader's tests.

#include <filesystem>
#include <string>

#include "hikari/io/models/obj_loader.h"
#include "input_error.h"

namespace hikari::testing {

/// The four vertices of a unit quad in the z = 0 plane, counter-clockwise seen from +z.
inline constexpr const char* k_obj_quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

/// The message of the InputError that load_obj(path) throws, or "" when it throws none.
inline std::string obj_load_error(const std::filesystem::path& path) {
    return input_error_of([&] { load_obj(path); });
}

}  // namespace hikari::testing
