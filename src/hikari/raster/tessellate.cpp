#include "hikari/raster/tessellate.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "hikari/core/aabb.h"
#include "hikari/core/memory_budget.h"
#include "hikari/geometry/surface_uv.h"
#include "hikari/raster/screen_triangle.h"

namespace hikari {

namespace {

constexpr float k_pi = std::numbers::pi_v<float>;

/// Appends triangle (a, b, c) of vertex indices, turned so that its front (counter-clockwise,
/// N = (P2 − P1) × (P3 − P2)) faces along `outward`. `edges` are its TriangleSet::edge_flags
/// in the order (a, b, c): which of its edges are grid lines rather than a cell's diagonal.
void push_triangle(TriangleSet& out, uint32_t a, uint32_t b, uint32_t c, Vec3 outward,
                   uint32_t material, PrimitiveId id, uint8_t edges) {
    const Vec3& p1 = out.positions[a];
    const Vec3& p2 = out.positions[b];
    const Vec3& p3 = out.positions[c];
    if (dot(cross(p2 - p1, p3 - p2), outward) < 0.0f) {
        std::swap(b, c);
        edges = mirrored_edge_flags(edges);
    }
    out.indices.push_back({a, b, c});
    out.material.push_back(material);
    out.id.push_back(id);
    out.edge_flags.push_back(edges);
}

/// Edge flags of the two triangles (a, b, d) and (a, d, c) of a grid cell: the cell's outline,
/// not its diagonal a–d.
constexpr uint8_t k_cell_first = 0b011, k_cell_second = 0b110;

uint32_t push_vertex(TriangleSet& out, Vec3 p, Vec3 n, Vec2 uv = {}) {
    out.positions.push_back(p);
    out.normals.push_back(n);
    out.uvs.push_back(uv);
    if (!out.colors.empty()) out.colors.emplace_back(1.0f);  // spheres and planes: white
    return static_cast<uint32_t>(out.positions.size() - 1);
}

/// Marks a vertex without a seam copy yet.
constexpr uint32_t k_no_copy = ~0u;

/// Whether `p` is one of the sphere's poles (on its y axis), where longitude is undefined.
bool is_pole(const Sphere& s, Vec3 p) { return p.x == s.center.x && p.z == s.center.z; }

/// A copy of vertex `k` of `out` with texture coordinates `uv`.
uint32_t copy_vertex(TriangleSet& out, uint32_t k, Vec2 uv) {
    const uint32_t copy = push_vertex(out, out.positions[k], out.normals[k], uv);
    if (!out.colors.empty()) out.colors[copy] = out.colors[k];
    return copy;
}

/// The sphere's longitude/latitude mapping (geometry/surface_uv.h) on its triangles from
/// `first_triangle` on, as the ray tracer computes it at its hits. Where a triangle straddles
/// the seam u = 0 ≡ 1, its corners on the u < 1/2 side are copies with u + 1; where a corner is
/// a pole (u undefined), it is a copy with the mean u of the other two. Copies share position
/// and normal, so the rasterized shape is the same.
void map_sphere_uvs(const Sphere& s, size_t first_vertex, size_t first_triangle, TriangleSet& out) {
    for (size_t k = first_vertex; k < out.positions.size(); ++k)
        out.uvs[k] = sphere_uv(s, out.positions[k]).uv;
    std::vector<uint32_t> wrapped(out.positions.size(), k_no_copy);
    for (size_t t = first_triangle; t < out.indices.size(); ++t) {
        auto& tri = out.indices[t];
        float lo = 1.0f, hi = 0.0f;
        for (const uint32_t k : tri)
            if (!is_pole(s, out.positions[k])) {
                lo = std::min(lo, out.uvs[k].x), hi = std::max(hi, out.uvs[k].x);
            }
        if (hi - lo > 0.5f)
            for (uint32_t& k : tri)
                if (!is_pole(s, out.positions[k]) && out.uvs[k].x < 0.5f) {
                    if (wrapped[k] == k_no_copy)
                        wrapped[k] = copy_vertex(out, k, {out.uvs[k].x + 1.0f, out.uvs[k].y});
                    k = wrapped[k];
                }
        for (int c = 0; c < 3; ++c)
            if (is_pole(s, out.positions[tri[c]])) {
                const float u = 0.5f * (out.uvs[tri[(c + 1) % 3]].x + out.uvs[tri[(c + 2) % 3]].x);
                tri[c] = copy_vertex(out, tri[c], {u, out.uvs[tri[c]].y});
            }
    }
}

/// Projected radius in pixels of `s` seen by `camera`; infinity when the eye is (nearly) inside.
float projected_radius(const Sphere& s, const Camera& camera) {
    if (camera.projection == Projection::orthographic)
        return s.radius / camera.view_height * static_cast<float>(camera.height);
    const float dist = length(s.center - camera.eye);
    if (dist <= 1.05f * s.radius) return std::numeric_limits<float>::infinity();
    const float tan_angular = s.radius / std::sqrt(dist * dist - s.radius * s.radius);
    const float tan_half_fov = std::tan(camera.fov_y_degrees * k_pi / 360.0f);
    return tan_angular / tan_half_fov * 0.5f * static_cast<float>(camera.height);
}

/// Two unit tangents completing `n` to a right-handed frame (u, v, n).
std::pair<Vec3, Vec3> tangent_frame(Vec3 n) {
    const Vec3 a = std::abs(n.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 u = normalize(cross(a, n));
    return {u, cross(n, u)};
}

}  // namespace

uint32_t sphere_segments(float radius_px) {
    // Sagitta r (1 − cos π/n) ≈ r π² / (2 n²) ≤ 0.05 px  ⇔  n ≥ π √(10 r).
    if (!(radius_px < 1e6f)) return 512;
    const float n = std::ceil(k_pi * std::sqrt(10.0f * std::max(radius_px, 0.0f)));
    return static_cast<uint32_t>(std::clamp(n, 16.0f, 512.0f));
}

void tessellate_sphere(const Sphere& s, uint32_t lon, TriangleSet& out) {
    const uint32_t lat = std::max(2u, lon / 2);  // automatic counts start at 16: 8 bands
    const size_t first_vertex = out.positions.size(), first_triangle = out.indices.size();
    auto vertex = [&](float theta, float phi) {
        const Vec3 n{std::sin(theta) * std::cos(phi), std::cos(theta),
                     std::sin(theta) * std::sin(phi)};
        return push_vertex(out, s.center + s.radius * n, n);
    };
    const uint32_t top = push_vertex(out, s.center + Vec3(0, s.radius, 0), {0, 1, 0});
    const uint32_t first_ring = static_cast<uint32_t>(out.positions.size());
    for (uint32_t k = 1; k < lat; ++k)
        for (uint32_t m = 0; m < lon; ++m)
            vertex(k_pi * float(k) / float(lat), 2 * k_pi * float(m) / float(lon));
    const uint32_t bottom = push_vertex(out, s.center - Vec3(0, s.radius, 0), {0, -1, 0});
    auto ring = [&](uint32_t k, uint32_t m) { return first_ring + (k - 1) * lon + m % lon; };
    // Edge flags: the latitude/longitude grid lines are the sphere's edges, the diagonals that
    // split each grid cell into two triangles are not.
    auto tri = [&](uint32_t a, uint32_t b, uint32_t c, uint8_t edges) {
        const Vec3 centroid = (out.positions[a] + out.positions[b] + out.positions[c]) / 3.0f;
        push_triangle(out, a, b, c, centroid - s.center, s.material, s.id, edges);
    };
    for (uint32_t m = 0; m < lon; ++m) tri(top, ring(1, m), ring(1, m + 1), k_all_edges);
    for (uint32_t k = 1; k + 1 < lat; ++k)
        for (uint32_t m = 0; m < lon; ++m) {
            tri(ring(k, m), ring(k + 1, m), ring(k + 1, m + 1), k_cell_first);
            tri(ring(k, m), ring(k + 1, m + 1), ring(k, m + 1), k_cell_second);
        }
    for (uint32_t m = 0; m < lon; ++m)
        tri(bottom, ring(lat - 1, m + 1), ring(lat - 1, m), k_all_edges);
    map_sphere_uvs(s, first_vertex, first_triangle, out);
}

void tessellate_plane(const Plane& plane, Vec3 eye, float half_extent, TriangleSet& out) {
    constexpr int k_steps = 32;  // grid lines on each side of the foot point
    const auto [u, v] = tangent_frame(plane.normal);
    const Vec3 foot = eye - dot(eye - plane.point, plane.normal) * plane.normal;
    float coord[2 * k_steps + 1];
    for (int k = -k_steps; k <= k_steps; ++k) {
        const float t = float(std::abs(k)) / float(k_steps);
        coord[k + k_steps] = (k < 0 ? -1.0f : 1.0f) * half_extent * t * t * t;
    }
    const auto base = static_cast<uint32_t>(out.positions.size());
    constexpr int n = 2 * k_steps + 1;
    for (const float cj : coord)
        for (const float ci : coord) {
            const Vec3 p = foot + ci * u + cj * v;
            push_vertex(out, p, plane.normal, plane_uv(plane, p).uv);
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const uint32_t a = base + j * n + i, b = a + 1, c = a + n, d = c + 1;
            push_triangle(out, a, b, d, plane.normal, plane.material, plane.id, k_cell_first);
            push_triangle(out, a, d, c, plane.normal, plane.material, plane.id, k_cell_second);
        }
}

namespace {

/// What the raster pipeline holds per vertex and per triangle of the tessellated scene: the
/// copy tessellate_scene makes (position, normal, uv, colour; indices, material, id, edge
/// flags), the clip-space positions and screen triangles of its projection, and about two
/// entries of tile bins per triangle; and once more for the shadow casters' own copy and
/// projection (raster/shadow_map.cpp). Measured: zbuffer with a shadow map over a sphere of
/// 2048 segments (4.2 million triangles) peaks at 1.2 GiB, this count says 1.2 GiB.
constexpr double k_raster_bytes_per_vertex = 2 * (3 * sizeof(Vec3) + sizeof(Vec2) + sizeof(Vec4));
constexpr double k_raster_bytes_per_triangle =
    2 * (sizeof(std::array<uint32_t, 3>) + 2 * sizeof(uint32_t) + 1 + 2 * sizeof(ScreenTriangle) +
         2 * sizeof(uint64_t)) -
    sizeof(ScreenTriangle);

}  // namespace

double sphere_triangle_count(uint32_t segments) {
    const double lon = segments, lat = std::max(2u, segments / 2);
    return 2.0 * lon * (lat - 1.0);
}

RasterCounts check_raster_memory(const Scene& scene, SphereGeometry spheres) {
    RasterCounts n{static_cast<double>(scene.triangles.size()),
                   static_cast<double>(scene.triangles.positions.size())};
    double finest = 0;  // the finest sphere tessellation asked for, for the message
    for (const Sphere& s : scene.spheres) {
        if (spheres == SphereGeometry::exact && s.segments == 0) continue;
        const uint32_t lon =
            s.segments > 0 ? s.segments : sphere_segments(projected_radius(s, scene.camera));
        const double lat = std::max(2u, lon / 2);
        n.triangles += sphere_triangle_count(lon);
        // The rings and poles, and the texture seam's copies (map_sphere_uvs).
        n.vertices += lon * (lat - 1.0) + 2.0 + 2.0 * lon + lat + 2.0;
        finest = std::max(finest, static_cast<double>(s.segments));
    }
    // A plane is a 64 x 64 grid of cells (tessellate_plane).
    n.triangles += 2.0 * 64 * 64 * static_cast<double>(scene.planes.size());
    n.vertices += 65.0 * 65 * static_cast<double>(scene.planes.size());
    const double bytes =
        n.vertices * k_raster_bytes_per_vertex + n.triangles * k_raster_bytes_per_triangle;
    check_memory_need(bytes, fmt::format("rasterizing {:.0f} triangles{}", n.triangles,
                                         finest > 0 ? fmt::format(" (spheres of {:.0f} segments, "
                                                                  "--tessellation)",
                                                                  finest)
                                                    : std::string()));
    return n;
}

float plane_half_extent(const Scene& scene) {
    Aabb bounds;
    for (const Sphere& s : scene.spheres) {
        bounds.extend(s.center - Vec3(s.radius));
        bounds.extend(s.center + Vec3(s.radius));
    }
    for (const Vec3& p : scene.triangles.positions) bounds.extend(p);
    float size = bounds.empty() ? 1.0f : length(bounds.extent());
    for (const Plane& p : scene.planes)
        size = std::max(size, std::abs(dot(scene.camera.eye - p.point, p.normal)));
    return 1e4f * std::max(size, 1e-3f);
}

float nearest_object(const Scene& scene) {
    const Vec3 eye = scene.camera.eye;
    const Vec3 forward = normalize(scene.camera.look_at - eye);
    float nearest = k_infinity;
    for (const Sphere& s : scene.spheres)
        nearest = std::min(nearest, std::max(0.0f, length(s.center - eye) - s.radius));
    const TriangleSet& tris = scene.triangles;
    for (size_t t = 0; t < tris.size(); ++t) {
        const Vec3 a = tris.positions[tris.indices[t][0]], b = tris.positions[tris.indices[t][1]],
                   c = tris.positions[tris.indices[t][2]];
        // Wholly behind the eye: never in view.
        if (dot(a - eye, forward) <= 0.0f && dot(b - eye, forward) <= 0.0f &&
            dot(c - eye, forward) <= 0.0f)
            continue;
        // The eye in the triangle's plane: seen edge-on, a line of no area.
        const Vec3 n = cross(b - a, c - a);
        const float size = std::max({length(b - a), length(c - a), length(c - b)});
        if (std::abs(dot(n, eye - a)) <= 1e-6f * length(n) * size) continue;
        // The distance to its bounds: no farther than to the triangle itself.
        const Aabb box{min(min(a, b), c), max(max(a, b), c)};
        nearest = std::min(nearest, box.distance_to(eye));
    }
    return nearest;
}

RasterScene tessellate_scene(const Scene& scene, SphereGeometry spheres) {
    const RasterCounts counts = check_raster_memory(scene, spheres);
    RasterScene rs;
    TriangleSet& out = rs.triangles;
    const TriangleSet& in = scene.triangles;
    // Reserved whole: a vector grown by doubling would hold up to three times as much while
    // it moves.
    const auto vertices = static_cast<size_t>(counts.vertices);
    const auto triangles = static_cast<size_t>(counts.triangles);
    out.positions.reserve(vertices);
    out.normals.reserve(vertices);
    out.uvs.reserve(vertices);
    out.indices.reserve(triangles);
    out.material.reserve(triangles);
    out.id.reserve(triangles);
    out.edge_flags.reserve(triangles);
    out.positions = in.positions;
    out.normals = in.normals;
    // Every vertex gets texture coordinates (spheres and planes always have them; triangles
    // without get (0, 0)).
    out.uvs = in.uvs;
    out.uvs.resize(out.positions.size());
    if (!in.colors.empty()) out.colors.reserve(vertices);
    out.colors = in.colors;  // empty, or one per vertex: then white for what is added below

    // Spheres and planes by id, to be merged with the (id-ordered) mesh triangles.
    struct Item {
        PrimitiveId id;
        bool is_plane;
        uint32_t index;
    };
    std::vector<Item> items;
    for (uint32_t i = 0; i < scene.spheres.size(); ++i)
        if (spheres == SphereGeometry::exact && scene.spheres[i].segments == 0)
            rs.spheres.push_back(scene.spheres[i]);
        else
            items.push_back({scene.spheres[i].id, false, i});
    for (uint32_t i = 0; i < scene.planes.size(); ++i)
        items.push_back({scene.planes[i].id, true, i});
    std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.id < b.id; });

    const float half_extent = scene.planes.empty() ? 0.0f : plane_half_extent(scene);
    auto emit = [&](const Item& item) {
        if (item.is_plane)
            tessellate_plane(scene.planes[item.index], scene.camera.eye, half_extent, out);
        else {
            const Sphere& s = scene.spheres[item.index];
            tessellate_sphere(
                s, s.segments > 0 ? s.segments : sphere_segments(projected_radius(s, scene.camera)),
                out);
        }
    };
    size_t next = 0;
    for (size_t t = 0; t < in.size(); ++t) {
        while (next < items.size() && items[next].id < in.id[t]) emit(items[next++]);
        out.indices.push_back(in.indices[t]);
        out.material.push_back(in.material[t]);
        out.id.push_back(in.id[t]);
        out.edge_flags.push_back(in.edge_flags.empty() ? k_all_edges : in.edge_flags[t]);
    }
    while (next < items.size()) emit(items[next++]);
    rs.planes = scene.planes;
    rs.nearest_object = nearest_object(scene);
    return rs;
}

}  // namespace hikari
