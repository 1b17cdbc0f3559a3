#pragma once
// The lights a point is lit by: a view of the scene's, read by shading/direct.h.

#include <cstddef>

#include "hikari/core/vec.h"
#include "hikari/scene/light.h"

namespace hikari {

/// The lights and ambient light a point is lit by.
struct LightingEnvironment {
    const Light* lights = nullptr;  ///< light_count lights (Scene::lights)
    size_t light_count = 0;
    Vec3 ambient{0.0f};  ///< ambient intensity Ia
};

}  // namespace hikari
