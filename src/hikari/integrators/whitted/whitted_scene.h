#pragma once
// What the Whitted ray tracer's shading reads from a scene: views into it, nothing copied.

#include "hikari/scene/scene.h"
#include "hikari/shading/lighting_environment.h"

namespace hikari {

/// Everything shading a Whitted hit reads from the scene (views into it, nothing copied).
struct WhittedScene {
    LightingEnvironment lighting;
    const Material* materials = nullptr;
    const Sky* sky = nullptr;
    Vec3 background{0.0f};

    explicit WhittedScene(const Scene& scene)
        : lighting{scene.lights.data(), scene.lights.size(), scene.ambient},
          materials(scene.materials.data()),
          sky(&scene.sky),
          background(scene.background) {}
};

}  // namespace hikari
