#include "hikari/shading/textures/mip_pyramid.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "hikari/core/cancel.h"
#include "hikari/core/parallel.h"

namespace hikari {

namespace {

/// One output texel's share of the input along an axis: input texels [first, first +
/// weights.size()) with their weights, which sum to 1.
struct Footprint1d {
    int first = 0;
    std::vector<float> weights;
};

/// For each of `out` texels along an axis of `in` texels: the input texels its interval
/// [j·in/out, (j + 1)·in/out) overlaps, weighted by the overlap's length.
std::vector<Footprint1d> box_footprints(int in, int out) {
    std::vector<Footprint1d> footprints(static_cast<size_t>(out));
    const double scale = static_cast<double>(in) / out;
    for (int j = 0; j < out; ++j) {
        const double lo = j * scale, hi = (j + 1) * scale;
        Footprint1d& f = footprints[static_cast<size_t>(j)];
        f.first = static_cast<int>(std::floor(lo));
        const int last = std::min(in - 1, static_cast<int>(std::ceil(hi)) - 1);
        for (int i = f.first; i <= last; ++i) {
            const double overlap = std::min<double>(hi, i + 1) - std::max<double>(lo, i);
            f.weights.push_back(static_cast<float>(overlap / scale));
        }
    }
    return footprints;
}

}  // namespace

int next_mip_size(int size) { return std::max(1, size / 2); }

Image box_downsample(const Image& image, int width, int height) {
    const std::vector<Footprint1d> across = box_footprints(image.width, width);
    const std::vector<Footprint1d> down = box_footprints(image.height, height);
    // Separable: rows first into `wide` (width × image.height), then columns.
    Image wide(width, image.height);
    Image out(width, height);
    hikari::parallel_for(tbb::blocked_range<int>(0, image.height), [&](const auto& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y) {
            for (int x = 0; x < width; ++x) {
                const Footprint1d& f = across[static_cast<size_t>(x)];
                Vec3 sum(0.0f);
                for (size_t k = 0; k < f.weights.size(); ++k)
                    sum += image.at(f.first + static_cast<int>(k), y) * f.weights[k];
                wide.at(x, y) = sum;
            }
        }
    });
    hikari::parallel_for(tbb::blocked_range<int>(0, height), [&](const auto& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y) {
            const Footprint1d& f = down[static_cast<size_t>(y)];
            for (int x = 0; x < width; ++x) {
                Vec3 sum(0.0f);
                for (size_t k = 0; k < f.weights.size(); ++k)
                    sum += wide.at(x, f.first + static_cast<int>(k)) * f.weights[k];
                out.at(x, y) = sum;
            }
        }
    });
    return out;
}

MipPyramid build_mip_pyramid(Image base) {
    // A float file's NaN or infinity would spread through every coarser level.
    for (Vec3& texel : base.pixels)
        if (!is_finite(texel)) texel = Vec3(0.0f);
    MipPyramid pyramid;
    pyramid.levels.push_back(std::move(base));
    while (pyramid.levels.back().width > 1 || pyramid.levels.back().height > 1) {
        throw_if_cancelled();  // SIGINT / SIGTERM: once per level
        const Image& last = pyramid.levels.back();
        Image next = box_downsample(last, next_mip_size(last.width), next_mip_size(last.height));
        pyramid.levels.push_back(std::move(next));
    }
    return pyramid;
}

}  // namespace hikari
