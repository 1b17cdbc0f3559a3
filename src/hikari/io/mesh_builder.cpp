#include "hikari/io/mesh_builder.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <optional>
#include <utility>

#include "hikari/core/cancel.h"
#include "hikari/core/error.h"
#include "hikari/core/memory_budget.h"
#include "hikari/geometry/polygon_triangulation.h"

namespace hikari {
namespace {

/// A triangle kept for the output: vertex indices of the PolygonMesh, its face, outline edges.
struct PendingTriangle {
    std::array<uint32_t, 3> v;
    uint32_t face;
    uint8_t edge_flags;
};

/// "FILE:LINE: " where the face's line is known, else "FILE: ".
std::string face_where(const std::filesystem::path& file, const PolygonMesh& mesh, size_t face) {
    if (face < mesh.face_line.size() && mesh.face_line[face] > 0)
        return fmt::format("{}:{}: ", file.string(), mesh.face_line[face]);
    return fmt::format("{}: ", file.string());
}

/// Twice the triangle's area (the length of N = (P2 - P1) x (P3 - P2), lecture Fig 4.3); zero or
/// not finite for a triangle that cannot be drawn.
float doubled_area(Vec3 p1, Vec3 p2, Vec3 p3) { return length(cross(p2 - p1, p3 - p2)); }

/// Every face split into triangles, in face order; degenerate triangles dropped and counted.
std::vector<PendingTriangle> triangulate_faces(const std::filesystem::path& file,
                                               const PolygonMesh& mesh, MeshData& out) {
    const size_t vertex_count = mesh.positions.size();
    std::vector<PendingTriangle> triangles;
    triangles.reserve(mesh.corners.size() >= 2 * mesh.face_count()
                          ? mesh.corners.size() - 2 * mesh.face_count()
                          : 0);
    std::vector<PolygonTriangle> local;
    std::vector<Vec3> outline;
    size_t crossing_faces = 0;
    for (size_t f = 0; f < mesh.face_count(); ++f) {
        if (f % 65536 == 0) throw_if_cancelled();  // SIGINT / SIGTERM
        const uint32_t begin = mesh.face_start[f], end = mesh.face_start[f + 1];
        const uint32_t n = end - begin;
        if (n < 3)
            throw InputError(face_where(file, mesh, f) +
                             fmt::format("face {} has {} corner{}; a face needs at least 3", f + 1,
                                         n, n == 1 ? "" : "s"));
        for (uint32_t k = begin; k < end; ++k) {
            if (mesh.corners[k] >= vertex_count)
                throw InputError(face_where(file, mesh, f) +
                                 fmt::format("face {} refers to vertex {}, but the file has {}",
                                             f + 1, mesh.corners[k], vertex_count));
        }
        local.clear();
        if (n == 3) {
            local.push_back({{0, 1, 2}, 7});
        } else {
            outline.clear();
            for (uint32_t k = begin; k < end; ++k)
                outline.push_back(mesh.positions[mesh.corners[k]]);
            if (triangulate_polygon(outline, local) == PolygonShape::SelfIntersecting) {
                if (crossing_faces < 3)
                    out.warnings.push_back(
                        face_where(file, mesh, f) +
                        fmt::format("face {} crosses itself; its triangles may cover area outside "
                                    "its outline",
                                    f + 1));
                ++crossing_faces;
            }
        }
        for (const PolygonTriangle& t : local) {
            const PendingTriangle p{
                {mesh.corners[begin + t.corner[0]], mesh.corners[begin + t.corner[1]],
                 mesh.corners[begin + t.corner[2]]},
                static_cast<uint32_t>(f),
                t.edge_flags};
            const float area2 = doubled_area(mesh.positions[p.v[0]], mesh.positions[p.v[1]],
                                             mesh.positions[p.v[2]]);
            if (!(area2 > 0.0f) || !std::isfinite(area2)) {
                ++out.degenerate_skipped;
                continue;
            }
            triangles.push_back(p);
        }
    }
    if (crossing_faces > 3)
        out.warnings.push_back(
            fmt::format("{}: {} more faces cross themselves", file.string(), crossing_faces - 3));
    return triangles;
}

bool is_usable_normal(Vec3 n) {
    const float l = dot(n, n);
    return l > 0.0f && std::isfinite(l);
}

/// Computes the normal of each corner (3 per triangle) that needs one: the sum of the unit face
/// normals around its point that it is smoothed with — those of its own smoothing group, or
/// those within the crease angle of its own face — each weighted by the triangle's angle at the
/// point (Thürmer & Wüthrich 1998), so a polygon counts the same however it was triangulated.
class CornerNormals {
  public:
    CornerNormals(const PolygonMesh& mesh, const std::vector<PendingTriangle>& triangles,
                  const MeshOptions& options)
        : m_mesh(mesh), m_triangles(triangles) {
        m_unit_normal.resize(triangles.size());
        m_corner_angle.resize(triangles.size());
        for (size_t t = 0; t < triangles.size(); ++t) {
            if (t % 65536 == 0) throw_if_cancelled();  // SIGINT / SIGTERM
            const auto& v = triangles[t].v;
            const Vec3 p[3] = {mesh.positions[v[0]], mesh.positions[v[1]], mesh.positions[v[2]]};
            m_unit_normal[t] = normalize(cross(p[1] - p[0], p[2] - p[1]));
            for (int k = 0; k < 3; ++k) {
                const Vec3 a = normalize(p[(k + 1) % 3] - p[k]),
                           b = normalize(p[(k + 2) % 3] - p[k]);
                m_corner_angle[t][k] = std::acos(std::clamp(dot(a, b), -1.0f, 1.0f));
            }
        }
        m_by_groups = std::any_of(mesh.smoothing_group.begin(), mesh.smoothing_group.end(),
                                  [](uint32_t g) { return g != 0; });
        const float crease = std::clamp(options.crease_angle_degrees, 0.0f, 180.0f);
        m_min_cos = std::cos(crease * static_cast<float>(M_PI) / 180.0f) - 1e-6f;
        weld_positions();
        index_corners_by_point();
    }

