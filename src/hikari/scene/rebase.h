#pragma once
// Rebasing the world to the camera (issue 26, item 5): a scene placed far from the origin, as
// models in CAD or georeferenced coordinates are, is translated so that the eye sits at the
// origin before a method builds anything from it (BVH, tessellation, shadow maps, clip-space
// setup). A translation changes no image in exact arithmetic, and near the camera, where every
// visible detail is, floats are then as dense as they get: hit points, ray–surface distances and
// the view matrix's translation stop cancelling against a huge common offset.

#include "hikari/scene/scene.h"

namespace hikari {

/// How far from the origin the eye must be, in multiples of max(1, |look_at − eye|), for
/// render_scene to rebase: a scene framed near the origin (every scene in scenes/, the Cornell
/// box's eye 800 units out looking 800 units ahead) renders exactly as before, while one moved
/// many viewing distances away (whitted.json by 10³ or more) is rebased.
inline constexpr float k_rebase_ratio = 16.0f;

/// Whether the eye lies far from the origin compared with the distance it looks at: its largest
/// coordinate exceeds k_rebase_ratio · max(1, |look_at − eye|).
bool worth_rebasing(const Camera& camera);

/// `scene` translated by −camera.eye, so that its eye is the origin: the camera's eye and
/// look_at, point lights' positions, area lights' corners, sphere centres, plane points and
/// triangle vertices, each subtracted in double and rounded once. Directions (directional and
/// environment lights, normals, edges, `up`) stay, and so does everything the images depend on:
/// distances from the eye (depth cueing), texture coordinates (relative to a plane's point or a
/// sphere's centre, or per vertex), and solid checkers, whose offset takes up the translation
/// (modulo their period of two cells) so that the pattern stays where it was on the surfaces.
Scene rebased_to_camera(Scene scene);

/// A point of the world in double precision: the origin a scene is rebased to.
struct WorldOrigin {
    double x = 0, y = 0, z = 0;
};

/// p − origin, subtracted in double and rounded to float once.
Vec3 relative_to(WorldOrigin origin, double px, double py, double pz);

/// Gives every solid checker of the scene's materials the offset that keeps its pattern where it
/// was on the surfaces once the world has moved by −origin.
void keep_checkers_in_place(Scene& scene, WorldOrigin origin);

}  // namespace hikari
