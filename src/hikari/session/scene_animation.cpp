#include "hikari/session/scene_animation.h"

#include <utility>

#include <fmt/format.h>

#include "hikari/io/files/read_file.h"
#include "hikari/io/models/model_file.h"
#include "hikari/io/scene/animation_json.h"
#include "hikari/io/scene/json_reader.h"
#include "hikari/io/scene/scene_json.h"

namespace hikari {

std::optional<SceneAnimation> SceneAnimation::of(const SceneSource& source) {
    const bool model = !source.json_text && is_model_file(source.file);
    if (model || (!source.json_text && source.file.empty())) return std::nullopt;
    SceneAnimation a;
    a.m_file = source.json_text && source.file.empty() ? "scene" : source.file;
    a.m_base_dir = source.json_text ? std::filesystem::path(source.base_dir)
                                    : std::filesystem::path(source.file).parent_path();
    a.m_crease_angle = source.crease_angle;
    const std::string text =
        source.json_text ? *source.json_text : read_file_bytes(source.file, InputKind::scene);
    a.m_document = parse_json(text, a.m_file);
    apply_scene_overrides(a.m_document, source.overrides);
    if (!a.m_document.is_object() || !a.m_document.contains("animation")) return std::nullopt;
    a.m_animation = parse_animation(JsonNode(a.m_document, a.m_file, ""));
    return a;
}

nlohmann::json SceneAnimation::document(int frame) const {
    return frame_document(m_document, m_animation, frame, m_file);
}

Scene SceneAnimation::scene(int frame, std::vector<std::string>& warnings) const {
    SceneLoadOptions options;
    options.crease_angle = m_crease_angle;
    return parse_scene_document(document(frame), fmt::format("{} (frame {})", m_file, frame),
                                m_base_dir, warnings, options);
}

void SceneAnimation::show(Session& session, int frame) const {
    std::vector<std::string> warnings;
    session.replace_scene(scene(frame, warnings));
}

}  // namespace hikari
