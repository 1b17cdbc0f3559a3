// One image shared by tiles among processes (frame/tile_share.h), played here by three renders
// of one session: each renders its tiles, and the combine hook gathers them into the last,
// which must then equal the whole image bit for bit, light-traced caustics and AOVs included.
// (tests/mpi/ runs the same through mpirun.)

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hikari/frame/tile_exchange.h"
#include "hikari/session/session.h"

namespace hikari {
namespace {

/// The three parts' renders of `request`, gathered into part 0's framebuffer: the parts run one
/// after another, so each part's combine keeps its bytes (and its caustic sums) for part 0.
Framebuffer shared_render(Session& session, RenderRequest request) {
    constexpr int k_parts = 3;
    std::array<std::vector<std::byte>, k_parts> tiles;
    std::vector<int64_t> summed;  // the light tracer's sums over the parts rendered so far
    std::array<std::vector<int64_t>, k_parts> own_sums;
    // Pass 1: every part's own sums; pass 2: every part's tiles with the sums of all.
    for (const bool gather : {false, true}) {
        Framebuffer whole;
        for (int part = k_parts - 1; part >= 0; --part) {
            TileShare share;
            share.part = part;
            share.parts = k_parts;
            share.sum_over_parts = [&, part, gather](std::span<int64_t> sums) {
                if (!gather) {
                    own_sums[size_t(part)].assign(sums.begin(), sums.end());
                    return;
                }
                for (size_t i = 0; i < sums.size(); ++i) {
                    int64_t total = 0;
                    for (const auto& own : own_sums) total += own.empty() ? 0 : own[i];
                    sums[i] = total;
                }
            };
            share.combine = [&, part](Framebuffer& fb) {
                if (part != 0) {
                    tiles[size_t(part)] = pack_tiles(fb, part, k_parts);
                    return;
                }
                for (int other = 1; other < k_parts; ++other)
                    unpack_tiles(fb, tiles[size_t(other)], other, k_parts);
            };
            request.tile_share = &share;
            RenderResult result = session.render(request);
            if (part == 0) whole = std::move(result.framebuffer);
        }
        if (gather) return whole;
    }
    return {};
}

bool same_buffers(const Framebuffer& a, const Framebuffer& b) {
    return a.film.linear().pixels == b.film.linear().pixels && a.depth == b.depth && a.id == b.id &&
           a.normal == b.normal;
}

TEST(TileShareRender, PathWithCausticsGatheredEqualsOneRender) {
    Session session({.file = std::string(HIKARI_SOURCE_DIR) + "/scenes/cornell-glass.json"});
    RenderRequest request;
    request.method = "path";
    request.width = 37;
    request.height = 29;
    request.options.samples_per_pixel = 2;
    const Framebuffer one = session.render(request).framebuffer;
    EXPECT_TRUE(same_buffers(shared_render(session, request), one));
}

TEST(TileShareRender, WhittedGatheredEqualsOneRenderAndOtherMethodsIgnoreTheShare) {
    Session session({.file = std::string(HIKARI_SOURCE_DIR) + "/scenes/assignment.json"});
    for (const char* method : {"raytrace", "zbuffer"}) {
        RenderRequest request;
        request.method = method;
        request.width = 41;
        request.height = 23;
        const Framebuffer one = session.render(request).framebuffer;
        EXPECT_TRUE(same_buffers(shared_render(session, request), one)) << method;
    }
}

}  // namespace
}  // namespace hikari
