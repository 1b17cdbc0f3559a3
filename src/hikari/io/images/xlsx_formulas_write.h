#pragma once
// Excelでレンダリング！ taken literally (the lecture's closing slide): a workbook whose cells
// compute the assignment's picture themselves, with spreadsheet formulas, from parameter cells.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "hikari/io/images/image_write.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// Why the formula workbook cannot express `scene` (one sentence naming the first obstacle), or
/// an empty string when it can: one sphere with a plain Phong material (no texture, mirror,
/// glass or emission), nothing else, one directional or point light, a perspective camera whose
/// eye is outside the sphere, a plain background, no depth cueing.
std::string formula_workbook_obstacle(const Scene& scene);

/// The workbook (libxlsxwriter) for `scene`, whose formula_workbook_obstacle must be empty:
/// - sheet "image": one square cell per pixel (square in Excel and LibreOffice), its value the
/// shading I_d/(I₀k_d) + I_s/(I₀k_s)
///   (cos α + cosⁿγ, −1 off the sphere), coloured by a three-colour scale from the unlit to the
///   fully lit colour to the highlight, and the background colour off the sphere;
/// - sheet "parameters": eye, look-at, up, fov_y, W, H, sphere centre S and radius r, the light
///   (direction L or position, I₀), k_a, k_d, k_s, n, I_a and the background, each a named
///   cell the formulas read; the camera frame derived from them by formulas;
/// - one sheet per quantity of the lecture, a cell per pixel: "E_x" "E_y" "E_z" (the ray
///   direction Ê), "D" (B² − 4AC), "t", "N_x" "N_y" "N_z", "cos_alpha", "cos_gamma", and
///   "red" "green" "blue", the 8-bit values a render writes with `encoding`.
/// Each formula is stored with its result worked out in double precision, so a spreadsheet that
/// keeps stored results (LibreOffice) shows the picture at once; changing a parameter (n)
/// recomputes the cells that depend on it and changes the picture. Throws InputError naming `path`
/// when the image is larger than a sheet or the write fails.
std::vector<uint8_t> encode_xlsx_formulas(const std::filesystem::path& path, const Scene& scene,
                                          SampleEncoding encoding);

}  // namespace hikari
