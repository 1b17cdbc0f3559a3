#include "hikari/io/files/read_file.h"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>

#include <fmt/format.h>

#include "hikari/core/error.h"
#include "hikari/core/huge_page_allocator.h"
#include "hikari/core/memory_budget.h"
#include "hikari/io/files/printable_text.h"

namespace hikari {

namespace {

[[noreturn]] void throw_read_error(const std::filesystem::path& path, int error) {
    throw InputError(printable_text(path.string() + ": cannot read: " + std::strerror(error)));
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

/// read_file_bytes() with `too_large` as the end of the message for a file over `max_bytes`.
std::string read_bounded(const std::filesystem::path& path, std::uintmax_t max_bytes,
                         const std::string& too_large_reason, const FileFormatCheck& check = {});

}  // namespace

std::string read_file_bytes(const std::filesystem::path& path, std::uintmax_t max_bytes) {
    return read_bounded(path, max_bytes,
                        fmt::format("larger than the limit of {} bytes", max_bytes));
}

std::string read_file_bytes(const std::filesystem::path& path, InputKind kind) {
    return read_file_bytes(path, kind, FileFormatCheck{});
}

std::string read_file_bytes(const std::filesystem::path& path, InputKind kind,
                            const FileFormatCheck& check) {
    const std::uintmax_t max_bytes = input_limit(kind);
    const auto size = static_cast<double>(max_bytes);
    const std::string limit = max_bytes >= (1u << 30) ? fmt::format("{:.3g} GiB", size / (1 << 30))
                              : max_bytes >= (1u << 20)
                                  ? fmt::format("{:.3g} MiB", size / (1 << 20))
                                  : fmt::format("{} bytes", max_bytes);
    return read_bounded(
        path, max_bytes,
        fmt::format("larger than the limit of {} for {} {} file (raise it with "
                    "--max-input-size)",
                    limit, kind == InputKind::image ? "an" : "a", input_kind_name(kind)),
        check);
}

namespace {

std::string read_bounded(const std::filesystem::path& path, std::uintmax_t max_bytes,
                         const std::string& too_large_reason, const FileFormatCheck& check) {
    // Refused before opening: fopen blocks on a FIFO until a writer comes, and a device such as
    // /dev/zero never ends.
    std::error_code status_error;
    const std::filesystem::file_status status = std::filesystem::status(path, status_error);
    if (!status_error && std::filesystem::exists(status) &&
        !std::filesystem::is_regular_file(status)) {
        throw InputError(printable_text(path.string() + ": cannot read: " + kind_of(status.type()) +
                                        ", not a file"));
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
        throw InputError(
            printable_text(fmt::format("{}: cannot read: {}", path.string(), too_large_reason)));
    };
    if (!size_error && size > max_bytes) too_large();
    if (!size_error) {
        check_memory_need(check.memory_per_byte * static_cast<double>(size),
                          fmt::format("{} {} ({})", check.what, path.string(),
                                      memory_size_text(static_cast<double>(size))));
    }
    if (check.check_head) {
        char head[k_file_head_bytes];
        const size_t n = std::fread(head, 1, sizeof head, file.get());
        if (std::ferror(file.get())) throw_read_error(path, errno != 0 ? errno : EIO);
        check.check_head(std::string_view(head, n), size_error ? n : size);
        bytes.append(head, n);
        if (n < sizeof head) return bytes;
    }
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

}  // namespace

}  // namespace hikari
