#pragma once
// What each fuzz target does with one input, shared by the libFuzzer targets in fuzz/ and by
// tests/io/fuzz_regression_test.cpp, which replays every input that once broke hikari.
// Each function returns normally when the input loads or is refused with InputError; anything
// else (a crash, a sanitizer report, an inconsistent result: std::abort) is a bug.

#include <unistd.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "hikari/core/error.h"
#include "hikari/io/image_read.h"
#include "hikari/io/obj_loader.h"
#include "hikari/io/scene_json.h"

namespace hikari::fuzz {

/// Writes `data` to a file named `name` in this process's private temporary directory: the
/// loaders read by path (to resolve MTL files and to name the file in errors).
inline std::filesystem::path write_input(const uint8_t* data, size_t size,
                                         const std::string& name) {
    static const std::filesystem::path dir = [] {
        auto d =
            std::filesystem::temp_directory_path() / ("hikari-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    const auto path = dir / name;
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return path;
}

/// Scene JSON text -> Scene.
inline void scene_json_input(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    std::vector<std::string> warnings;
    try {
        // Mesh paths resolve under a directory that does not exist: fuzzing must not read the
        // machine's files.
        parse_scene(text, "fuzz.json", "/nonexistent-hikari-fuzz", warnings);
    } catch (const InputError&) {
    }
}

/// OBJ text -> MeshData, which must be internally consistent.
inline void obj_input(const uint8_t* data, size_t size) {
    try {
        const MeshData mesh = load_obj(write_input(data, size, "input.obj"));
        if (mesh.normals.size() != mesh.positions.size() ||
            mesh.material.size() != mesh.indices.size())
            std::abort();
        for (const auto& triangle : mesh.indices)
            for (uint32_t i : triangle)
                if (i >= mesh.positions.size()) std::abort();
    } catch (const InputError&) {
    }
}

/// The first byte picks a reader (PNG, JPEG, PPM, PFM, EXR); the rest is the file.
inline void image_input(const uint8_t* data, size_t size) {
    if (size == 0) return;
    static constexpr std::array<const char*, 5> k_names = {"in.png", "in.jpg", "in.ppm", "in.pfm",
                                                           "in.exr"};
    try {
        const Image image = read_image(write_input(data + 1, size - 1, k_names[data[0] % 5]));
        if (image.pixels.size() != static_cast<size_t>(image.width) * image.height) std::abort();
    } catch (const InputError&) {
    }
}

}  // namespace hikari::fuzz
