#pragma once
// What the Whitted ray tracer's shading reads from a scene: views into it, nothing copied.

#include "hikari/scene/scene.h"
#include "hikari/shading/lighting_environment.h"
#include "hikari/shading/soft_shadows/occluders.h"

namespace hikari {

/// Everything shading a Whitted hit reads from the scene (views into it, nothing copied).
struct WhittedScene {
    LightingEnvironment lighting;
    const Material* materials = nullptr;
    const Sky* sky = nullptr;
    Vec3 background{0.0f};
    /// Samples per area or environment light per point.
    int light_samples = 1;
    /// The shadow casters of analytic area-light shadows; null: area lights are sampled.
    const OccluderSet* occluders = nullptr;

    explicit WhittedScene(const Scene& scene, int samples = 1, const OccluderSet* casters = nullptr)
        : lighting{scene.lights.data(), scene.lights.size(), scene.ambient},
          materials(scene.materials.data()),
          sky(&scene.sky),
          background(scene.background),
          light_samples(samples),
          occluders(casters) {}
};

}  // namespace hikari
