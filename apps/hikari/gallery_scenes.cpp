#include "gallery_scenes.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "hikari/core/aabb.h"
#include "hikari/core/error.h"
#include "hikari/io/scene/scene_json.h"

namespace hikari::gallery {

namespace {

Json vec(float x, float y, float z) { return {x, y, z}; }

/// A ground of two triangles, 12 × 12 around the origin, material "ground".
Json ground_triangles() {
    return {{{"type", "triangle"},
             {"vertices", {vec(-6, 0, -6), vec(-6, 0, 6), vec(6, 0, 6)}},
             {"material", "ground"}},
            {{"type", "triangle"},
             {"vertices", {vec(-6, 0, -6), vec(6, 0, 6), vec(6, 0, -6)}},
             {"material", "ground"}}};
}

/// Fig 4.24b's light: from above, front and right, as the model scene's key light.
constexpr float k_shadow_light[3] = {-2.2f, -3.5f, -2.5f};

/// Unit vector toward the light of Fig 4.24b.
Vec3 toward_shadow_light() {
    return -normalize(Vec3(k_shadow_light[0], k_shadow_light[1], k_shadow_light[2]));
}

/// `scene`'s triangles as OBJ text, every vertex with the one normal `n`.
std::string obj_with_normal(const Scene& scene, Vec3 n) {
    std::string out = "# hikari gallery, Fig 4.24b: the model, every normal toward the light\n";
    for (const Vec3& p : scene.triangles.positions)
        out += fmt::format("v {} {} {}\n", p.x, p.y, p.z);
    out += fmt::format("vn {} {} {}\n", n.x, n.y, n.z);
    for (const auto& [a, b, c] : scene.triangles.indices)
        out += fmt::format("f {}//1 {}//1 {}//1\n", a + 1, b + 1, c + 1);
    return out;
}

/// A camera at `eye` looking at `at`, `width` × `height` pixels.
Json camera(Json eye, Json at, float fov_y, int width, int height) {
    return {{"eye", std::move(eye)},
            {"look_at", std::move(at)},
            {"fov_y", fov_y},
            {"width", width},
            {"height", height}};
}

/// The U of Fig 4.9c and Fig 4.4 seen from +z, counter-clockwise: arms 0.8 wide, a notch 1.4
/// wide and 2 deep, 3 × 3 in all.
constexpr float k_u_outline[8][2] = {{-1.5f, -1.5f}, {1.5f, -1.5f},  {1.5f, 1.5f},  {0.7f, 1.5f},
                                     {0.7f, -0.5f},  {-0.7f, -0.5f}, {-0.7f, 1.5f}, {-1.5f, 1.5f}};

}  // namespace

PlacedModel place_model(const std::filesystem::path& model, const std::string& file_in_scenes) {
    // The mesh loaded as a scene's one object, as every figure will load it.
    const std::string probe =
        Json{{"objects", {{{"type", "mesh"}, {"file", std::filesystem::absolute(model).string()}}}}}
            .dump();
    std::vector<std::string> warnings;
    const Scene scene =
        parse_scene(probe, model.string(), std::filesystem::current_path(), warnings);
    Aabb box;
    for (const Vec3& p : scene.triangles.positions) box.extend(p);
    if (scene.triangles.size() == 0 || box.empty())
        throw InputError(fmt::format("{}: the model has no triangles", model.string()));
    const Vec3 extent = box.extent();
    const float scale = 1.2f / std::max({extent.x, extent.y, extent.z, 1e-12f});
    const Vec3 c = box.center();
    PlacedModel placed;
    placed.object = {
        {"type", "mesh"},
        {"file", file_in_scenes},
        {"material", "model"},
        {"transform", {{{"translate", {-c.x, -box.min.y, -c.z}}}, {{"scale", scale}}}}};
    placed.height = extent.y * scale;
    // The bounding sphere fills the view (38° high, 4:3): r / sin(19°), with a margin.
    const float radius = 0.5f * length(extent) * scale;
    placed.distance = 1.1f * radius / std::sin(19.0f * 3.14159265f / 180.0f);
    placed.toward_light_obj = obj_with_normal(scene, toward_shadow_light());
    return placed;
}

Json model_scene(const PlacedModel& m, int width) {
    const Vec3 centre(0, 0.5f * m.height, 0);
    Json objects = ground_triangles();
    objects.push_back(m.object);
    const Json eye = vec(centre.x + m.distance * 0.5f, centre.y + m.distance * 0.42f,
                         centre.z + m.distance * 0.76f);
    return {
        {"description", "hikari gallery: the model on a ground (Fig 4.1 and others)"},
        {"camera", camera(eye, vec(centre.x, centre.y, centre.z), 38, width, width * 3 / 4)},
        {"background", vec(0.62f, 0.7f, 0.82f)},
        {"ambient", vec(0.15f, 0.15f, 0.16f)},
        {"materials",
         {{"model",
           {{"ka", vec(0.85f, 0.55f, 0.35f)},
            {"kd", vec(0.85f, 0.55f, 0.35f)},
            {"ks", vec(0.4f, 0.4f, 0.4f)},
            {"shininess", 40}}},
          {"ground", {{"ka", vec(0.7f, 0.7f, 0.68f)}, {"kd", vec(0.7f, 0.7f, 0.68f)}}}}},
        {"lights",
         {{{"type", "point"}, {"position", vec(2.2f, 3.5f, 2.5f)}, {"intensity", vec(18, 17, 16)}},
          {{"type", "directional"},
           {"direction", vec(-0.5f, -1, -0.3f)},
           {"intensity", vec(0.25f, 0.27f, 0.32f)}}}},
        {"objects", objects}};
}

Json depth_cued(Json scene, float near, float far) {
    scene["description"] =
        "Fig 4.1b: depth cueing, near bright and sharp, far dark and blurred (遠：暗い、ぼやけ)";
    scene["depth_cue"] = {{"near", near}, {"far", far}, {"color", vec(0, 0, 0)}, {"blur", 4}};
    return scene;
}

Json textured(Json scene) {
    const Json checker = {{"type", "checker"},
                          {"size", 0.25},
                          {"color_a", vec(0.9f, 0.9f, 0.85f)},
                          {"color_b", vec(0.25f, 0.35f, 0.6f)}};
    scene["materials"]["ground"]["texture"] = checker;
    scene["materials"]["model"]["texture"] = checker;
    return scene;
}

Json shadows_only(Json scene, const std::string& obj_file) {
    scene["description"] =
        "Fig 4.24b: shadows only. One directional light; every normal faces it (the model's in "
        "its OBJ copy, the ground's kd divided by its cos α), so cos α = 1 everywhere and each "
        "surface shows its flat colour ka + kd where the light reaches it, ka where its shadow "
        "falls. Shadow rays and shadow maps use the true geometry.";
    const Vec3 l = toward_shadow_light();
    const float ground_cos = l.y;  // the ground's normal is +y
    for (auto& [name, m] : scene["materials"].items()) {
        const Json colour = m.value("kd", vec(0.8f, 0.8f, 0.8f));
        const float kd = name == "ground" ? 0.6f / ground_cos : 0.6f;
        m["ka"] = {0.4f * colour[0].get<float>(), 0.4f * colour[1].get<float>(),
                   0.4f * colour[2].get<float>()};
        m["kd"] = {kd * colour[0].get<float>(), kd * colour[1].get<float>(),
                   kd * colour[2].get<float>()};
        m["ks"] = vec(0, 0, 0);
    }
    scene["ambient"] = vec(1, 1, 1);
    scene["lights"] = {{{"type", "directional"},
                        {"direction", vec(k_shadow_light[0], k_shadow_light[1], k_shadow_light[2])},
                        {"intensity", vec(1, 1, 1)}}};
    for (Json& object : scene["objects"])
        if (object.value("type", "") == "mesh") object["file"] = obj_file;
    return scene;
}

Json closer(Json scene, float fraction) {
    Json& camera = scene["camera"];
    for (int i = 0; i < 3; ++i) {
        const float at = camera["look_at"][i].get<float>(), eye = camera["eye"][i].get<float>();
        camera["eye"][i] = at + fraction * (eye - at);
    }
    return scene;
}

Json with_lights(Json scene, Json lights) {
    scene["lights"] = std::move(lights);
    return scene;
}

Json phong_sphere(float n, int width) {
    return {
        {"description", fmt::format("Fig 4.39: the Phong highlight with n = {}", n)},
        {"camera", camera(vec(0, 0, 0), vec(0, 0, -1), 40, width / 2, width / 2)},
        {"background", vec(0.1f, 0.1f, 0.1f)},
        {"ambient", vec(0.1f, 0.1f, 0.1f)},
        {"materials",
         {{"clay",
           {{"ka", vec(0.8f, 0.3f, 0.2f)},
            {"kd", vec(0.8f, 0.3f, 0.2f)},
            {"ks", vec(0.6f, 0.6f, 0.6f)},
            {"shininess", n}}}}},
        {"lights",
         {{{"type", "directional"}, {"direction", vec(1, -1, -1)}, {"intensity", vec(1, 1, 1)}}}},
        {"objects",
         {{{"type", "sphere"}, {"center", vec(0, 0, -3)}, {"radius", 1}, {"material", "clay"}}}}};
}

Json refraction_scene(float ior, int width) {
    const Json checker = {{"type", "checker"},
                          {"size", 0.5},
                          {"color_a", vec(0.9f, 0.85f, 0.3f)},
                          {"color_b", vec(0.15f, 0.3f, 0.7f)}};
    return {
        {"description", fmt::format("Fig 4.43: refraction through a ball of ior {}", ior)},
        {"camera", camera(vec(0, 1, 4.5f), vec(0, 1, 0), 40, width / 2, width / 2)},
        {"background", vec(0.3f, 0.3f, 0.35f)},
        {"ambient", vec(0.3f, 0.3f, 0.3f)},
        {"materials",
         {{"glass",
           {{"ks", vec(0.6f, 0.6f, 0.6f)},
            {"shininess", 200},
            {"transparency", 0.9},
            {"reflectivity", 0.05},
            {"ior", ior}}},
          {"wall", {{"ka", vec(1, 1, 1)}, {"kd", vec(0.8f, 0.8f, 0.8f)}, {"texture", checker}}}}},
        {"lights",
         {{{"type", "point"}, {"position", vec(2, 4, 5)}, {"intensity", vec(30, 30, 30)}}}},
        // The wall halfway between two planes of the solid checker's cells (z = −2.25, cells
        // 0.5 deep): on a cell boundary, rounding picks either cell's colour pixel by pixel.
        {"objects",
         {{{"type", "sphere"}, {"center", vec(0, 1, 0)}, {"radius", 0.8}, {"material", "glass"}},
          {{"type", "plane"},
           {"point", vec(0, 0, -2.25f)},
           {"normal", vec(0, 0, 1)},
           {"material", "wall"}}}}};
}

std::string concave_polygon_obj() {
    // The U lies in the tilted plane z = −10 − 2x/3: its left arm nearer than z = −10.3, its
    // right arm farther; its centroid (x = 0 by symmetry) at z = −10.
    std::string obj = "# Fig 4.9c: one concave polygon (a U), written by hikari gallery\n";
    for (const auto& p : k_u_outline)
        obj += fmt::format("v {} {} {}\n", p[0], p[1], -10.0f - 2.0f * p[0] / 3.0f);
    obj += "vn 0.5547 0 0.8321\n";
    obj += "f 1//1 2//1 3//1 4//1 5//1 6//1 7//1 8//1\n";
    return obj;
}

Json concave_polygon_scene(const std::string& obj_file, int width) {
    // The bar at z = −10.3 crosses the U's plane at x = 0.45, inside the notch: the two never
    // touch, yet the bar is behind the left arm and in front of the right one.
    const auto bar = [](Json a, Json b, Json c) {
        return Json{{"type", "triangle"},
                    {"vertices", {std::move(a), std::move(b), std::move(c)}},
                    {"material", "bar"}};
    };
    return {{"description",
             "Fig 4.9c: a concave polygon (a U, one polygon) and a bar through its notch, behind "
             "the U's left arm and in front of its right arm"},
            {"camera", camera(vec(0, 0, 0), vec(0, 0, -1), 30, width / 2, width / 2)},
            {"background", vec(0.95f, 0.95f, 0.92f)},
            {"ambient", vec(0.7f, 0.7f, 0.7f)},
            {"materials",
             {{"u", {{"ka", vec(0.95f, 0.55f, 0.1f)}}}, {"bar", {{"ka", vec(0.2f, 0.35f, 0.9f)}}}}},
            {"lights", Json::array()},
            {"objects",
             {{{"type", "mesh"}, {"file", obj_file}, {"material", "u"}},
              bar(vec(-2.5f, 0.2f, -10.3f), vec(2.5f, 0.2f, -10.3f), vec(2.5f, 0.8f, -10.3f)),
              bar(vec(-2.5f, 0.2f, -10.3f), vec(2.5f, 0.8f, -10.3f), vec(-2.5f, 0.8f, -10.3f))}}};
}

std::string concave_block_obj() {
    // The U extruded from z = 0.5 (front, vertices 1–8) to z = −0.5 (back, 9–16).
    std::string obj =
        "# Fig 4.4: a U-shaped block, a concave polyhedron, written by hikari gallery\n";
    for (const float z : {0.5f, -0.5f})
        for (const auto& p : k_u_outline) obj += fmt::format("v {} {} {}\n", p[0], p[1], z);
    obj += "f 1 2 3 4 5 6 7 8\nf 16 15 14 13 12 11 10 9\n";
    // Side i joins outline edge i → i + 1; N = (P2 − P1) × (P3 − P2) points outward.
    for (int i = 0; i < 8; ++i) {
        const int j = (i + 1) % 8;
        obj += fmt::format("f {} {} {} {}\n", i + 1, i + 9, j + 9, j + 1);
    }
    return obj;
}

Json concave_block_scene(const std::string& obj_file, int width) {
    return {
        {"description", "Fig 4.4: a U-shaped block, a concave polyhedron"},
        {"camera", camera(vec(5.5f, 1.2f, 3), vec(0, 0, 0), 40, width / 2, width / 2)},
        {"background", vec(0.95f, 0.95f, 0.92f)},
        {"ambient", vec(0.3f, 0.3f, 0.3f)},
        {"materials", {{"block", {{"ka", vec(0.6f, 0.7f, 0.9f)}, {"kd", vec(0.6f, 0.7f, 0.9f)}}}}},
        {"lights",
         {{{"type", "directional"},
           {"direction", vec(-0.4f, -1, -0.6f)},
           {"intensity", vec(0.8f, 0.8f, 0.8f)}}}},
        {"objects", {{{"type", "mesh"}, {"file", obj_file}, {"material", "block"}}}}};
}

}  // namespace hikari::gallery
