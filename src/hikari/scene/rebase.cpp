#include "hikari/scene/rebase.h"

#include <algorithm>
#include <cmath>
#include <variant>

namespace hikari {

namespace {

Vec3 minus(Vec3 p, Vec3 origin) {
    return relative_to({origin.x, origin.y, origin.z}, p.x, p.y, p.z);
}

/// The checker evaluated at p − origin shows what it showed at p when its offset grows by
/// `origin`; its cell parity repeats every two cells along each axis, so the new offset is taken
/// modulo 2·size. That keeps it as small as the cells (a file that moved its checker along with
/// the scene, offset −origin, gets back offset 0), so the pattern is computed near 0 too.
void keep_checker_in_place(std::optional<Texture>& texture, WorldOrigin origin) {
    if (!texture) return;
    auto* checker = std::get_if<CheckerTexture>(&*texture);
    if (!checker) return;
    const double period = 2.0 * double(checker->size);
    const auto shifted = [&](float offset, double o) {
        return static_cast<float>(std::fmod(double(offset) + o, period));
    };
    checker->offset = {shifted(checker->offset.x, origin.x), shifted(checker->offset.y, origin.y),
                       shifted(checker->offset.z, origin.z)};
}

}  // namespace

bool worth_rebasing(const Camera& camera) {
    const Vec3 e = camera.eye;
    const float farthest = std::max({std::abs(e.x), std::abs(e.y), std::abs(e.z)});
    return farthest > k_rebase_ratio * std::max(1.0f, length(camera.look_at - e));
}

Scene rebased_to_camera(Scene scene) {
    const Vec3 origin = scene.camera.eye;
    scene.camera.eye = Vec3(0.0f);
    scene.camera.look_at = minus(scene.camera.look_at, origin);
    const auto same = [](Vec3 v) { return v; };
    const LightMove move{[&](Vec3 p) { return minus(p, origin); }, same, same};
    for (Light& light : scene.lights) move_light(light, move);
    for (Sphere& s : scene.spheres) s.center = minus(s.center, origin);
    for (Plane& p : scene.planes) p.point = minus(p.point, origin);
    for (Vec3& p : scene.triangles.positions) p = minus(p, origin);
    keep_checkers_in_place(scene, {origin.x, origin.y, origin.z});
    return scene;
}

Vec3 relative_to(WorldOrigin origin, double px, double py, double pz) {
    return {static_cast<float>(px - origin.x), static_cast<float>(py - origin.y),
            static_cast<float>(pz - origin.z)};
}

void keep_checkers_in_place(Scene& scene, WorldOrigin origin) {
    for (Material& m : scene.materials) {
        keep_checker_in_place(m.texture, origin);
        keep_checker_in_place(m.ambient_texture, origin);
    }
}

}  // namespace hikari
