#include "hikari/io/scene/scene_document_rebase.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace hikari {
namespace {

using nlohmann::json;

bool is_point(const json& v) {
    return v.is_array() && v.size() == 3 &&
           std::all_of(v.begin(), v.end(), [](const json& c) { return c.is_number(); });
}

/// `key` of `object` moved by −origin, when it holds a point.
void move_point(json& object, const char* key, WorldOrigin origin) {
    if (!object.is_object() || !object.contains(key) || !is_point(object[key])) return;
    json& p = object[key];
    p = {p[0].get<double>() - origin.x, p[1].get<double>() - origin.y,
         p[2].get<double>() - origin.z};
}

/// An object's transform followed by a translation by −origin.
void move_transform(json& object, WorldOrigin origin) {
    if (!object.contains("transform")) {
        object["transform"] = json::array();
    }
    json& steps = object["transform"];
    if (!steps.is_array()) return;  // the parser reports it
    if (!steps.empty() && steps.back().is_object() && steps.back().size() == 1 &&
        steps.back().contains("translate")) {
        move_point(steps.back(), "translate", origin);
        return;
    }
    steps.push_back({{"translate", {-origin.x, -origin.y, -origin.z}}});
}

}  // namespace

std::optional<WorldOrigin> rebase_scene_document(json& doc) {
    if (!doc.is_object() || !doc.contains("camera") || !doc["camera"].is_object()) return {};
    json& camera = doc["camera"];
    if (!camera.contains("eye") || !is_point(camera["eye"])) return {};
    Camera c;
    c.eye = {camera["eye"][0].get<float>(), camera["eye"][1].get<float>(),
             camera["eye"][2].get<float>()};
    if (camera.contains("look_at")) {
        if (!is_point(camera["look_at"])) return {};
        c.look_at = {camera["look_at"][0].get<float>(), camera["look_at"][1].get<float>(),
                     camera["look_at"][2].get<float>()};
    } else {
        c.look_at = c.eye + Vec3{0, 0, -1};  // the default camera looks down −z
        camera["look_at"] = {c.look_at.x, c.look_at.y, c.look_at.z};
    }
    if (!is_finite(c.eye) || !is_finite(c.look_at) || !worth_rebasing(c)) return {};
    const WorldOrigin origin{c.eye.x, c.eye.y, c.eye.z};
    move_point(camera, "eye", origin);
    move_point(camera, "look_at", origin);
    if (doc.contains("lights") && doc["lights"].is_array())
        for (json& light : doc["lights"]) {
            move_point(light, "position", origin);
            move_point(light, "corner", origin);
        }
    if (doc.contains("objects") && doc["objects"].is_array())
        for (json& object : doc["objects"]) {
            if (!object.is_object() || !object.contains("type") || !object["type"].is_string())
                continue;
            const std::string type = object["type"].get<std::string>();
            if (type == "sphere") move_point(object, "center", origin);
            if (type == "plane") move_point(object, "point", origin);
            if (type == "mesh") move_transform(object, origin);
            if (type == "triangle") {
                if (object.contains("transform")) {
                    move_transform(object, origin);
                } else if (object.contains("vertices") && object["vertices"].is_array()) {
                    for (json& v : object["vertices"])
                        if (is_point(v))
                            v = {v[0].get<double>() - origin.x, v[1].get<double>() - origin.y,
                                 v[2].get<double>() - origin.z};
                }
            }
        }
    return origin;
}

}  // namespace hikari
