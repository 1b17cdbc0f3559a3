#pragma once
// Where a render's images go, and the checks, made before any work, that they can be written
// there without replacing a file the render reads.

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hikari/scene/camera.h"
#include "render_options.h"

namespace hikari::cli {

/// The output of `method`: `-o` as given for one method; for several, `-o NAME.EXT` becomes
/// NAME-<method>.EXT. Without -o, `<scene>.png` for the default method alone, else
/// `<scene>-<method>.png` (so rendering a scene by several methods keeps every picture), with
/// `-<aov>` added for a buffer other than colour.
std::string output_for(const RenderOptions& o, std::string_view method);

/// A file the render reads, which its output must not replace, and what it is to the render.
struct RenderInput {
    std::filesystem::path file;
    std::string role;  ///< "the scene file", "the model file", "a file the scene reads"
};

/// The files a render of `scene_file` reads: the scene (or model) file, and the files the
/// scene names. A scene that cannot be read or parsed names none here: its loader reports it.
std::vector<RenderInput> render_inputs(const std::string& scene_file);

/// Refuses, before any work is done, an output the render could not be written to (usage
/// errors, exit 2: a directory, an unknown extension, a missing or read-only directory, a name
/// too long), or that is a file the render reads (a scene named `scene.png` rendered without
/// -o, `render bunny.ply -o bunny.ply`, a scene's mesh or texture). Then removes the
/// temporaries that a killed earlier run left beside it (io/atomic_file.h).
void check_output_path(const std::filesystem::path& output, std::span<const RenderInput> inputs);

/// Refuses, before rendering, a spreadsheet output larger than a sheet holds.
void check_spreadsheet_size(const std::filesystem::path& output, const Camera& camera);

/// Whether `output` holds display values (PNG, JPEG, PPM, a spreadsheet), not linear floats.
bool is_picture_file(const std::string& output);

}  // namespace hikari::cli
