#include "hikari/io/read_file.h"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>

#include "hikari/core/error.h"
#include "hikari/core/huge_page_allocator.h"

namespace hikari {

namespace {

[[noreturn]] void throw_read_error(const std::filesystem::path& path, int error) {
    throw InputError(path.string() + ": cannot read: " + std::strerror(error));
}

}  // namespace

std::string read_file_bytes(const std::filesystem::path& path) {
    // stdio rather than iostreams: POSIX fopen/fread set errno, so the message can say why.
    errno = 0;
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                         &std::fclose);
    if (!file) throw_read_error(path, errno);
    std::string bytes;
    // A regular file's size, when known, sizes the string once, mapped in one call: growing it
    // by doubling would copy and fault in about three times the file (docs/performance.md).
    std::error_code size_error;
    const std::uintmax_t size = std::filesystem::file_size(path, size_error);
    if (!size_error && size < bytes.max_size()) {
        bytes.reserve(static_cast<size_t>(size));
        populate_pages(bytes.data(), static_cast<size_t>(size));
    }
    char buffer[1 << 16];
    for (;;) {
        const size_t n = std::fread(buffer, 1, sizeof buffer, file.get());
        bytes.append(buffer, n);
        if (n < sizeof buffer) break;
    }
    if (std::ferror(file.get())) throw_read_error(path, errno != 0 ? errno : EIO);
    return bytes;
}

}  // namespace hikari
