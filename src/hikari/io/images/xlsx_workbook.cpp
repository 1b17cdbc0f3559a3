#include "hikari/io/images/xlsx_workbook.h"

#include <unistd.h>

#include <atomic>

#include <fmt/format.h>

#include "hikari/core/error.h"

namespace hikari {

TemporaryWorkbook::TemporaryWorkbook() {
    static std::atomic<unsigned> counter{0};
    m_path = std::filesystem::temp_directory_path() /
             fmt::format("hikari-{}-{}.xlsx", ::getpid(), counter++);
}

TemporaryWorkbook::~TemporaryWorkbook() {
    std::error_code ignored;
    std::filesystem::remove(m_path, ignored);
}

void fail_workbook(const std::filesystem::path& path, const std::string& why) {
    throw InputError(fmt::format("cannot write {}: {}", path.string(), why));
}

void check_workbook(lxw_error error, const std::filesystem::path& path) {
    if (error != LXW_NO_ERROR) fail_workbook(path, lxw_strerror(error));
}

}  // namespace hikari
