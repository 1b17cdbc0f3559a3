#include "hikari/io/scene/animation_json.h"

#include <initializer_list>
#include <limits>
#include <string_view>

#include <fmt/format.h>

#include "hikari/core/mat4.h"
#include "hikari/io/files/printable_text.h"
#include "hikari/io/scene/json_reader.h"

namespace hikari {

namespace {

using nlohmann::json;

/// The most frames an animation may have (a day of video at 24 frames per second is 2 million).
constexpr int k_max_frames = 10'000'000;

Vec3d to_double(Vec3 v) { return {v.x, v.y, v.z}; }
Vec3 to_float(Vec3d v) {
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}
json to_json(Vec3d v) { return json::array({v.x, v.y, v.z}); }
json to_json(Vec3 v) { return to_json(to_double(v)); }

KeyInterpolation parse_interpolation(const JsonNode& node) {
    const std::string word = node.as_string();
    if (word == "linear") return KeyInterpolation::linear;
    if (word == "smooth") return KeyInterpolation::smooth;
    node.fail(fmt::format("unknown interpolation {} (expected \"linear\" or \"smooth\")",
                          quote_token(word, '"')));
}

/// A track's "keys": objects with a "frame" and at least one more of `allowed`, frames strictly
/// increasing; `read(key, frame)` takes each key's values.
template <class Read>
void parse_keys(const JsonNode& keys, std::initializer_list<std::string_view> allowed, Read read) {
    keys.expect_array();
    if (keys.value().empty()) keys.fail("expected at least one key");
    double previous = -std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < keys.value().size(); ++i) {
        const JsonNode key = keys.at(i);
        key.expect_object(allowed);
        const JsonNode frame_node = key.at("frame");
        const double frame = frame_node.as_number();
        if (!(frame > previous))
            frame_node.fail(fmt::format(
                "keys must be in increasing frame order: frame {:g} comes after frame {:g}", frame,
                previous));
        previous = frame;
        if (key.value().size() < 2) key.fail("a key sets at least one value besides \"frame\"");
        read(key, frame);
    }
}

CameraKeys parse_camera_keys(const JsonNode& keys) {
    CameraKeys c;
    parse_keys(keys, {"frame", "eye", "look_at", "up", "fov_y"},
               [&c](const JsonNode& key, double frame) {
                   if (key.has("eye")) c.eye.push_back({frame, to_double(key.at("eye").as_vec3())});
                   if (key.has("look_at"))
                       c.look_at.push_back({frame, to_double(key.at("look_at").as_vec3())});
                   if (key.has("up"))
                       c.up.push_back({frame, to_double(key.at("up").as_direction())});
                   if (!key.has("fov_y")) return;
                   const JsonNode fov = key.at("fov_y");
                   const float degrees = fov.as_number();
                   if (!(degrees > 0 && degrees < 180))
                       fov.fail("expected an angle in degrees between 0 and 180 (exclusive)");
                   c.fov_y.push_back({frame, degrees});
               });
    return c;
}

/// A key's "scale": one positive number, or three; `uniform` allows only the first.
Vec3d parse_scale(const JsonNode& node, bool uniform) {
    if (node.value().is_number()) return Vec3d(node.as_positive());
    if (uniform) node.fail("a sphere scales by one positive number (it stays a sphere)");
    const Vec3 s = node.as_vec3();
    if (!(min_component(s) > 0.0f)) node.fail("expected three positive numbers");
    return to_double(s);
}

TransformKeys parse_transform_keys(const JsonNode& keys, bool uniform_scale) {
    TransformKeys t;
    parse_keys(
        keys, {"frame", "scale", "rotate", "translate"}, [&](const JsonNode& key, double frame) {
            if (key.has("scale"))
                t.scale.push_back({frame, parse_scale(key.at("scale"), uniform_scale)});
            if (key.has("rotate")) {
                const JsonNode r = key.at("rotate");
                r.expect_object({"axis", "degrees"});
                t.rotate.push_back({frame, rotation_about(to_double(r.at("axis").as_direction()),
                                                          r.at("degrees").as_number())});
            }
            if (key.has("translate"))
                t.translate.push_back({frame, to_double(key.at("translate").as_vec3())});
        });
    return t;
}

/// The index into `list` (the scene's "objects" or "lights") that `node` names: an index, or
/// for objects the value of an object's "name".
size_t parse_target(const JsonNode& node, const JsonNode& list, std::string_view what) {
    list.expect_array();
    const size_t count = list.value().size();
    if (count == 0) node.fail(fmt::format("the scene has no {}s to animate", what));
    if (node.value().is_number()) return static_cast<size_t>(node.as_int(0, int(count) - 1));
    if (what != "object" || !node.value().is_string())
        node.fail(fmt::format("expected the index of a {} (0 to {}){}", what, count - 1,
                              what == "object" ? " or an object's \"name\"" : ""));
    const std::string name = node.as_string();
    for (size_t i = 0; i < count; ++i) {
        const json& object = list.value()[i];
        if (object.is_object() && object.contains("name") && object["name"] == name) return i;
    }
    node.fail(fmt::format("no object has the name {}", quote_token(name, '"')));
}

/// An "objects" or "lights" entry of the block: {what: target, "interpolation", "keys"}.
TransformAnimation parse_transform_animation(const JsonNode& node, const JsonNode& list,
                                             std::string_view what, KeyInterpolation fallback) {
    node.expect_object({what, "interpolation", "keys"});
    TransformAnimation a;
    a.index = parse_target(node.at(what), list, what);
    const json& target = list.value()[a.index];
    const std::string type =
        target.is_object() && target.contains("type") && target["type"].is_string()
            ? target["type"].get<std::string>()
            : "";
    if (type == "environment")
        node.at(what).fail(
            "an environment light has no transform keys (turn its map with rotation_degrees)");
    a.interpolation =
        node.has("interpolation") ? parse_interpolation(node.at("interpolation")) : fallback;
    a.keys = parse_transform_keys(node.at("keys"), type == "sphere");
    return a;
}

/// The block's "objects" or "lights" (`what` the singular): one entry per animated target.
std::vector<TransformAnimation> parse_transform_animations(const JsonNode& block,
                                                           const JsonNode& root,
                                                           std::string_view what,
                                                           KeyInterpolation fallback) {
    const std::string plural = fmt::format("{}s", what);
    std::vector<TransformAnimation> out;
    if (!block.has(plural)) return out;
    const JsonNode entries = block.at(plural);
    entries.expect_array();
    if (!root.has(plural)) entries.fail(fmt::format("the scene has no {}s to animate", what));
    for (size_t i = 0; i < entries.value().size(); ++i) {
        const JsonNode entry = entries.at(i);
        out.push_back(parse_transform_animation(entry, root.at(plural), what, fallback));
        for (size_t j = 0; j + 1 < out.size(); ++j)
            if (out[j].index == out.back().index)
                entry.at(what).fail(fmt::format("{} {} already has keys at {}[{}]", what,
                                                out.back().index, entries.path(), j));
    }
    return out;
}

/// world_from_model of the steps at one frame, as a scene's "transform" list of them builds it
/// (io/scene/scene_json.cpp, parse_transform): scale, then rotate, then translate.
Mat4 transform_matrix(const TransformAtFrame& t) {
    Mat4 m = Mat4::identity();
    if (t.scale) m = scale(to_float(*t.scale)) * m;
    if (t.rotate) m = rotate(to_float(t.rotate->axis), static_cast<float>(t.rotate->degrees)) * m;
    if (t.translate) m = translate(to_float(*t.translate)) * m;
    return m;
}

/// A triangle's or mesh's "transform" with the frame's steps appended.
void append_steps(json& steps, const TransformAtFrame& t) {
    if (t.scale) {
        const Vec3d s = *t.scale;
        steps.push_back({{"scale", s.x == s.y && s.y == s.z ? json(s.x) : to_json(s)}});
    }
    if (t.rotate)
        steps.push_back(
            {{"rotate", {{"axis", to_json(t.rotate->axis)}, {"degrees", t.rotate->degrees}}}});
    if (t.translate) steps.push_back({{"translate", to_json(*t.translate)}});
}

/// An object moved by the frame's transform, written as its type is written.
void move_object(json& object, const TransformAtFrame& t, const JsonNode& node) {
    const std::string type = object.at("type").get<std::string>();
    if (type == "triangle" || type == "mesh") return append_steps(object["transform"], t);
    const Mat4 m = transform_matrix(t);
    if (type == "sphere") {
        const Vec3 centre = node.at("center").as_vec3();
        const float radius = node.at("radius").as_positive();
        object["center"] = to_json(transform_point(m, centre));
        if (t.scale) object["radius"] = radius * static_cast<float>(t.scale->x);
    } else if (type == "plane") {
        const Vec3 point = node.at("point").as_vec3();
        const Vec3 normal = node.at("normal").as_direction();
        Mat4 inverse;
        invert(m, inverse);
        object["point"] = to_json(transform_point(m, point));
        object["normal"] = to_json(transform_normal(transpose(inverse), normal));
    }
}

/// A light moved by the frame's transform: its points ("position", an area light's "corner")
/// and its directions ("direction", "edge1", "edge2").
void move_light(json& light, const TransformAtFrame& t, const JsonNode& node) {
    const Mat4 m = transform_matrix(t);
    for (const char* key : {"position", "corner"})
        if (node.has(key)) light[key] = to_json(transform_point(m, node.at(key).as_vec3()));
    for (const char* key : {"direction", "edge1", "edge2"})
        if (node.has(key)) light[key] = to_json(transform_direction(m, node.at(key).as_vec3()));
}

void write_camera(json& doc, const Animation& a, double frame) {
    const CameraKeys& k = a.camera;
    if (k.eye.empty() && k.look_at.empty() && k.up.empty() && k.fov_y.empty()) return;
    json& camera = doc["camera"];
    if (!camera.is_null() && !camera.is_object()) return;  // the parser reports it
    if (!k.eye.empty()) camera["eye"] = to_json(sample(k.eye, frame, a.camera_interpolation));
    if (!k.look_at.empty())
        camera["look_at"] = to_json(sample(k.look_at, frame, a.camera_interpolation));
    if (!k.up.empty()) camera["up"] = to_json(sample(k.up, frame, a.camera_interpolation));
    if (!k.fov_y.empty()) camera["fov_y"] = sample(k.fov_y, frame);
}

}  // namespace

