#pragma once
// A linear-RGB float image, what methods render into, and its 8-bit sRGB form, what PNG and PPM
// files hold.

#include <cstddef>
#include <cstdint>
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

/// Row-major 8-bit sRGB RGB triples, row 0 at the top (linear_to_srgb8 of each channel): a
/// quarter of the memory of an Image, for renders whose only output is a PNG or PPM file.
struct Srgb8Image {
    int width = 0;
    int height = 0;
    /// 3 per pixel. A new image's bytes are not initialised: whoever makes one writes them all.
    std::vector<uint8_t, UninitializedHugePageAllocator<uint8_t>> bytes;

    Srgb8Image() = default;
    /// An image whose bytes the caller must all write.
    Srgb8Image(int w, int h)
        : width(w), height(h), bytes(static_cast<size_t>(w) * static_cast<size_t>(h) * 3) {}

    uint8_t* row(int y) { return bytes.data() + static_cast<size_t>(y) * width * 3; }
    const uint8_t* row(int y) const { return bytes.data() + static_cast<size_t>(y) * width * 3; }
};

}  // namespace hikari
