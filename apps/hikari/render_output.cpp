#include "render_output.h"

#include <optional>

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/frame/tone_map.h"
#include "hikari/io/files/atomic_file.h"
#include "hikari/io/images/image_write.h"
#include "hikari/io/images/xlsx_formulas_write.h"
#include "output_paths.h"
#include "signals.h"

namespace hikari::cli {

namespace {

/// Writes a colour render to `output` developed as --exposure and --tonemap ask, at --bit-depth.
void write_colour(const std::string& output, Image colour, const RenderOptions& o) {
    expose_and_tone_map(colour, o.exposure, is_picture_file(output) ? o.tone_map : ToneMap::clamp);
    write_image(output, colour, image_write_settings(o));
}

}  // namespace

Film output_film(const Camera& camera, const std::string& output, const RenderOptions& o) {
    const bool srgb8 = is_colour_aov(o.aov) && is_picture_file(output) && o.bit_depth == 8 &&
                       o.encoding == SampleEncoding::srgb && o.exposure == 0.0f &&
                       o.tone_map == ToneMap::clamp;
    return Film(camera, srgb8 ? FilmFormat::srgb8 : FilmFormat::linear);
}

Development development(const RenderOptions& o, bool display) {
    Development how{o.aov, o.exposure, o.tone_map, std::nullopt, display};
    if (!o.depth_range.empty()) how.depth_range = DepthRange{o.depth_range[0], o.depth_range[1]};
    return how;
}

void write_output(const std::string& output, RenderResult&& result, const RenderOptions& o,
                  const Scene& scene) {
    if (render_control().cancel.load()) throw Interrupted();
    const DevelopedImage image =
        develop(std::move(result), development(o, is_picture_file(output)), scene);
    if (const auto* srgb8 = std::get_if<Srgb8Image>(&image))
        write_image(output, *srgb8);
    else
        write_image(output, std::get<Image>(image), image_write_settings(o));
}

void write_formula_workbook(const std::string& output, const Scene& scene, const RenderOptions& o) {
    if (const std::string why = formula_workbook_obstacle(scene); !why.empty())
        throw InputError(fmt::format(
            "--formulas cannot express this scene: {} (the workbook computes the lecture's "
            "assignment: one sphere, one directional light)",
            why));
    write_file_atomically(output, encode_xlsx_formulas(output, scene, o.encoding));
}

void write_progressive_snapshot(const std::string& output, const Image& mean,
                                const RenderOptions& o) {
    if (render_control().cancel.load()) return;
    write_colour(output, mean, o);
}

}  // namespace hikari::cli
