#pragma once
// The scenes of `hikari gallery`'s figures, as JSON documents the gallery writes into its
// scenes/ folder (and the small OBJ models some of them load from there).

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace hikari::gallery {

using Json = nlohmann::json;

/// The model placed on the ground: its bounds, and the mesh object that puts it there (its
/// largest side 1.2 long, standing on y = 0, centred on the y axis).
struct PlacedModel {
    Json object;         ///< the mesh object, its file named relative to the gallery's scenes/
    float height = 1;    ///< its height after placing
    float distance = 3;  ///< how far the camera stands from its centre to see all of it
    /// Fig 4.24b: the model as OBJ text with every vertex normal turned toward the light of
    /// shadows_only (positions and faces as in the file).
    std::string toward_light_obj;
};

/// Loads `model` to measure it; the object names it as `file_in_scenes` (a copy beside the
/// gallery's scenes). Throws InputError for a model without triangles.
PlacedModel place_model(const std::filesystem::path& model, const std::string& file_in_scenes);

/// The model on the ground under a key point light and a fill directional light (Fig 4.1).
Json model_scene(const PlacedModel& m, int width);

/// Fig 4.1b: `scene` with depth cueing as the lecture puts it (遠：暗い、ぼやけ): from `near` to
/// `far` eye distance the colour fades to black and blurs.
Json depth_cued(Json scene, float near, float far);

/// Fig 4.1f: `scene` with a checker texture on the model and the ground.
Json textured(Json scene);

/// Fig 4.24b, shadowing without shading, in one render: `scene` (model_scene) lit by one
/// directional light, its model loaded from `obj_file` (PlacedModel::toward_light_obj, every
/// normal facing the light) and its ground's kd divided by the ground's cos α, so that cos α is 1
/// everywhere: each surface shows ka + kd = its flat colour where the light reaches it and ka
/// (40% of it) where a shadow falls. Shadow rays and maps use the true geometry.
Json shadows_only(Json scene, const std::string& obj_file);

/// The turntable's scene: `scene` (model_scene) with its eye `fraction` of the way from its
/// look_at point, so that the model fills more of the turntable's small panels.
Json closer(Json scene, float fraction);

/// `scene` with its lights replaced by `lights`.
Json with_lights(Json scene, Json lights);

/// The assignment's sphere with Phong exponent `n` (Fig 4.39).
Json phong_sphere(float n, int width);

/// A glass ball with index of refraction `ior` before a checker wall (Fig 4.43).
Json refraction_scene(float ior, int width);

/// Fig 4.9c: the U-shaped polygon (one face of 8 corners) of concave_polygon_scene, as OBJ text.
std::string concave_polygon_obj();
/// Fig 4.9c: a concave polygon (a U, one polygon, in `obj_file`) and a bar through its notch.
Json concave_polygon_scene(const std::string& obj_file, int width);

/// Fig 4.4: a U-shaped block (a concave polyhedron), as OBJ text with polygon faces.
std::string concave_block_obj();
/// Fig 4.4: the U-shaped block of `obj_file`, seen from above and to the right.
Json concave_block_scene(const std::string& obj_file, int width);

}  // namespace hikari::gallery
