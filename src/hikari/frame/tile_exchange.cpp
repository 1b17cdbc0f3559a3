#include "hikari/frame/tile_exchange.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "hikari/frame/tiles.h"

namespace hikari {

namespace {

/// One buffer of a framebuffer as bytes (`Byte`: std::byte, const for reading): `pixel_bytes`
/// per pixel, rows of the framebuffer's width.
template <class Byte>
struct PixelBytes {
    Byte* data;
    size_t pixel_bytes;
};

/// Every buffer `fb` holds, colour first.
template <class Byte, class Fb>
std::vector<PixelBytes<Byte>> buffers_of(Fb& fb) {
    auto bytes = [](auto* p) { return reinterpret_cast<Byte*>(p); };
    std::vector<PixelBytes<Byte>> buffers;
    if (fb.film.format() == FilmFormat::srgb8)
        buffers.push_back({bytes(fb.film.srgb8().bytes.data()), 3});
    else
        buffers.push_back({bytes(fb.film.linear().pixels.data()), sizeof(Vec3)});
    if (!fb.depth.empty()) buffers.push_back({bytes(fb.depth.data()), sizeof(float)});
    if (!fb.id.empty()) buffers.push_back({bytes(fb.id.data()), sizeof(uint32_t)});
    if (!fb.normal.empty()) buffers.push_back({bytes(fb.normal.data()), sizeof(Vec3)});
    return buffers;
}

/// Calls `copy(row, size)` for each row of each tile of `part` in each buffer of `fb`, in the
/// order pack_tiles writes them.
template <class Byte, class Fb, class Copy>
void for_each_tile_row(Fb& fb, int part, int parts, Copy&& copy) {
    const int width = fb.width(), height = fb.height();
    const TileShare share{part, parts, {}};
    for (const PixelBytes<Byte>& buffer : buffers_of<Byte>(fb))
        for (int64_t t = 0, n = tile_count(width, height); t < n; ++t) {
            if (!share.owns(t)) continue;
            const Tile tile = tile_at(t, width, height);
            for (int y = tile.y0; y < tile.y1; ++y) {
                const size_t first = static_cast<size_t>(y) * static_cast<size_t>(width) +
                                     static_cast<size_t>(tile.x0);
                copy(buffer.data + first * buffer.pixel_bytes,
                     static_cast<size_t>(tile.x1 - tile.x0) * buffer.pixel_bytes);
            }
        }
}

}  // namespace

std::vector<std::byte> pack_tiles(const Framebuffer& fb, int part, int parts) {
    std::vector<std::byte> bytes;
    for_each_tile_row<const std::byte>(fb, part, parts, [&](const std::byte* row, size_t size) {
        bytes.insert(bytes.end(), row, row + size);
    });
    return bytes;
}

void unpack_tiles(Framebuffer& fb, std::span<const std::byte> bytes, int part, int parts) {
    size_t expected = 0;
    for_each_tile_row<std::byte>(fb, part, parts,
                                 [&](std::byte*, size_t size) { expected += size; });
    if (bytes.size() != expected)
        throw std::invalid_argument(
            fmt::format("tiles of part {} of {}: {} bytes where the framebuffer's take {}", part,
                        parts, bytes.size(), expected));
    size_t at = 0;
    for_each_tile_row<std::byte>(fb, part, parts, [&](std::byte* row, size_t size) {
        std::memcpy(row, bytes.data() + at, size);
        at += size;
    });
}

}  // namespace hikari
