#include "hikari/core/build_cache.h"

namespace hikari {

void BuildCache::invalidate(SceneParts changed) {
    std::lock_guard lock(m_mutex);
    std::erase_if(m_entries,
                  [&](const auto& entry) { return overlaps(entry.second.depends_on, changed); });
}

void BuildCache::bind(const void* scene) {
    std::lock_guard lock(m_mutex);
    if (scene != m_scene) m_entries.clear();
    m_scene = scene;
}

void BuildCache::clear() {
    std::lock_guard lock(m_mutex);
    m_entries.clear();
}

size_t BuildCache::size() const {
    std::lock_guard lock(m_mutex);
    return m_entries.size();
}

}  // namespace hikari
