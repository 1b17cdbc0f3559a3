#pragma once
// Pictures of one scene by several methods, placed side by side, each under a strip naming its
// method (`hikari render -m a,b,c --side-by-side`): one picture in which the methods compare at a
// glance, and one frame of a video that shows them all at once.

#include <span>
#include <string>

#include "hikari/core/image.h"

namespace hikari {

/// Picture pixels between two panels.
constexpr int k_panel_gap = 2;

/// The size of side_by_side's picture.
struct PictureSize {
    int width = 0, height = 0;
};

/// The size of side_by_side's picture of panels of `panel` size labelled `labels` (one per
/// panel): the panels and the gaps between them wide; a label strip taller, 12 font pixels (the
/// font's 9 and a margin) at the labels' scale, so an even panel height stays even.
PictureSize side_by_side_size(PictureSize panel, std::span<const std::string> labels);

/// `panels` (one size, at least one) left to right, k_panel_gap pixels apart, each under a light
/// strip with `labels[i]` centred in dark text (frame/bitmap_font.h: at twice the font's size
/// when every label fits its panel so, else at its size, cut at the panel's edge if still too
/// wide). `labels` has one entry per panel.
Srgb8Image side_by_side(std::span<const Srgb8Image> panels, std::span<const std::string> labels);

}  // namespace hikari
