#pragma once
// The write step of `hikari render`: the film a render fills for its output file, and the
// finished framebuffer written there as the options ask (buffer, exposure, tone map, bits).

#include <string>

#include "hikari/core/image.h"
#include "hikari/frame/film.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/scene/scene.h"
#include "hikari/session/developed_frame.h"
#include "render_options.h"

namespace hikari::cli {

/// The film for `output`: 8-bit sRGB where the file keeps only that (the colour, neither exposed
/// nor tone mapped, in an 8-bit PNG, JPEG, PPM or spreadsheet), else linear floats.
Film output_film(const Camera& camera, const std::string& output, const RenderOptions& o);

/// How --aov, --exposure, --tonemap and --depth-range develop a render (session/developed_frame.h);
/// `display`: whether the output holds display values (is_picture_file).
Development development(const RenderOptions& o, bool display);

/// Writes the render `result` to `output` developed as the options ask (development), at
/// --bit-depth and --encoding, unless the render was interrupted: throws Interrupted. `scene`:
/// the scene rendered.
void write_output(const std::string& output, RenderResult&& result, const RenderOptions& o,
                  const Scene& scene);

/// `--formulas`: the workbook of io/images/xlsx_formulas_write.h for `scene` (the scene as the
/// render would see it) written to `output`. Throws InputError naming what the formulas cannot
/// express.
void write_formula_workbook(const std::string& output, const Scene& scene, const RenderOptions& o);

/// `--progressive`: the image so far written over `output` (atomically, as every image is: a
/// viewer watching the file sees the old image or the new one, never half of one).
void write_progressive_snapshot(const std::string& output, const Image& mean,
                                const RenderOptions& o);

}  // namespace hikari::cli
