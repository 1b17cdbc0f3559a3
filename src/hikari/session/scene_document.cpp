#include "hikari/session/scene_document.h"

#include <charconv>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "hikari/io/files/read_file.h"
#include "hikari/io/models/model_file.h"
#include "hikari/io/models/model_scene.h"
#include "hikari/io/scene/default_scene.h"
#include "hikari/io/scene/json_reader.h"
#include "hikari/io/scene/scene_document_rebase.h"
#include "hikari/io/scene/scene_overrides.h"

namespace hikari {

namespace {

namespace fs = std::filesystem;

/// Every "file" member under `node` made absolute against `base`: the scene format reads mesh,
/// texture and environment files relative to the scene file, which a downloaded copy leaves.
void absolute_files(nlohmann::json& node, const fs::path& base) {
    if (node.is_object()) {
        for (auto& [key, value] : node.items()) {
            if (key == "file" && value.is_string() &&
                fs::path(value.get<std::string>()).is_relative())
                value = (base / value.get<std::string>()).lexically_normal().string();
            else
                absolute_files(value, base);
        }
    } else if (node.is_array()) {
        for (nlohmann::json& item : node) absolute_files(item, base);
    }
}

/// The document `source` names before its overrides, and the folder its files are read from.
nlohmann::json source_document(const SceneSource& source, fs::path& base) {
    if (source.json_text) {
        base = source.base_dir;
        return parse_json(*source.json_text, source.file.empty() ? "scene" : source.file);
    }
    if (source.file.empty()) {
        base = ".";
        return parse_json(default_scene_json(), "scenes/assignment.json (built in)");
    }
    base = fs::path(source.file).parent_path();
    if (!is_model_file(source.file))
        return parse_json(read_file_bytes(source.file, InputKind::scene), source.file);
    ModelSceneOptions options{.ground = source.ground, .mesh = {}};
    if (source.crease_angle) options.mesh.crease_angle_degrees = *source.crease_angle;
    return model_scene_document(source.file, load_model(source.file, options.mesh), options);
}

/// `f` as the shortest decimal that reads back as the same float (1.2, not 1.2000000476837158).
/// (from_chars, not stod: the decimal point does not depend on the locale.)
double shortest(float f) {
    const std::string text = fmt::format("{}", f);
    double value = f;
    std::from_chars(text.data(), text.data() + text.size(), value);
    return value;
}

}  // namespace

nlohmann::json camera_document(const Camera& camera) {
    const auto vec = [](Vec3 v) {
        return nlohmann::json::array({shortest(v.x), shortest(v.y), shortest(v.z)});
    };
    return {{"projection",
             camera.projection == Projection::perspective ? "perspective" : "orthographic"},
            {"eye", vec(camera.eye)},
            {"look_at", vec(camera.look_at)},
            {"up", vec(camera.up)},
            {"fov_y", shortest(camera.fov_y_degrees)},
            {"view_height", shortest(camera.view_height)},
            {"width", camera.width},
            {"height", camera.height}};
}

nlohmann::json scene_document(const SceneSource& source, const Camera& camera) {
    fs::path base;
    nlohmann::json doc = source_document(source, base);
    apply_scene_overrides(doc, source.overrides);
    rebase_scene_document(doc);
    absolute_files(doc, fs::absolute(base));
    if (source.crease_angle && doc.contains("objects") && doc["objects"].is_array())
        for (nlohmann::json& object : doc["objects"])
            if (object.is_object() && object.value("type", "") == "mesh")
                object["crease_angle"] = *source.crease_angle;
    doc["camera"] = camera_document(camera);
    return doc;
}

}  // namespace hikari
