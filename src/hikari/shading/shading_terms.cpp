#include "hikari/shading/shading_terms.h"

namespace hikari {

Scene isolate_shading_term(Scene scene, ShadingTerm term) {
    for (Material& m : scene.materials) {
        if (term != ShadingTerm::ambient) m.ka = Vec3(0.0f);
        if (term != ShadingTerm::diffuse) m.kd = Vec3(0.0f);
        if (term != ShadingTerm::specular) m.ks = Vec3(0.0f);
    }
    if (term == ShadingTerm::ambient) return scene;
    // Light reflected by surfaces only: what escaping rays see belongs to the ambient image.
    scene.show_background = false;
    scene.background = Vec3(0.0f);
    scene.sky.gradient = false;
    if (scene.depth_cue) scene.depth_cue->color = Vec3(0.0f);
    return scene;
}

}  // namespace hikari
