#include "hikari/io/images/xlsx_write.h"

#include <string>

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/io/images/colour_palette.h"
#include "hikari/io/images/xlsx_workbook.h"

namespace hikari {

namespace {

/// Cell size of the picture on screen and paper, in pixels: two digits of the workbook's font,
/// square in Excel and LibreOffice alike (set_square_cells).
constexpr uint32_t k_cell_pixels = 16;
/// Cell size of the channel sheets: wide enough for "255".
constexpr uint32_t k_number_width_pixels = 30, k_number_height_pixels = 16;

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& why) {
    fail_workbook(path, why);
}

void check(lxw_error error, const std::filesystem::path& path) { check_workbook(error, path); }

/// A sheet of `width` × `height` cells of the given size in pixels, printed without gridlines
/// on one page (its print area set: a sheet of blank filled cells is otherwise not printed).
lxw_worksheet* add_grid_sheet(lxw_workbook* book, const char* name, int width, int height,
                              uint32_t cell_width, uint32_t cell_height,
                              const std::filesystem::path& path) {
    lxw_worksheet* sheet = workbook_add_worksheet(book, name);
    if (!sheet) fail(path, "libxlsxwriter could not add a worksheet");
    const auto last_row = static_cast<lxw_row_t>(height - 1);
    const auto last_column = static_cast<lxw_col_t>(width - 1);
    if (cell_width == cell_height) {
        set_square_cells(sheet, 0, last_column, cell_width, path);
    } else {
        check(worksheet_set_column_pixels(sheet, 0, last_column, cell_width, nullptr), path);
        worksheet_set_default_row(sheet, 0.75 * cell_height, LXW_FALSE);  // points = 3/4 pixel
    }
    worksheet_gridlines(sheet, LXW_HIDE_ALL_GRIDLINES);
    worksheet_set_margins(sheet, 0.2, 0.2, 0.2, 0.2);
    if (width * cell_width > height * cell_height) worksheet_set_landscape(sheet);
    worksheet_fit_to_pages(sheet, 1, 1);
    check(worksheet_print_area(sheet, 0, 0, last_row, last_column), path);
    return sheet;
}

}  // namespace

std::vector<uint8_t> encode_xlsx(const std::filesystem::path& path, const Srgb8Image& image) {
    if (image.width > k_xlsx_max_columns || image.height > k_xlsx_max_rows)
        fail(path, fmt::format("{}x{} pixels do not fit a spreadsheet (at most {} columns and {} "
                               "rows)",
                               image.width, image.height, k_xlsx_max_columns, k_xlsx_max_rows));
    const PalettedImage paletted = median_cut(image, k_xlsx_palette_colours);
    return build_workbook(path, [&](lxw_workbook* book) {
        // Sheet 1: the picture, one fill format per palette colour.
        lxw_worksheet* picture = add_grid_sheet(book, "image", image.width, image.height,
                                                k_cell_pixels, k_cell_pixels, path);
        std::vector<lxw_format*> fills;
        for (const auto& rgb : paletted.palette) {
            lxw_format* f = workbook_add_format(book);
            format_set_pattern(f, LXW_PATTERN_SOLID);
            format_set_num_format(f, ";;;");  // the cell's number is not shown
            format_set_bg_color(f, (uint32_t{rgb[0]} << 16) | (uint32_t{rgb[1]} << 8) | rgb[2]);
            fills.push_back(f);
        }
        // Each cell holds its pixel's colour as the number 0xRRGGBB, hidden by its format: a
        // sheet of blank cells would not be printed (LibreOffice skips empty pages).
        for (int y = 0; y < image.height; ++y) {
            const uint8_t* row = image.row(y);
            for (int x = 0; x < image.width; ++x) {
                const uint32_t rgb =
                    (uint32_t{row[3 * x]} << 16) | (uint32_t{row[3 * x + 1]} << 8) | row[3 * x + 2];
                check(worksheet_write_number(
                          picture, static_cast<lxw_row_t>(y), static_cast<lxw_col_t>(x), rgb,
                          fills[paletted.index[static_cast<size_t>(y) * image.width + x]]),
                      path);
            }
        }
        // Sheets 2–4: the channels as numbers.
        const char* names[3] = {"red", "green", "blue"};
        for (int c = 0; c < 3; ++c) {
            lxw_worksheet* values =
                add_grid_sheet(book, names[c], image.width, image.height, k_number_width_pixels,
                               k_number_height_pixels, path);
            for (int y = 0; y < image.height; ++y) {
                const uint8_t* row = image.row(y);
                for (int x = 0; x < image.width; ++x)
                    check(
                        worksheet_write_number(values, static_cast<lxw_row_t>(y),
                                               static_cast<lxw_col_t>(x), row[3 * x + c], nullptr),
                        path);
            }
        }
    });
}

}  // namespace hikari
