#pragma once
// What the two workbook writers share: libxlsxwriter writes only to files, so a workbook is
// built in a temporary file, checked call by call, and read back as bytes.

#include <xlsxwriter.h>

#include <filesystem>
#include <string>

namespace hikari {

/// A workbook file in the temporary directory, removed when this goes out of scope (the bytes
/// are then written atomically to the real output).
class TemporaryWorkbook {
  public:
    TemporaryWorkbook();
    ~TemporaryWorkbook();
    TemporaryWorkbook(const TemporaryWorkbook&) = delete;
    TemporaryWorkbook& operator=(const TemporaryWorkbook&) = delete;
    const std::filesystem::path& path() const { return m_path; }

  private:
    std::filesystem::path m_path;
};

/// Throws InputError "cannot write PATH: WHY".
[[noreturn]] void fail_workbook(const std::filesystem::path& path, const std::string& why);

/// fail_workbook with libxlsxwriter's words unless `error` is LXW_NO_ERROR.
void check_workbook(lxw_error error, const std::filesystem::path& path);

}  // namespace hikari
