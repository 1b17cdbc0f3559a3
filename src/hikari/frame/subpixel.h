#pragma once
// Where a pixel's samples lie when a method takes several (`--spp N`): the same points in every
// pixel and in every method, so that a ray-traced and a rasterized image at equal N sample the
// same scene points and agree edge pixel for edge pixel.

#include "hikari/core/rng.h"
#include "hikari/core/strata.h"
#include "hikari/core/vec.h"

namespace hikari {

/// Sample s of n inside a pixel, as an offset from its top-left corner in [0, 1)²: the cell
/// (s mod cols, s div cols) of the most square grid cols × rows = n (core/strata.h), jittered
/// inside the cell by a random stream seeded by s alone (stratified sampling: Mitchell 1996).
inline Vec2 subpixel_sample(int s, int n) {
    int cols = 1, rows = 1;
    strata(n, cols, rows);
    Pcg32 stream(static_cast<uint64_t>(s), 0x68696b617269ULL);
    const float jitter_x = stream.next_float(), jitter_y = stream.next_float();
    const int column = s % cols, row = s / cols;
    return {(static_cast<float>(column) + jitter_x) / static_cast<float>(cols),
            (static_cast<float>(row) + jitter_y) / static_cast<float>(rows)};
}

}  // namespace hikari
