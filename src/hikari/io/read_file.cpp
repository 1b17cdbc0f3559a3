#include "hikari/io/read_file.h"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/core/huge_page_allocator.h"

namespace hikari {

namespace {

[[noreturn]] void throw_read_error(const std::filesystem::path& path, int error) {
    throw InputError(path.string() + ": cannot read: " + std::strerror(error));
}

/// What a file that is not a regular one is, for the message.
const char* kind_of(std::filesystem::file_type type) {
    switch (type) {
        case std::filesystem::file_type::directory:
            return "a directory";
        case std::filesystem::file_type::block:
        case std::filesystem::file_type::character:
            return "a device";
        case std::filesystem::file_type::fifo:
            return "a FIFO";
        case std::filesystem::file_type::socket:
            return "a socket";
        default:
            return "not a regular file";
    }
}

}  // namespace

std::string read_file_bytes(const std::filesystem::path& path, std::uintmax_t max_bytes) {
    // Refused before opening: fopen blocks on a FIFO until a writer comes, and a device such as
    // /dev/zero never ends.
    std::error_code status_error;
    const std::filesystem::file_status status = std::filesystem::status(path, status_error);
    if (!status_error && std::filesystem::exists(status) &&
        !std::filesystem::is_regular_file(status)) {
        throw InputError(path.string() + ": cannot read: " + kind_of(status.type()) +
                         ", not a file");
    }
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
    const auto too_large = [&] {
        throw InputError(fmt::format("{}: cannot read: larger than the limit of {} bytes",
                                     path.string(), max_bytes));
    };
    if (!size_error && size > max_bytes) too_large();
    if (!size_error && size < bytes.max_size()) {
        bytes.reserve(static_cast<size_t>(size));
        populate_pages(bytes.data(), static_cast<size_t>(size));
    }
    char buffer[1 << 16];
    for (;;) {
        const size_t n = std::fread(buffer, 1, sizeof buffer, file.get());
        bytes.append(buffer, n);
        if (bytes.size() > max_bytes) too_large();
        if (n < sizeof buffer) break;
    }
    if (std::ferror(file.get())) throw_read_error(path, errno != 0 ? errno : EIO);
    return bytes;
}

}  // namespace hikari
