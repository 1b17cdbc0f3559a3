#pragma once
// How many bytes hikari reads from one input file, per kind of input (`--max-input-size`), so that
// a file far larger than any real scene, mesh or image is refused before it is read instead of
// filling the memory.

#include <cstdint>
#include <string_view>

namespace hikari {

/// The kinds of input file, each with its own default limit (README, "Robustness").
enum class InputKind {
    scene,  ///< scene JSON: 256 MiB
    mesh,   ///< OBJ, MTL, PLY, glTF, GLB and glTF buffers: 4 GiB
    image,  ///< textures and environment maps: 1 GiB
};

/// The most bytes read_file_bytes() reads from one file of `kind`: the default for the kind, or
/// the value set with set_max_input_size().
std::uintmax_t input_limit(InputKind kind);

/// What a file of `kind` is called in messages: "scene", "mesh", "image".
std::string_view input_kind_name(InputKind kind);

/// Replaces every kind's limit with `bytes` (the command line's --max-input-size); 0 restores
/// the defaults. Process-wide: set it once, before loading.
void set_max_input_size(std::uintmax_t bytes);

}  // namespace hikari
