#pragma once
// An animated scene's frames for the front ends (the scene file's "animation" block,
// io/scene/animation_json.h). Frame k's scene is built as a session builds the scene file that
// frame k's document is, and handed to the session with Session::replace_scene, which keeps
// what was built from geometry the frame left where it was (a camera-only animation keeps every
// BVH).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hikari/scene/animation.h"
#include "hikari/session/session.h"

namespace hikari {

/// The frames of one animated scene file.
class SceneAnimation {
  public:
    /// The animation of `source`'s scene, its --set edits applied; nullopt for a scene without
    /// an "animation" block, a model file or the built-in default scene. Throws InputError as a
    /// session's load does (a file that cannot be read, a bad animation block).
    static std::optional<SceneAnimation> of(const SceneSource& source);

    int frame_count() const { return m_animation.frame_count; }
    /// Frames per second, the block's "fps".
    double fps() const { return m_animation.fps; }
    const Animation& animation() const { return m_animation; }

    /// Frame `frame`'s scene document: the file with the frame's values written in and no
    /// animation block, what `hikari render` of that document as a file renders bit for bit.
    nlohmann::json document(int frame) const;
    /// Frame `frame`'s scene; messages name the file and the frame. Throws InputError.
    Scene scene(int frame, std::vector<std::string>& warnings) const;
    /// Puts frame `frame`'s scene on `session` (Session::replace_scene).
    void show(Session& session, int frame) const;

  private:
    SceneAnimation() = default;

    nlohmann::json m_document;  ///< the scene file with its --set edits
    std::string m_file;         ///< for messages
    std::filesystem::path m_base_dir;
    std::optional<float> m_crease_angle;
    Animation m_animation;
};

}  // namespace hikari
