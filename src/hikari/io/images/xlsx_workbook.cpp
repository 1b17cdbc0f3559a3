#include "hikari/io/images/xlsx_workbook.h"

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/io/files/atomic_file.h"
#include "hikari/io/files/read_file.h"

namespace hikari {

namespace {

/// The workbook's default font size (Courier New, set_square_cells) and its digit's width at
/// 96 pixels per inch: 0.6 em of 10 points = 6 points = 8 pixels.
constexpr double k_default_font_points = 10;
constexpr uint32_t k_default_font_digit_pixels = 8;

}  // namespace

std::vector<uint8_t> build_workbook(const std::filesystem::path& output,
                                    const std::function<void(lxw_workbook*)>& fill) {
    const TemporaryFile file(output);
    std::string directory = output.has_parent_path() ? output.parent_path().string() : ".";
    lxw_workbook_options options{};
    options.constant_memory = LXW_TRUE;
    options.tmpdir = directory.data();
    lxw_workbook* book = workbook_new_opt(file.path().c_str(), &options);
    if (!book) fail_workbook(output, "libxlsxwriter could not start a workbook");
    // The default format (the first, xf 0) sets the font that column widths are measured in:
    // set_square_cells.
    lxw_format* default_format = STAILQ_FIRST(book->formats);
    format_set_font_name(default_format, "Courier New");
    format_set_font_size(default_format, k_default_font_points);
    try {
        fill(book);
    } catch (...) {
        workbook_close(book);
        throw;
    }
    check_workbook(workbook_close(book), output);
    const std::string bytes = read_file_bytes(file.path());
    return {bytes.begin(), bytes.end()};
}

void set_square_cells(lxw_worksheet* sheet, lxw_col_t first, lxw_col_t last, uint32_t pixels,
                      const std::filesystem::path& path) {
    // libxlsxwriter stores w = pixels' / 7 digits (it assumes Calibri's 7-pixel digit); the
    // width wanted is pixels / 8 digits of Courier New, so pixels' = 7 · pixels / 8.
    const uint32_t calibri_pixels = pixels * 7 / k_default_font_digit_pixels;
    check_workbook(worksheet_set_column_pixels(sheet, first, last, calibri_pixels, nullptr), path);
    worksheet_set_default_row(sheet, 0.75 * pixels, LXW_FALSE);  // points = 3/4 pixel
}

void fail_workbook(const std::filesystem::path& path, const std::string& why) {
    throw InputError(fmt::format("cannot write {}: {}", path.string(), why));
}

void check_workbook(lxw_error error, const std::filesystem::path& path) {
    if (error != LXW_NO_ERROR) fail_workbook(path, lxw_strerror(error));
}

}  // namespace hikari
