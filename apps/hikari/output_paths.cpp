#include "output_paths.h"

#include <unistd.h>
#include <climits>

#include <algorithm>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_options.h"
#include "hikari/core/error.h"
#include "hikari/io/files/atomic_file.h"
#include "hikari/io/files/printable_text.h"
#include "hikari/io/files/read_file.h"
#include "hikari/io/images/image_format.h"
#include "hikari/io/images/image_write.h"
#include "hikari/io/images/svg_write.h"
#include "hikari/io/images/xlsx_write.h"
#include "hikari/io/models/model_file.h"
#include "hikari/io/models/model_references.h"
#include "hikari/io/scene/json_reader.h"

namespace hikari::cli {

namespace {

namespace fs = std::filesystem;

/// Every string member "file" of a scene's JSON (meshes, textures, environment maps), relative
/// to `base_dir`; `depth` bounds the walk on hostile nesting.
void collect_named_files(const nlohmann::json& v, const fs::path& base_dir,
                         std::vector<RenderInput>& out, int depth = 0) {
    if (depth > 64 || !v.is_structured()) return;
    for (auto it = v.begin(); it != v.end(); ++it) {
        if (v.is_object() && it.key() == "file" && it->is_string())
            out.push_back({base_dir / it->get<std::string>(), "a file the scene reads"});
        else
            collect_named_files(*it, base_dir, out, depth + 1);
    }
}

/// A directory, or a name without a format hikari writes.
void check_output_format(const fs::path& output) {
    std::error_code ec;
    if (fs::is_directory(output, ec))
        throw UsageError(fmt::format("{}: is a directory; name an image file to write",
                                     quote_token(output.string(), '\0', k_quoted_path_bytes)));
    if (!is_supported_image_extension(output) && !is_svg_path(output))
        throw UsageError(fmt::format(
            "{}: unknown output format {} (supported: {}, and .svg for wireframe and hiddenline)",
            quote_token(output.string(), '\0', k_quoted_path_bytes),
            output.has_extension() ? "'" + output.extension().string() + "'" : "(no extension)",
            k_writable_image_extensions));
}

/// The most a temporary's name adds after its prefix: `<pid>-<n>.tmp`.
constexpr size_t k_temporary_suffix_bytes = 10 + 1 + 20 + 4;

/// A directory that is missing, not one, or not writable, or a file name longer than it allows.
void check_output_directory(const fs::path& output) {
    std::error_code ec;
    const fs::path dir = output.has_parent_path() ? output.parent_path() : ".";
    if (!fs::is_directory(dir, ec))
        throw UsageError(
            fmt::format("{}: cannot write: the directory {} {}",
                        quote_token(output.string(), '\0', k_quoted_path_bytes),
                        quote_token(dir.string(), '\0', k_quoted_path_bytes),
                        fs::exists(dir, ec) ? "is not a directory" : "does not exist"));
    if (::access(dir.c_str(), W_OK) != 0)
        throw UsageError(fmt::format("{}: cannot write: the directory {} is not writable",
                                     quote_token(output.string(), '\0', k_quoted_path_bytes),
                                     quote_token(dir.string(), '\0', k_quoted_path_bytes)));
    // The temporary beside it (io/files/atomic_file.h) adds its own name to the directory's.
    const size_t temporary = (output.has_parent_path() ? dir.string().size() + 1 : 0) +
                             temporary_prefix_for(output).size() + k_temporary_suffix_bytes;
    if (const size_t length = std::max(output.string().size(), temporary); length >= PATH_MAX)
        throw UsageError(fmt::format(
            "{}: cannot write: the path is {} bytes long with its temporary; the system allows "
            "{}",
            quote_token(output.string(), '\0', k_quoted_path_bytes), length, PATH_MAX - 1));
    const long name_max = ::pathconf(dir.c_str(), _PC_NAME_MAX);
    if (const size_t length = output.filename().string().size();
        name_max > 0 && length > static_cast<size_t>(name_max))
        throw UsageError(
            fmt::format("{}: cannot write: the file name is {} bytes long; the "
                        "file system allows {}",
                        quote_token(output.string(), '\0', k_quoted_path_bytes), length, name_max));
}

/// An output that is one of the files the render reads.
void check_not_an_input(const fs::path& output, std::span<const RenderInput> inputs) {
    std::error_code ec;
    for (const RenderInput& input : inputs) {
        if (fs::equivalent(output, input.file, ec))
            throw UsageError(fmt::format(
                "{}: refusing to overwrite {}{} with the render",
                quote_token(output.string(), '\0', k_quoted_path_bytes), input.role,
                input.role.starts_with("the ") ? "" : " (" + input.file.string() + ")"));
    }
}

}  // namespace

std::string output_for(const RenderOptions& o, std::string_view method) {
    const bool several = o.methods.size() > 1;
    if (!o.output.empty()) {
        if (!several) return o.output;
        const fs::path out(o.output);
        return (out.parent_path() /
                (out.stem().string() + "-" + std::string(method) + out.extension().string()))
            .string();
    }
    const std::string stem =
        o.scene_file.empty() ? "assignment" : fs::path(o.scene_file).stem().string();
    const std::string suffix =
        !several && method == methods().front().name ? "" : "-" + std::string(method);
    return stem + suffix + (o.aov == Aov::color ? "" : "-" + std::string(aov_name(o.aov))) + ".png";
}

std::vector<RenderInput> render_inputs(const std::string& scene_file) {
    if (scene_file.empty()) return {};
    const bool model = is_model_file(scene_file);
    std::vector<RenderInput> inputs{{scene_file, model ? "the model file" : "the scene file"}};
    if (!model) {
        try {
            const nlohmann::json json = parse_json(read_file_bytes(scene_file), scene_file);
            collect_named_files(json, fs::path(scene_file).parent_path(), inputs);
        } catch (const std::exception&) {  // not readable or not JSON: the load says why
        }
    }
    // The models' own references: MTL libraries, their textures, glTF images and buffers.
    const size_t named = inputs.size();
    for (size_t i = 0; i < named; ++i)
        if (is_model_file(inputs[i].file.string()))
            for (fs::path& file : model_references(inputs[i].file))
                inputs.push_back({std::move(file), "a file the model reads"});
    return inputs;
}

void check_output_path(const fs::path& output, std::span<const RenderInput> inputs) {
    check_output_format(output);
    check_output_directory(output);
    check_not_an_input(output, inputs);
    remove_stale_temporary_files(output);
}

void check_spreadsheet_size(const fs::path& output, const Camera& camera) {
    if (image_format_from_extension(output) != ImageFormat::Xlsx) return;
    if (camera.width > k_xlsx_max_columns || camera.height > k_xlsx_max_rows)
        throw InputError(fmt::format(
            "{}: a {}x{} image does not fit a spreadsheet (at most {} columns and {} rows)",
            quote_token(output.string(), '\0', k_quoted_path_bytes), camera.width, camera.height,
            k_xlsx_max_columns, k_xlsx_max_rows));
}

bool is_picture_file(const std::string& output) {
    const std::optional<ImageFormat> format = image_format_from_extension(output);
    return format && is_low_dynamic_range(*format);
}

}  // namespace hikari::cli
