#include "hikari/io/models/model_scene.h"

#include <cmath>

#include "hikari/io/models/model_file.h"
#include "hikari/scene/camera.h"

namespace hikari {
namespace {

nlohmann::json to_json(Vec3 v) { return nlohmann::json::array({v.x, v.y, v.z}); }

float radians(float degrees) { return degrees * static_cast<float>(M_PI) / 180.0f; }

/// The centre of the model's bounding box and the radius of the sphere about it that holds every
/// vertex (tighter than half the box's diagonal).
struct BoundingSphere {
    Vec3 centre;
    float radius = 0;
};

BoundingSphere bounding_sphere(const MeshData& mesh) {
    Vec3 lo(INFINITY), hi(-INFINITY);
    for (const Vec3& p : mesh.positions) {
        lo = min(lo, p);
        hi = max(hi, p);
    }
    BoundingSphere s{0.5f * (lo + hi), 0.0f};
    for (const Vec3& p : mesh.positions) s.radius = std::max(s.radius, length(p - s.centre));
    if (!(s.radius > 0.0f)) s.radius = 1.0f;
    return s;
}

float lowest_y(const MeshData& mesh) {
    float y = INFINITY;
    for (const Vec3& p : mesh.positions) y = std::min(y, p.y);
    return y;
}

}  // namespace

nlohmann::json model_scene_document(const std::filesystem::path& file, const MeshData& mesh,
                                    const ModelSceneOptions& options) {
    using nlohmann::json;
    const BoundingSphere sphere = bounding_sphere(mesh);
    Camera camera;
    camera.width = k_model_image_width;
    camera.height = k_model_image_height;
    if (!mesh.cameras.empty()) {
        const ModelCamera& c = mesh.cameras.front();
        camera.eye = c.camera.eye;
        camera.look_at = c.camera.look_at;
        camera.up = c.camera.up;
        camera.fov_y_degrees = c.camera.fov_y_degrees;
        if (c.aspect && *c.aspect > 0.0f)
            camera.height = std::max(1, static_cast<int>(std::lround(camera.width / *c.aspect)));
    } else {
        // The sphere fills the narrower of the two fields of view: seen from distance d its
        // silhouette spans the half-angle asin(r / d).
        const float azimuth = radians(k_model_view_azimuth_degrees);
        const float elevation = radians(k_model_view_elevation_degrees);
        const Vec3 toward_eye{std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
                              std::cos(azimuth) * std::cos(elevation)};
        const float tan_half_y = std::tan(radians(k_model_fov_y_degrees) / 2.0f);
        const float tan_half_x = tan_half_y * float(camera.width) / float(camera.height);
        const float half_angle = std::atan(std::min(tan_half_x, tan_half_y));
        const float distance = 1.05f * sphere.radius / std::sin(half_angle);
        camera.eye = sphere.centre + distance * toward_eye;
        camera.look_at = sphere.centre;
        camera.fov_y_degrees = k_model_fov_y_degrees;
    }
    json doc;
    doc["description"] = "The model " + file.filename().string() + ", framed automatically.";
    doc["camera"] = {{"eye", to_json(camera.eye)}, {"look_at", to_json(camera.look_at)},
                     {"up", to_json(camera.up)},   {"fov_y", camera.fov_y_degrees},
                     {"width", camera.width},      {"height", camera.height}};
    doc["background"] = {0.18, 0.2, 0.23};
    doc["ambient"] = {0.12, 0.12, 0.12};
    doc["lights"] = json::array();
    if (mesh.lights.empty()) {
        // Key light from the viewer's upper left, fill from the right, both relative to the
        // camera so that any framing is lit from the front.
        const CameraFrame frame = make_camera_frame(camera);
        const Vec3 back = -1.0f * frame.forward;
        const Vec3 key = normalize(-0.6f * frame.right + 0.9f * frame.up + 0.8f * back);
        const Vec3 fill = normalize(0.9f * frame.right + 0.1f * frame.up + 0.5f * back);
        doc["lights"].push_back({{"type", "directional"},
                                 {"direction", to_json(-1.0f * key)},
                                 {"intensity", {0.9, 0.9, 0.9}}});
        doc["lights"].push_back({{"type", "directional"},
                                 {"direction", to_json(-1.0f * fill)},
                                 {"intensity", {0.3, 0.3, 0.32}}});
    }
    json mesh_object = {{"type", "mesh"},
                        {"file", std::filesystem::absolute(file).string()},
                        {"crease_angle", options.mesh.crease_angle_degrees}};
    doc["objects"] = json::array({mesh_object});
    if (options.ground) {
        const float size = sphere.radius / 2.0f;
        doc["materials"]["ground"] = {{"ka", {0.6, 0.6, 0.6}},
                                      {"kd", {0.6, 0.6, 0.6}},
                                      {"texture",
                                       {{"type", "checker"},
                                        {"size", size},
                                        {"color_a", {0.9, 0.9, 0.9}},
                                        {"color_b", {0.55, 0.55, 0.55}}}}};
        // Just below the lowest point, so the model stands on it without sharing its depth.
        const float y = lowest_y(mesh) - 1e-4f * sphere.radius;
        doc["objects"].push_back({{"type", "plane"},
                                  {"point", to_json({sphere.centre.x, y, sphere.centre.z})},
                                  {"normal", {0, 1, 0}},
                                  {"material", "ground"}});
    }
    return doc;
}

Scene load_model_scene(const std::filesystem::path& file, const ModelSceneOptions& options,
                       std::vector<std::string>& warnings, SceneLoadOptions load) {
    ModelSceneOptions own = options;
    if (load.crease_angle) own.mesh.crease_angle_degrees = *load.crease_angle;
    const MeshData mesh = load_model(file, own.mesh);
    const std::filesystem::path absolute = std::filesystem::absolute(file);
    load.preloaded_file = absolute;
    load.preloaded = &mesh;
    return parse_scene(model_scene_document(file, mesh, own).dump(), file.string(),
                       absolute.parent_path(), warnings, load);
}

}  // namespace hikari