    Vec3 normal(size_t t, int slot) const {
        const uint32_t key = point_of(m_triangles[t].v[slot]);
        Vec3 sum(0.0f);
        for (uint32_t k = m_start[key]; k < m_start[key + 1]; ++k) {
            const uint32_t other = m_around[k] / 3, other_slot = m_around[k] % 3;
            if (other == t || smoothed_together(t, other))
                sum += m_corner_angle[other][other_slot] * m_unit_normal[other];
        }
        return is_usable_normal(sum) ? normalize(sum) : m_unit_normal[t];
    }

  private:
    uint32_t point_of(uint32_t vertex) const { return m_point[vertex]; }

    /// Numbers the distinct positions: vertices at exactly the same place are one point, so a
    /// file that splits its vertices per face (at texture seams, or everywhere, as some PLY
    /// exporters do) is still smoothed across them.
    void weld_positions() {
        const size_t n = m_mesh.positions.size();
        std::vector<uint32_t> order(n);
        for (size_t i = 0; i < n; ++i) order[i] = uint32_t(i);
        auto bits = [&](uint32_t i) {
            std::array<uint32_t, 3> b{};
            std::memcpy(b.data(), &m_mesh.positions[i], sizeof(Vec3));
            return b;
        };
        std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
            return std::pair(bits(a), a) < std::pair(bits(b), b);
        });
        m_point.resize(n);
        uint32_t point = 0;
        for (size_t k = 0; k < n; ++k) {
            if (k > 0 && bits(order[k]) != bits(order[k - 1])) ++point;
            m_point[order[k]] = point;
        }
    }

    bool smoothed_together(size_t a, size_t b) const {
        if (m_by_groups) {
            const uint32_t g = m_mesh.smoothing_group[m_triangles[a].face];
            return g != 0 && g == m_mesh.smoothing_group[m_triangles[b].face];
        }
        return dot(m_unit_normal[a], m_unit_normal[b]) >= m_min_cos;
    }

    /// m_around[m_start[p] .. m_start[p + 1]) lists the corners at point p, as 3 × triangle +
    /// corner.
    void index_corners_by_point() {
        uint32_t points = 0;
        for (const PendingTriangle& t : m_triangles)
            for (uint32_t v : t.v) points = std::max(points, point_of(v) + 1);
        m_start.assign(size_t{points} + 1, 0);
        for (const PendingTriangle& t : m_triangles)
            for (uint32_t v : t.v) ++m_start[point_of(v) + 1];
        for (size_t p = 0; p < points; ++p) m_start[p + 1] += m_start[p];
        m_around.resize(m_start[points]);
        std::vector<uint32_t> fill(m_start.begin(), m_start.end() - 1);
        for (size_t t = 0; t < m_triangles.size(); ++t)
            for (uint32_t k = 0; k < 3; ++k)
                m_around[fill[point_of(m_triangles[t].v[k])]++] = uint32_t(3 * t + k);
    }

    const PolygonMesh& m_mesh;
    const std::vector<PendingTriangle>& m_triangles;
    std::vector<Vec3> m_unit_normal;
    std::vector<std::array<float, 3>> m_corner_angle;
    std::vector<uint32_t> m_point, m_start, m_around;
    bool m_by_groups = false;
    float m_min_cos = -1.0f;
};

