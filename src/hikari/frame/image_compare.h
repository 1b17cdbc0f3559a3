#pragma once
// Comparing two images, as `hikari compare` reports it: how close two methods' pictures are.

#include <cstddef>

#include "hikari/core/image.h"

namespace hikari {

/// How two images of one size differ.
struct ImageDifference {
    /// PSNR in dB over the sRGB-encoded values in [0, 1] (clamped), RGB channels, peak 1: for
    /// two 8-bit images the PSNR image tools report (peak 255 over the bytes). Infinity for
    /// equal images.
    double psnr_db = 0;
    double max_difference = 0;  ///< the largest |a − b| of an encoded channel value
    int max_x = 0, max_y = 0;   ///< the pixel where it is (the first, row by row)
    size_t differing = 0;       ///< pixels where a channel's linear values differ by > tolerance
    size_t pixels = 0;
    size_t not_a_number_a = 0;  ///< pixels of `a` with a NaN channel
    size_t not_a_number_b = 0;  ///< pixels of `b` with a NaN channel
};

/// Compares `a` and `b` (the same size). `eight_bit`: the encoded values are rounded to
/// multiples of 1/255 first, as 8-bit files store them (so the float round trip of decoding
/// adds nothing). Pixels differ where some channel's linear values differ by more than
/// `tolerance`. NaN is one value: a channel NaN in both images is equal, NaN in one only differs
/// by the most an encoded value can (1), in PSNR, the largest difference and the count alike.
ImageDifference compare_images(const Image& a, const Image& b, bool eight_bit = false,
                               float tolerance = 0.0f);

/// A false-colour picture of where `a` and `b` differ: each pixel's largest encoded channel
/// difference d as black (0), blue (scale/3), red (2·scale/3), yellow (scale and above); equal
/// pixels black. Linear RGB, for write_image.
Image difference_image(const Image& a, const Image& b, double scale);

}  // namespace hikari
