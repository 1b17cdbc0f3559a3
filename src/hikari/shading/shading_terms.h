#pragma once
// One term of the lecture's shading model (Fig 4.29) at a time: the scene changed so that a
// method's ordinary render shows only the ambient, only the diffuse or only the specular light
// (`--aov ambient|diffuse|specular`). The code that renders it is the code that renders the
// full colour, so the three images add up to the colour image.

#include <optional>

#include "hikari/frame/framebuffer.h"
#include "hikari/scene/scene.h"

namespace hikari {

/// A term of ka Ia + Σ I (kd cos α + ks cos^n γ).
enum class ShadingTerm { ambient, diffuse, specular };

/// The shading term an AOV names (`--aov ambient|diffuse|specular`), if it names one.
inline std::optional<ShadingTerm> shading_term_of(Aov aov) {
    if (aov == Aov::ambient) return ShadingTerm::ambient;
    if (aov == Aov::diffuse) return ShadingTerm::diffuse;
    if (aov == Aov::specular) return ShadingTerm::specular;
    return std::nullopt;
}

/// `scene` with every material's other two terms set to zero. The ambient term also keeps what
/// rays that meet no surface see (background, sky, environment, the faces of area lights) and
/// the depth cue's colour; the diffuse and specular terms see black there. Every term is linear
/// in these inputs, and mirror and refraction weights do not depend on them, so for Whitted ray
/// tracing and the raster methods the three renders sum to the full render (up to float
/// rounding), mirrors and glass included.
Scene isolate_shading_term(Scene scene, ShadingTerm term);

}  // namespace hikari