Animation parse_animation(const JsonNode& root) {
    const JsonNode node = root.at("animation");
    node.expect_object({"frames", "fps", "interpolation", "camera", "objects", "lights"});
    Animation a;
    a.frame_count = node.at("frames").as_int(1, k_max_frames);
    if (node.has("fps")) {
        a.fps = node.at("fps").as_positive();
        if (a.fps > 1000) node.at("fps").fail("expected at most 1000 frames per second");
    }
    const KeyInterpolation fallback = node.has("interpolation")
                                          ? parse_interpolation(node.at("interpolation"))
                                          : KeyInterpolation::linear;
    a.camera_interpolation = fallback;
    if (node.has("camera")) {
        const JsonNode camera = node.at("camera");
        camera.expect_object({"interpolation", "keys"});
        if (camera.has("interpolation"))
            a.camera_interpolation = parse_interpolation(camera.at("interpolation"));
        a.camera = parse_camera_keys(camera.at("keys"));
    }
    a.objects = parse_transform_animations(node, root, "object", fallback);
    a.lights = parse_transform_animations(node, root, "light", fallback);
    return a;
}

json frame_document(const json& doc, const Animation& animation, int frame,
                    const std::string& file) {
    json out = doc;
    out.erase("animation");
    const auto f = static_cast<double>(frame);
    write_camera(out, animation, f);
    for (const TransformAnimation& a : animation.objects) {
        json& object = out["objects"][a.index];
        const JsonNode node(object, file, fmt::format("objects[{}]", a.index));
        move_object(object, sample(a.keys, f, a.interpolation), node);
    }
    for (const TransformAnimation& a : animation.lights) {
        json& light = out["lights"][a.index];
        const JsonNode node(light, file, fmt::format("lights[{}]", a.index));
        move_light(light, sample(a.keys, f, a.interpolation), node);
    }
    return out;
}

}  // namespace hikari
