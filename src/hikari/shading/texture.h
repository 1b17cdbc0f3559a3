#pragma once
// Every texture kind's evaluation behind one call (one file per kind in shading/textures/).

#include <type_traits>

#include "hikari/core/lanes.h"
#include "hikari/core/visit.h"
#include "hikari/scene/texture.h"
#include "hikari/shading/surface.h"
#include "hikari/shading/textures/checker_texture.h"
#include "hikari/shading/textures/image_texture.h"

namespace hikari {

/// Whether packs of number type F evaluate `texture` themselves; where not, their lanes fall
/// back to the scalar code (MaterialSample::scalar_only); see k_texture_has_lane_form.
template <class F>
HIKARI_INLINE HIKARI_HD bool texture_has_lanes(const Texture& texture) {
    if constexpr (k_is_scalar<F>) return true;
    return visit_kind(texture, [](const auto& kind) {
        return k_texture_has_lane_form<std::decay_t<decltype(kind)>>;
    });
}

/// The texture's linear RGB colour at `point`.
template <class F>
HIKARI_INLINE HIKARI_HD Vec3T<F> texture_colour(const Texture& texture,
                                                const SurfacePoint<F>& point) {
    return visit_kind(texture, [&](const auto& kind) {
        using Kind = std::decay_t<decltype(kind)>;
        // Image textures live in host vectors: scenes that have them never reach the GPU
        // (integrators/whitted/whitted_kernels.cpp refuses them), so the device pass has no image
        // lookup to compile.
        if constexpr (HIKARI_DEVICE_PASS && std::is_same_v<Kind, ImageTexture>)
            return Vec3T<F>(F(1.0f));
        else if constexpr (k_is_scalar<F> || k_texture_has_lane_form<Kind>)
            return texture_colour<F>(kind, point);
        else
            return Vec3T<F>(F(0.0f));  // never used: texture_has_lanes is false
    });
}

}  // namespace hikari