/// Equal to the bit (so -0 and 0 differ, and a NaN equals itself): normals computed from the same
/// faces in the same order share a vertex, any other pair does not.
bool same_bits(Vec3 a, Vec3 b) {
    return std::bit_cast<uint32_t>(a.x) == std::bit_cast<uint32_t>(b.x) &&
           std::bit_cast<uint32_t>(a.y) == std::bit_cast<uint32_t>(b.y) &&
           std::bit_cast<uint32_t>(a.z) == std::bit_cast<uint32_t>(b.z);
}

}  // namespace

MeshData build_mesh(const std::filesystem::path& file, PolygonMesh mesh,
                    const MeshOptions& options) {
    MeshData out;
    out.warnings = std::move(mesh.warnings);
    // What the triangles and vertices below will take, checked before any of it is allocated:
    // per triangle the pending one, its output indices, material and edge flags, and the
    // computed normals' face normal and corner angles; per vertex its output attributes and
    // the bookkeeping of normal variants (about 40 bytes).
    const size_t corners = mesh.corners.size(), faces = mesh.face_count();
    const double triangle_count =
        corners >= 2 * faces ? static_cast<double>(corners - 2 * faces) : 0.0;
    check_memory_need(triangle_count * (sizeof(PendingTriangle) + 41.0) +
                          40.0 * static_cast<double>(mesh.positions.size()),
                      fmt::format("{}: building {:.0f} triangles", file.string(), triangle_count));
    const std::vector<PendingTriangle> triangles = triangulate_faces(file, mesh, out);
    if (triangles.empty()) {
        throw InputError(fmt::format(
            "{}: {}", file.string(),
            out.degenerate_skipped > 0
                ? fmt::format("no usable triangles: all {} are degenerate", out.degenerate_skipped)
                : std::string("no faces: the file defines no triangles or polygons")));
    }
    if (triangles.size() > UINT32_MAX / 3)
        throw InputError(fmt::format("{}: too many triangles", file.string()));

    const size_t vertex_count = mesh.positions.size();
    std::vector<uint8_t> has_own_normal(vertex_count, 0);
    bool any_computed = false;
    for (const PendingTriangle& t : triangles) {
        for (uint32_t v : t.v) {
            has_own_normal[v] = !mesh.normals.empty() && is_usable_normal(mesh.normals[v]);
            any_computed |= !has_own_normal[v];
        }
    }
    std::optional<CornerNormals> computed;
    if (any_computed) computed.emplace(mesh, triangles, options);

    // Output vertices in order of first use: one per input vertex with its own normal, one per
    // distinct computed normal of an input vertex otherwise (split along creases). The variants
    // of one input vertex form a chain through next_variant.
    constexpr uint32_t k_none = UINT32_MAX;
    std::vector<uint32_t> first_variant(vertex_count, k_none);
    std::vector<uint32_t> next_variant;
    const bool has_uvs = !mesh.uvs.empty();
    out.positions.reserve(vertex_count);
    out.normals.reserve(vertex_count);
    if (has_uvs) out.uvs.reserve(vertex_count);
    const bool has_colors = !mesh.colors.empty();
    if (has_colors) out.colors.reserve(vertex_count);
    out.indices.reserve(triangles.size());
    out.material.reserve(triangles.size());
    out.edge_flags.reserve(triangles.size());
    for (size_t t = 0; t < triangles.size(); ++t) {
        if (t % 65536 == 0) throw_if_cancelled();  // SIGINT / SIGTERM
        const PendingTriangle& tri = triangles[t];
        std::array<uint32_t, 3> index{};
        for (int slot = 0; slot < 3; ++slot) {
            const uint32_t v = tri.v[slot];
            const Vec3 n =
                has_own_normal[v] ? normalize(mesh.normals[v]) : computed->normal(t, slot);
            // Walk the chain; `last` is the variant whose link is followed (k_none: the head).
            uint32_t last = k_none, at = first_variant[v];
            while (at != k_none && !same_bits(out.normals[at], n)) {
                last = at;
                at = next_variant[at];
            }
            if (at == k_none) {
                at = static_cast<uint32_t>(out.positions.size());
                (last == k_none ? first_variant[v] : next_variant[last]) = at;
                next_variant.push_back(k_none);
                out.positions.push_back(mesh.positions[v]);
                out.normals.push_back(n);
                if (has_uvs) out.uvs.push_back(mesh.uvs[v]);
                if (has_colors) out.colors.push_back(mesh.colors[v]);
            }
            index[slot] = at;
        }
        out.indices.push_back(index);
        out.material.push_back(mesh.face_material.empty() ? -1 : mesh.face_material[tri.face]);
        out.edge_flags.push_back(tri.edge_flags);
    }
    out.materials = std::move(mesh.materials);
    return out;
}

}  // namespace hikari
