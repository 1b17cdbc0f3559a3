#pragma once
// What a render builds from the scene and can keep for the next one (a BVH, the occluders of
// analytic soft shadows, light-sampling tables): a render session (session/session.h) renders one
// scene many times, with another camera, size or method, and only the first render should pay
// for what does not depend on them. Each entry says which parts of the scene it was built from,
// so an edit drops exactly the entries it makes stale.

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

namespace hikari {

/// The parts of a scene that a built structure depends on (bit flags, combined with |).
enum class SceneParts : uint8_t {
    none = 0,
    geometry = 1,   ///< spheres, planes, triangles (positions, normals, uvs, ids, shadow flags)
    lights = 2,     ///< Scene::lights
    materials = 4,  ///< Scene::materials
    all = 7,
};

constexpr SceneParts operator|(SceneParts a, SceneParts b) {
    return static_cast<SceneParts>(static_cast<uint8_t>(a) | static_cast<uint8_t>(b));
}

constexpr bool overlaps(SceneParts a, SceneParts b) {
    return (static_cast<uint8_t>(a) & static_cast<uint8_t>(b)) != 0;
}

/// Structures built from one scene, each under a key, kept until a part of the scene it
/// depends on changes. Thread-safe: two renders asking for the same key build it once.
class BuildCache {
  public:
    /// The entry `key` (of type T), built by `build()` when absent; `built` (when given) says
    /// whether this call built it. The build runs under the cache's lock, so keep builders to
    /// one structure each.
    template <class T, class Build>
    std::shared_ptr<const T> get(std::string_view key, SceneParts depends_on, Build&& build,
                                 bool* built = nullptr) {
        std::lock_guard lock(m_mutex);
        auto it = m_entries.find(key);
        if (built) *built = it == m_entries.end();
        if (it == m_entries.end()) {
            std::shared_ptr<const T> made = std::make_shared<const T>(build());
            it = m_entries.emplace(std::string(key), Entry{made, depends_on, {}}).first;
        }
        return std::static_pointer_cast<const T>(it->second.value);
    }

    /// The entry `key` when it was built for `version` (what it depends on beyond the scene's
    /// parts, spelled as a string: a setting, a light's position), else one built by `build()`
    /// in its place (the stale one dropped first): one entry per key however often that changes.
    template <class T, class Build>
    std::shared_ptr<const T> get_version(std::string_view key, std::string_view version,
                                         SceneParts depends_on, Build&& build,
                                         bool* built = nullptr) {
        std::lock_guard lock(m_mutex);
        auto it = m_entries.find(key);
        const bool fresh = it == m_entries.end() || it->second.version != version;
        if (built) *built = fresh;
        if (!fresh) return std::static_pointer_cast<const T>(it->second.value);
        if (it != m_entries.end()) m_entries.erase(it);
        std::shared_ptr<const T> made = std::make_shared<const T>(build());
        m_entries.emplace(std::string(key), Entry{made, depends_on, std::string(version)});
        return made;
    }

    /// Ties the cache to the scene object its entries are built from (their references point
    /// into it): cached_or_built uses the cache only for that scene, and builds anew for any
    /// other (a render's modified copy, a rebased scene). Clears the cache when it changes.
    void bind(const void* scene);

    /// The scene the entries are built from (see bind).
    const void* scene() const { return m_scene; }

    /// Drops every entry built from any of `changed`.
    void invalidate(SceneParts changed);

    /// Drops every entry.
    void clear();

    /// How many entries are kept.
    size_t size() const;

  private:
    struct Entry {
        std::shared_ptr<const void> value;
        SceneParts depends_on;
        std::string version;  ///< get_version's; empty for get
    };
    mutable std::mutex m_mutex;
    const void* m_scene = nullptr;
    std::map<std::string, Entry, std::less<>> m_entries;
};

/// `cache`'s entry `key` when the cache is bound to `scene`, else (no cache, or a render of
/// another scene object) a structure built for this render alone: the one call a method makes
/// for each structure it could keep. `built` as in BuildCache::get.
template <class T, class Build>
std::shared_ptr<const T> cached_or_built(BuildCache* cache, const void* scene, std::string_view key,
                                         SceneParts depends_on, Build&& build,
                                         bool* built = nullptr) {
    if (cache && cache->scene() == scene)
        return cache->get<T>(key, depends_on, std::forward<Build>(build), built);
    if (built) *built = true;
    return std::make_shared<const T>(build());
}

}  // namespace hikari
