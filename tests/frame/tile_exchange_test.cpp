// A framebuffer's tiles packed by one process and unpacked by another (frame/tile_exchange.h):
// the gathered buffers are the whole image, every buffer and both film formats.

#include "hikari/frame/tile_exchange.h"

#include <cstdint>
#include <stdexcept>

#include <gtest/gtest.h>

#include "hikari/frame/tiles.h"

namespace hikari {
namespace {

/// A framebuffer whose every buffer says which pixel it is, offset by `seed`.
Framebuffer numbered(FilmFormat format, int width, int height, bool aovs, uint32_t seed) {
    Framebuffer fb(Film(width, height, format), width, height, aovs);
    for (size_t i = 0; i < size_t(width) * height; ++i) {
        const float v = float(i + seed);
        fb.set_color(i, Vec3(v / 4096.0f, 0.5f, 1.0f - v / 8192.0f));
        if (!aovs) continue;
        fb.depth[i] = v;
        fb.id[i] = uint32_t(i) + seed;
        fb.normal[i] = Vec3(v, -v, 0.0f);
    }
    return fb;
}

bool same_pixels(const Framebuffer& a, const Framebuffer& b) {
    const bool film = a.film.format() == FilmFormat::srgb8
                          ? a.film.srgb8().bytes == b.film.srgb8().bytes
                          : a.film.linear().pixels == b.film.linear().pixels;
    return film && a.depth == b.depth && a.id == b.id && a.normal == b.normal;
}

TEST(TileExchange, EveryPartsTilesGatheredMakeTheWholeImage) {
    // 37 × 21: part tiles on the right and bottom edges; 3 parts over 3 × 2 tiles.
    for (const FilmFormat format : {FilmFormat::linear, FilmFormat::srgb8})
        for (const bool aovs : {true, false}) {
            const Framebuffer whole = numbered(format, 37, 21, aovs, 0);
            Framebuffer gathered = numbered(format, 37, 21, aovs, 7);  // every pixel wrong
            for (int part = 0; part < 3; ++part)
                unpack_tiles(gathered, pack_tiles(whole, part, 3), part, 3);
            EXPECT_TRUE(same_pixels(gathered, whole)) << aovs;
        }
}

TEST(TileExchange, OnePartWritesOnlyItsTiles) {
    const Framebuffer whole = numbered(FilmFormat::linear, 40, 40, true, 0);
    const Framebuffer before = numbered(FilmFormat::linear, 40, 40, true, 99);
    Framebuffer fb = before;
    unpack_tiles(fb, pack_tiles(whole, 1, 2), 1, 2);
    const TileShare share{1, 2, {}};
    for (int64_t t = 0; t < tile_count(40, 40); ++t) {
        const Tile tile = tile_at(t, 40, 40);
        const size_t corner = size_t(tile.y0) * 40 + size_t(tile.x0);
        EXPECT_EQ(fb.id[corner], (share.owns(t) ? whole : before).id[corner]) << t;
    }
}

TEST(TileExchange, BytesOfAnotherSizeAreRefused) {
    Framebuffer fb = numbered(FilmFormat::linear, 20, 20, false, 0);
    std::vector<std::byte> bytes = pack_tiles(fb, 0, 2);
    bytes.pop_back();
    EXPECT_THROW(unpack_tiles(fb, bytes, 0, 2), std::invalid_argument);
}

TEST(TileShare, PartsOwnEveryTileOnce) {
    for (const int parts : {1, 2, 3, 7}) {
        int64_t owned = 0;
        for (int part = 0; part < parts; ++part) {
            const TileShare share{part, parts, {}};
            int64_t mine = 0;
            for (int64_t t = 0; t < 23; ++t) mine += share.owns(t) ? 1 : 0;
            EXPECT_EQ(mine, share.owned_of(23)) << part << " of " << parts;
            owned += mine;
        }
        EXPECT_EQ(owned, 23);
    }
}

}  // namespace
}  // namespace hikari
