#pragma once
// Helpers shared by the raster/ tests: scenes from JSON text and image comparisons.

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "../support/scene_files.h"
#include "hikari/frame/framebuffer.h"
#include "hikari/io/scene/scene_json.h"

namespace hikari::testing {

/// A scene parsed from JSON text, meshes resolved against the repository root.
inline Scene raster_scene_from(const std::string& json) {
    std::vector<std::string> warnings;
    return parse_scene(json, "test.json", HIKARI_SOURCE_DIR, warnings);
}

/// Fraction of pixels whose id buffers agree.
inline double id_agreement(const Framebuffer& a, const Framebuffer& b) {
    size_t same = 0;
    for (size_t i = 0; i < a.id.size(); ++i) same += a.id[i] == b.id[i];
    return static_cast<double>(same) / static_cast<double>(a.id.size());
}

/// PSNR in dB of two colour buffers with peak 1 (colours clamped to [0, 1] as an 8-bit image
/// would show them).
inline double psnr(const Framebuffer& a, const Framebuffer& b) {
    double sum = 0;
    for (size_t i = 0; i < a.film.linear().pixels.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            const double d = std::clamp(a.film.linear().pixels[i][k], 0.0f, 1.0f) -
                             std::clamp(b.film.linear().pixels[i][k], 0.0f, 1.0f);
            sum += d * d;
        }
    const double mse = sum / (3.0 * static_cast<double>(a.film.linear().pixels.size()));
    return mse > 0 ? 10 * std::log10(1.0 / mse) : 1000.0;
}

/// A closed box from `lo` to `hi` as 12 triangle objects of scene JSON (comma-separated, for an
/// "objects" list), wound outward, material "m".
inline std::string box(Vec3 lo, Vec3 hi) {
    std::string out;
    const Vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z},
                       {lo.x, hi.y, lo.z}, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z},
                       {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                             {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    auto v = [&](int i) { return fmt::format("[{}, {}, {}]", c[i].x, c[i].y, c[i].z); };
    for (const auto& q : quads)
        out += fmt::format(
            R"({}{{"type": "triangle", "vertices": [{}, {}, {}], "material": "m"}}, {{"type": "triangle", "vertices": [{}, {}, {}], "material": "m"}})",
            out.empty() ? "" : ", ", v(q[0]), v(q[1]), v(q[2]), v(q[0]), v(q[2]), v(q[3]));
    return out;
}

}  // namespace hikari::testing
