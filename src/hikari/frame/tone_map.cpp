#include "hikari/frame/tone_map.h"

#include <cmath>

#include "hikari/core/parallel.h"

namespace hikari {

namespace {

// Reinhard, Stark, Shirley & Ferwerda 2002, "Photographic Tone Reproduction for Digital
// Images", eq. 3 (the simple operator), applied per channel.
float reinhard(float c) {
    if (!(c > 0.0f)) return 0.0f;  // also NaN
    if (std::isinf(c)) return 1.0f;
    return c / (1.0f + c);
}

// Narkowicz 2015, "ACES Filmic Tone Mapping Curve" (knarkowicz.wordpress.com): a rational fit
// of the ACES reference rendering transform, clamped to [0, 1].
float aces(float x) {
    if (!(x > 0.0f)) return 0.0f;  // also NaN
    // Past x ≈ 7.3 the curve is above 1 and clamps; stopping early keeps x² finite.
    if (x > 1e4f) return 1.0f;
    const float y = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
    return std::fmin(y, 1.0f);
}

}  // namespace

float tone_map(float c, ToneMap op) {
    switch (op) {
        case ToneMap::clamp:
            return c;
        case ToneMap::reinhard:
            return reinhard(c);
        case ToneMap::aces:
            return aces(c);
    }
    return c;
}

void expose_and_tone_map(Image& image, float exposure_ev, ToneMap op) {
    if (exposure_ev == 0.0f && op == ToneMap::clamp) return;
    const float scale = std::exp2(exposure_ev);
    hikari::parallel_for(0, image.height, [&](int y) {
        for (int x = 0; x < image.width; ++x) {
            Vec3& p = image.at(x, y);
            for (int c = 0; c < 3; ++c) p[c] = tone_map(p[c] * scale, op);
        }
    });
}

}  // namespace hikari
