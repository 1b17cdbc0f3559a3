#include "hikari/explain/primitive_names.h"

#include <fmt/format.h>

namespace hikari {

PrimitiveNames::PrimitiveNames(const Scene& scene) : m_kind(scene.primitive_count, "triangle") {
    for (const Sphere& s : scene.spheres)
        if (s.id < m_kind.size()) m_kind[s.id] = "sphere";
    for (const Plane& p : scene.planes)
        if (p.id < m_kind.size()) m_kind[p.id] = "plane";
}

std::string PrimitiveNames::primitive(PrimitiveId id) const {
    return fmt::format("{} (primitive {})", id < m_kind.size() ? m_kind[id] : "triangle", id);
}

std::string PrimitiveNames::screen_triangle(const ProjectedScene& ps, uint32_t t) const {
    const uint32_t source = ps.triangles[t].source;
    const PrimitiveId id = ps.scene.triangles.id[source];
    const std::string_view kind = id < m_kind.size() ? m_kind[id] : "triangle";
    if (kind == "triangle") return fmt::format("triangle {} (primitive {})", t, id);
    return fmt::format("triangle {} of {} (primitive {})", t, kind, id);
}

std::string view_depth_note(const RasterView& view, double z) {
    if (view.orthographic || !(z < 0.0)) return "";
    return fmt::format(" (view depth {:.4f})", -view.near_plane / z);
}

}  // namespace hikari
