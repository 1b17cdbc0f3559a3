#pragma once
// What the two workbook writers share: libxlsxwriter writes only to files, so a workbook is
// built in a temporary file beside its output, checked call by call, and read back as bytes.

#include <xlsxwriter.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace hikari {

/// The bytes of a workbook that `fill` writes the sheets of. libxlsxwriter writes only to files:
/// the workbook is built in a temporary beside `output`, named and removed as every other
/// temporary (io/files/atomic_file.h: also on SIGINT / SIGTERM), with libxlsxwriter's scratch
/// files (unlinked as soon as opened) in the same folder, so no other folder needs to exist or
/// have room; then closed, read back and removed.
std::vector<uint8_t> build_workbook(const std::filesystem::path& output,
                                    const std::function<void(lxw_workbook*)>& fill);

/// Sets columns `first`..`last` of `sheet` and its default row to squares of `pixels` pixels
/// (a multiple of 8, above 13), in Excel and in LibreOffice alike. Both apps measure a column in
/// digits of the workbook's default font: Excel rounds the digit to whole pixels (7 for Calibri 11,
/// whose digit is 7.4 pixels), LibreOffice does not, so Calibri's columns are 6% wider in
/// LibreOffice than in Excel, while rows are points in both. build_workbook makes the default font
/// Courier New 10, whose digit is exactly 8 pixels (6 points) in Excel and in LibreOffice's metric
/// twin Liberation Mono, so w = pixels / 8 digits is `pixels` in both (ECMA-376 §18.3.1.13).
void set_square_cells(lxw_worksheet* sheet, lxw_col_t first, lxw_col_t last, uint32_t pixels,
                      const std::filesystem::path& path);

/// Throws InputError "cannot write PATH: WHY".
[[noreturn]] void fail_workbook(const std::filesystem::path& path, const std::string& why);

/// fail_workbook with libxlsxwriter's words unless `error` is LXW_NO_ERROR.
void check_workbook(lxw_error error, const std::filesystem::path& path);

}  // namespace hikari
