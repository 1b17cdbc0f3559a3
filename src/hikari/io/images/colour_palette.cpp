#include "hikari/io/images/colour_palette.h"

#include <algorithm>
#include <numeric>

namespace hikari {

namespace {

/// A distinct colour of the image, as 0xRRGGBB, and how many pixels have it.
struct ColourCount {
    uint32_t rgb;
    uint32_t count;
    int channel(int c) const { return static_cast<int>((rgb >> (16 - 8 * c)) & 0xffu); }
};

/// Colours [first, last) of the sorted distinct colours, and their extent.
struct Box {
    size_t first, last;
    uint64_t pixels = 0;
    int longest = 0;  ///< channel of the widest extent
    int extent = 0;   ///< its width (0: one colour, cannot split)
};

Box make_box(const std::vector<ColourCount>& colours, size_t first, size_t last) {
    Box b{first, last};
    int lo[3] = {255, 255, 255}, hi[3] = {0, 0, 0};
    for (size_t i = first; i < last; ++i) {
        b.pixels += colours[i].count;
        for (int c = 0; c < 3; ++c) {
            lo[c] = std::min(lo[c], colours[i].channel(c));
            hi[c] = std::max(hi[c], colours[i].channel(c));
        }
    }
    for (int c = 0; c < 3; ++c)
        if (hi[c] - lo[c] > b.extent) b.extent = hi[c] - lo[c], b.longest = c;
    return b;
}

}  // namespace

PalettedImage median_cut(const Srgb8Image& image, int max_colours) {
    PalettedImage out;
    out.width = image.width;
    out.height = image.height;
    const size_t n = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
    std::vector<uint32_t> keys(n);
    for (size_t i = 0; i < n; ++i)
        keys[i] = (uint32_t{image.bytes[3 * i]} << 16) | (uint32_t{image.bytes[3 * i + 1]} << 8) |
                  image.bytes[3 * i + 2];
    std::vector<uint32_t> sorted = keys;
    std::sort(sorted.begin(), sorted.end());
    std::vector<ColourCount> colours;
    for (size_t i = 0; i < n;) {
        size_t j = i;
        while (j < n && sorted[j] == sorted[i]) ++j;
        colours.push_back({sorted[i], static_cast<uint32_t>(j - i)});
        i = j;
    }
    if (colours.empty()) return out;

    // Split the box with the most pixels among those that can still be split.
    std::vector<Box> boxes{make_box(colours, 0, colours.size())};
    while (boxes.size() < static_cast<size_t>(std::max(max_colours, 1))) {
        size_t pick = boxes.size();
        for (size_t b = 0; b < boxes.size(); ++b)
            if (boxes[b].extent > 0 &&
                (pick == boxes.size() || boxes[b].pixels > boxes[pick].pixels))
                pick = b;
        if (pick == boxes.size()) break;  // every box is one colour
        const Box box = boxes[pick];
        const int c = box.longest;
        std::sort(colours.begin() + static_cast<std::ptrdiff_t>(box.first),
                  colours.begin() + static_cast<std::ptrdiff_t>(box.last),
                  [c](const ColourCount& a, const ColourCount& b) {
                      return a.channel(c) < b.channel(c) ||
                             (a.channel(c) == b.channel(c) && a.rgb < b.rgb);
                  });
        // The median pixel, kept off both ends so that both halves hold a colour.
        uint64_t seen = 0;
        size_t split = box.first + 1;
        for (size_t i = box.first; i + 1 < box.last; ++i) {
            seen += colours[i].count;
            split = i + 1;
            if (2 * seen >= box.pixels) break;
        }
        boxes[pick] = make_box(colours, box.first, split);
        boxes.push_back(make_box(colours, split, box.last));
    }

    // Each box's mean colour; each distinct colour's box, found by its key.
    std::vector<std::pair<uint32_t, uint16_t>> box_of;
    box_of.reserve(colours.size());
    for (size_t b = 0; b < boxes.size(); ++b) {
        uint64_t sum[3] = {0, 0, 0};
        for (size_t i = boxes[b].first; i < boxes[b].last; ++i) {
            for (int c = 0; c < 3; ++c)
                sum[c] += static_cast<uint64_t>(colours[i].channel(c)) * colours[i].count;
            box_of.emplace_back(colours[i].rgb, static_cast<uint16_t>(b));
        }
        std::array<uint8_t, 3> mean{};
        for (int c = 0; c < 3; ++c)
            mean[static_cast<size_t>(c)] =
                static_cast<uint8_t>((sum[c] + boxes[b].pixels / 2) / boxes[b].pixels);
        out.palette.push_back(mean);
    }
    std::sort(box_of.begin(), box_of.end());
    out.index.resize(n);
    for (size_t i = 0; i < n; ++i)
        out.index[i] = std::lower_bound(box_of.begin(), box_of.end(),
                                        std::pair<uint32_t, uint16_t>{keys[i], 0})
                           ->second;
    return out;
}

}  // namespace hikari
