#pragma once
// A linear-RGB float image: what methods render into and what io/ writes out.

#include <cstddef>
#include <vector>

#include "hikari/core/huge_page_allocator.h"
#include "hikari/core/vec.h"

namespace hikari {

/// Row-major RGB pixels, row 0 at the top.
struct Image {
    int width = 0;
    int height = 0;
    HugePageVector<Vec3> pixels;  ///< huge pages: a full-HD image is 6000 page faults without

    Image() = default;
    Image(int w, int h, Vec3 fill = Vec3(0.0f))
        : width(w), height(h), pixels(static_cast<size_t>(w) * static_cast<size_t>(h), fill) {}

    Vec3& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
    const Vec3& at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
};

}  // namespace hikari
