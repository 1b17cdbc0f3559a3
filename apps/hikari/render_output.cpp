#include "render_output.h"

#include <optional>

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/frame/aov_picture.h"
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

/// --depth-range, when given.
std::optional<DepthRange> depth_range(const RenderOptions& o) {
    if (o.depth_range.empty()) return std::nullopt;
    return DepthRange{o.depth_range[0], o.depth_range[1]};
}

}  // namespace

Film output_film(const Camera& camera, const std::string& output, const RenderOptions& o) {
    const bool srgb8 = is_colour_aov(o.aov) && is_picture_file(output) && o.bit_depth == 8 &&
                       o.encoding == SampleEncoding::srgb && o.exposure == 0.0f &&
                       o.tone_map == ToneMap::clamp;
    return Film(camera, srgb8 ? FilmFormat::srgb8 : FilmFormat::linear);
}

void write_output(const std::string& output, Framebuffer&& fb, const RenderOptions& o,
                  const Scene& scene) {
    if (render_control().cancel.load()) throw Interrupted();
    const ImageWriteSettings settings = image_write_settings(o);
    if (fb.film.format() == FilmFormat::srgb8)
        write_image(output, fb.film.srgb8());
    else if (is_colour_aov(o.aov))
        write_colour(output, aov_image(std::move(fb), o.aov), o);
    else if (is_picture_file(output))
        write_image(output, aov_picture(fb, o.aov, depth_range(o), unbounded_primitives(scene)),
                    settings);
    else
        write_image(output, aov_image(std::move(fb), o.aov), settings);
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
