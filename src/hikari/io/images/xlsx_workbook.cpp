#include "hikari/io/images/xlsx_workbook.h"

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/io/files/atomic_file.h"
#include "hikari/io/files/read_file.h"

namespace hikari {

std::vector<uint8_t> build_workbook(const std::filesystem::path& output,
                                    const std::function<void(lxw_workbook*)>& fill) {
    const TemporaryFile file(output);
    std::string directory = output.has_parent_path() ? output.parent_path().string() : ".";
    lxw_workbook_options options{};
    options.constant_memory = LXW_TRUE;
    options.tmpdir = directory.data();
    lxw_workbook* book = workbook_new_opt(file.path().c_str(), &options);
    if (!book) fail_workbook(output, "libxlsxwriter could not start a workbook");
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

void fail_workbook(const std::filesystem::path& path, const std::string& why) {
    throw InputError(fmt::format("cannot write {}: {}", path.string(), why));
}

void check_workbook(lxw_error error, const std::filesystem::path& path) {
    if (error != LXW_NO_ERROR) fail_workbook(path, lxw_strerror(error));
}

}  // namespace hikari
