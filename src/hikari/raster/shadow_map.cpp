#include "hikari/raster/shadow_map.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "hikari/core/memory_budget.h"
#include "hikari/core/parallel.h"
#include "hikari/raster/cull.h"
#include "hikari/raster/sphere_raster.h"
#include "hikari/raster/zbuffer.h"
#include "hikari/shading/lights.h"

namespace hikari {

namespace {

constexpr float k_no_caster = std::numeric_limits<float>::infinity();

/// Bias and normal offset, in texels (lit_in_shadow_map). A point's depth may differ from
/// its texel's centre depth by up to half a texel diagonal times tan θ on a plane, hence the
/// slope term of one texel per unit of tan θ; tan θ is capped where the light grazes.
constexpr float k_constant_bias_texels = 1.0f;
constexpr float k_normal_offset_texels = 1.0f;
constexpr float k_max_slope = 8.0f;

/// The casters alone, as a scene of their own for the light's vertex stage.
RasterScene caster_scene(const RasterScene& raster, const std::vector<uint8_t>& casters) {
    RasterScene out;
    const TriangleSet& all = raster.triangles;
    out.triangles.positions = all.positions;
    out.triangles.normals = all.normals;
    for (size_t t = 0; t < all.size(); ++t) {
        if (!casters[t]) continue;
        out.triangles.indices.push_back(all.indices[t]);
        out.triangles.material.push_back(all.material[t]);
        out.triangles.id.push_back(all.id[t]);
    }
    for (const Sphere& s : raster.spheres)
        if (s.casts_shadow) out.spheres.push_back(s);
    return out;
}

/// The bounds of the vertices that `scene`'s triangles use and of its exact spheres, in the
/// orthonormal frame (origin, u, v, w).
Aabb bounds_in_frame(const RasterScene& scene, Vec3 origin, Vec3 u, Vec3 v, Vec3 w) {
    const TriangleSet& tris = scene.triangles;
    Aabb b;
    for (const auto& tri : tris.indices)
        for (uint32_t i : tri) {
            const Vec3 d = tris.positions[i] - origin;
            b.extend(Vec3(dot(d, u), dot(d, v), dot(d, w)));
        }
    for (const Sphere& s : scene.spheres) {
        const Vec3 d = s.center - origin;
        const Vec3 c(dot(d, u), dot(d, v), dot(d, w));
        b.extend(c - Vec3(s.radius));
        b.extend(c + Vec3(s.radius));
    }
    return b;
}

/// Renders `view` over `casters` by the project's vertex stage and Z-buffer (exact spheres drawn
/// per texel, raster/sphere_raster.h), then stores each texel's exact depth: its centre ray
/// intersected with the plane of the caster seen there, or with the sphere seen there.
/// `depth_of(hit)` turns a world point into the map's depth.
template <class DepthOf>
ShadowMapFace render_face(const RasterScene& casters, const RasterView& view, DepthOf depth_of) {
    ShadowMapFace face;
    face.view = view;
    invert(view.clip_from_world, face.world_from_clip);
    const ProjectedScene ps = project_triangles(casters, view, /*cull_back_faces=*/false);
    const SphereRaster spheres = prepare_sphere_raster(
        ps.scene.spheres, view, view_pixel_rays(view), static_cast<uint32_t>(ps.triangles.size()));
    const VisibilityBuffer vis =
        zbuffer_visibility(ps.triangles, view.width, view.height, nullptr, &spheres);
    face.depth.assign(vis.triangle.size(), k_no_caster);
    const TriangleSet& tris = ps.scene.triangles;
    hikari::parallel_for(tbb::blocked_range<int>(0, view.height), [&](const auto& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y)
            for (int x = 0; x < view.width; ++x) {
                const size_t texel = static_cast<size_t>(y) * view.width + x;
                if (vis.triangle[texel] == k_no_triangle) continue;
                if (spheres.is_sphere(vis.triangle[texel])) {
                    Ray ray;
                    const Sphere& s = spheres.spheres[vis.triangle[texel] - spheres.first_id];
                    const float t = pixel_sphere_hit(spheres.rays, s, x, y, ray);
                    if (t == t) face.depth[texel] = depth_of(ray.at(t));
                    continue;
                }
                const auto& idx = tris.indices[ps.triangles[vis.triangle[texel]].source];
                const Vec3 a = tris.positions[idx[0]];
                const Vec3 n = face_normal(a, tris.positions[idx[1]], tris.positions[idx[2]]);
                // The texel centre's ray: its points at NDC depth −1 and +1.
                const float ndc_x = 2.0f * (x + 0.5f) / view.width - 1.0f;
                const float ndc_y = 1.0f - 2.0f * (y + 0.5f) / view.height;
                const Vec4 h0 = face.world_from_clip * Vec4(ndc_x, ndc_y, -1.0f, 1.0f);
                const Vec4 h1 = face.world_from_clip * Vec4(ndc_x, ndc_y, 1.0f, 1.0f);
                const Vec3 o = h0.xyz() / h0.w;
                const Vec3 d = h1.xyz() / h1.w - o;
                const float denominator = dot(n, d);
                if (denominator == 0.0f) continue;  // seen edge-on: the rasterizer's call
                const float t = dot(n, a - o) / denominator;
                face.depth[texel] = depth_of(o + t * d);
            }
    });
    return face;
}

/// A directional light's orthographic map over the casters that lie above `receivers`.
std::optional<LightShadowMap> directional_map(Vec3 travel, const RasterScene& casters,
                                              const Aabb* receivers, int size) {
    LightShadowMap map;
    map.directional = true;
    map.direction = normalize(travel);
    map.size = size;
    map.origin = receivers ? receivers->center() : Vec3(0.0f);
    // The light's view: looking along its travel direction, w toward the light.
    const Vec3 w = -map.direction;
    const Vec3 up = std::abs(w.y) < 0.9f ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
    const Vec3 u = normalize(cross(up, w));
    const Vec3 v = cross(w, u);
    if (!receivers) {  // fitted to the casters alone: the map's reference is their centre
        const Aabb world =
            bounds_in_frame(casters, Vec3(0.0f), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1));
        if (!world.empty()) map.origin = world.center();
    }
    const Aabb caster_box = bounds_in_frame(casters, map.origin, u, v, w);
    Aabb receiver_box = caster_box;
    if (receivers) {
        receiver_box = Aabb{};
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3 p{(corner & 1) ? receivers->max.x : receivers->min.x,
                         (corner & 2) ? receivers->max.y : receivers->min.y,
                         (corner & 4) ? receivers->max.z : receivers->min.z};
            const Vec3 d = p - map.origin;
            receiver_box.extend(Vec3(dot(d, u), dot(d, v), dot(d, w)));
        }
    }
    // Only casters over the receivers matter, seen along the light.
    const float x0 = std::max(caster_box.min.x, receiver_box.min.x);
    const float x1 = std::min(caster_box.max.x, receiver_box.max.x);
    const float y0 = std::max(caster_box.min.y, receiver_box.min.y);
    const float y1 = std::min(caster_box.max.y, receiver_box.max.y);
    if (caster_box.empty() || !(x0 <= x1 && y0 <= y1)) return std::nullopt;
    // Square texels, with a margin of one texel all round.
    const float extent = std::max({x1 - x0, y1 - y0, 1e-6f * (1.0f + length(caster_box.extent()))});
    map.texel_size = extent / static_cast<float>(size - 2);
    const float half = 0.5f * extent + map.texel_size;
    const float cx = 0.5f * (x0 + x1), cy = 0.5f * (y0 + y1);
    const float depth_margin = 1e-3f * (caster_box.max.z - caster_box.min.z) + map.texel_size;

    RasterView view;
    view.eye = map.origin + w * (caster_box.max.z + depth_margin);
    view.width = view.height = size;
    // View depth runs along −w from map.origin: the casters lie between these two.
    const float near_depth = -(caster_box.max.z + depth_margin);
    const float far_depth = -(caster_box.min.z - depth_margin);
    view.near_plane = 1.0f;  // unused by a parallel projection's depth key
    view.far_plane = 1.0f + far_depth - near_depth;
    view.view_from_world = look_at(map.origin, map.origin - w, v);
    view.clip_from_view =
        orthographic(cx - half, cx + half, cy - half, cy + half, near_depth, far_depth);
    view.screen_from_clip = viewport(size, size);
    view.clip_from_world = view.clip_from_view * view.view_from_world;
    view.orthographic = true;
    const Vec3 origin = map.origin, direction = map.direction;
    map.faces.push_back(render_face(
        casters, view, [origin, direction](Vec3 hit) { return dot(hit - origin, direction); }));
    return map;
}

/// The nearest and farthest distances from `position` of the bounds of `casters`.
std::pair<float, float> caster_distances(Vec3 position, const RasterScene& casters) {
    Aabb bounds;
    for (const auto& tri : casters.triangles.indices)
        for (uint32_t i : tri) bounds.extend(casters.triangles.positions[i]);
    for (const Sphere& s : casters.spheres) {
        bounds.extend(s.center - Vec3(s.radius));
        bounds.extend(s.center + Vec3(s.radius));
    }
    float far_dist = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p{(corner & 1) ? bounds.max.x : bounds.min.x,
                     (corner & 2) ? bounds.max.y : bounds.min.y,
                     (corner & 4) ? bounds.max.z : bounds.min.z};
        far_dist = std::max(far_dist, length(p - position));
    }
    const Vec3 nearest = max(min(position, bounds.max), bounds.min);
    return {length(nearest - position), far_dist};
}

/// One square perspective face from `position` along unit `axis`, `fov_y` degrees wide, whose
/// depths are distances from `position`.
ShadowMapFace perspective_face(const RasterScene& casters, Vec3 position, Vec3 axis, Vec3 up,
                               float fov_y, float near_plane, float far_dist, int size) {
    RasterView view;
    view.eye = position;
    view.width = view.height = size;
    view.near_plane = near_plane;
    view.far_plane = 1.01f * far_dist + near_plane;
    view.view_from_world = look_at(position, position + axis, up);
    view.clip_from_view = perspective(fov_y, 1.0f, view.near_plane, view.far_plane);
    view.screen_from_clip = viewport(size, size);
    view.clip_from_world = view.clip_from_view * view.view_from_world;
    return render_face(casters, view, [position](Vec3 hit) { return length(hit - position); });
}

/// A point light's cube map: six 90° views along ±x, ±y, ±z, in that order (face 2a + (d_a < 0)
/// holds the directions whose largest component is axis a).
std::optional<LightShadowMap> point_map(Vec3 position, const RasterScene& casters, int size) {
    if (casters.triangles.indices.empty() && casters.spheres.empty()) return std::nullopt;
    LightShadowMap map;
    map.origin = position;
    map.size = size;
    map.texel_size = 2.0f / static_cast<float>(size);
    const auto [nearest, far_dist] = caster_distances(position, casters);
    // A point at distance d has depth at least d / √3 in the face that holds it.
    const float near_plane = std::max(0.5f * nearest, 1e-5f * far_dist) / std::sqrt(3.0f);
    const std::array<Vec3, 6> axes = {Vec3(1, 0, 0),  Vec3(-1, 0, 0), Vec3(0, 1, 0),
                                      Vec3(0, -1, 0), Vec3(0, 0, 1),  Vec3(0, 0, -1)};
    for (const Vec3& axis : axes) {
        const Vec3 up = axis.y != 0.0f ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
        map.faces.push_back(
            perspective_face(casters, position, axis, up, 90.0f, near_plane, far_dist, size));
    }
    return map;
}

/// Degrees added to a spot light's cone for its map, so that filtered lookups at the cone's edge
/// stay inside the map; the map's half-angle stays under 85°.
constexpr float k_cone_map_margin = 2.0f;
constexpr float k_max_cone_map_half_angle = 85.0f;

/// A spot light's map: one perspective face from the light along its axis, over its cone (what
/// the light does not reach needs no map).
std::optional<LightShadowMap> cone_map(const LightShadowView& light, const RasterScene& casters,
                                       int size) {
    if (casters.triangles.indices.empty() && casters.spheres.empty()) return std::nullopt;
    LightShadowMap map;
    map.cone = true;
    map.origin = light.origin;
    map.direction = normalize(light.direction);
    map.size = size;
    const float half = std::min(light.half_angle + k_cone_map_margin, k_max_cone_map_half_angle);
    const float tan_half = std::tan(half * (std::numbers::pi_v<float> / 180.0f));
    map.texel_size = 2.0f * tan_half / static_cast<float>(size);
    const auto [nearest, far_dist] = caster_distances(map.origin, casters);
    // A point at distance d has depth at least d · cos of the face's corner angle, whose tangent
    // is √2 · tan(half).
    const float near_plane =
        std::max(0.5f * nearest, 1e-5f * far_dist) / std::sqrt(1.0f + 2.0f * tan_half * tan_half);
    const Vec3 up = std::abs(map.direction.y) < 0.9f ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
    map.faces.push_back(perspective_face(casters, map.origin, map.direction, up, 2.0f * half,
                                         near_plane, far_dist, size));
    return map;
}

/// The face of a cube map that holds direction `d` from the light.
size_t cube_face(Vec3 d) {
    const Vec3 a(std::abs(d.x), std::abs(d.y), std::abs(d.z));
    if (a.x >= a.y && a.x >= a.z) return d.x < 0.0f ? 1 : 0;
    if (a.y >= a.z) return d.y < 0.0f ? 3 : 2;
    return d.z < 0.0f ? 5 : 4;
}

}  // namespace

void check_shadow_map_memory(const Scene& scene, const RasterScene& raster, int size) {
    double faces = 0;
    for (const Light& light : scene.lights) switch (shadow_view(light).projection) {
            case ShadowProjection::parallel:
            case ShadowProjection::cone:
                faces += 1;
                break;
            case ShadowProjection::cube:
                faces += 6;
                break;
            case ShadowProjection::none:
                break;
        }
    if (faces == 0) return;
    const double texels = static_cast<double>(size) * size;
    // Kept: one depth per texel of every face. While a face renders: its visibility buffer,
    // the sphere rays of its texels and the copy of the casters (caster_scene, projected).
    const double kept = faces * texels * sizeof(float);
    const double face = texels * (sizeof(uint32_t) + sizeof(Ray));
    const double casters =
        static_cast<double>(raster.triangles.size()) *
            (sizeof(std::array<uint32_t, 3>) + 2 * sizeof(uint32_t)) +
        static_cast<double>(raster.triangles.positions.size()) * 3 * sizeof(Vec3);
    check_memory_need(kept + face + casters,
                      fmt::format("{:.0f} shadow map faces of {}x{} texels (--shadow-map-size)",
                                  faces, size, size));
}

std::vector<uint8_t> shadow_casting_triangles(const Scene& scene, const RasterScene& raster) {
    std::vector<uint8_t> casts_by_id(scene.primitive_count, 1);
    for (const Sphere& s : scene.spheres) casts_by_id[s.id] = s.casts_shadow ? 1 : 0;
    for (const Plane& p : scene.planes) casts_by_id[p.id] = 0;
    const TriangleSet& own = scene.triangles;
    for (size_t t = 0; t < own.casts_shadow.size(); ++t)
        casts_by_id[own.id[t]] = own.casts_shadow[t];
    std::vector<uint8_t> casters(raster.triangles.size());
    for (size_t t = 0; t < casters.size(); ++t) casters[t] = casts_by_id[raster.triangles.id[t]];
    return casters;
}

ShadowMaps build_shadow_maps(const Scene& scene, const RasterScene& raster,
                             const std::vector<uint8_t>& casters, const Aabb* receivers, int size) {
    check_shadow_map_memory(scene, raster, size);
    ShadowMaps maps;
    maps.lights.resize(scene.lights.size());
    if (receivers && receivers->empty()) return maps;
    const RasterScene caster_triangles = caster_scene(raster, casters);
    for (size_t l = 0; l < scene.lights.size(); ++l) {
        const LightShadowView view = shadow_view(scene.lights[l]);
        switch (view.projection) {
            case ShadowProjection::parallel:
                maps.lights[l] = directional_map(view.direction, caster_triangles, receivers, size);
                break;
            case ShadowProjection::cube:  // area lights: their centre
                maps.lights[l] = point_map(view.origin, caster_triangles, size);
                break;
            case ShadowProjection::cone:
                maps.lights[l] = cone_map(view, caster_triangles, size);
                break;
            case ShadowProjection::none:
                break;
        }
    }
    return maps;
}

namespace {

/// A receiver point as the map sees it: the lookup point (moved off the surface by the normal
/// offset), its depth, the world size of a texel there, and the depth bias allowed.
struct MapLookup {
    Vec3 q;
    float depth = 0;
    float texel = 0;
    float tan_theta = 0;
    Vec3 across1, across2;  ///< unit directions across the map at q (its texel rows, columns)
};

MapLookup map_lookup(const LightShadowMap& map, Vec3 p, Vec3 n) {
    MapLookup m;
    const Vec3 to_light = map.directional ? -map.direction : normalize(map.origin - p);
    m.texel = map.directional ? map.texel_size : map.texel_size * length(p - map.origin);
    const float cos_theta = std::clamp(dot(n, to_light), 0.0f, 1.0f);
    const float sin_theta = std::sqrt(1.0f - cos_theta * cos_theta);
    m.tan_theta = std::min(sin_theta / std::max(cos_theta, 1e-6f), k_max_slope);
    m.q = p + n * (k_normal_offset_texels * m.texel);
    m.depth = map.directional ? dot(m.q - map.origin, map.direction) : length(m.q - map.origin);
    const Vec3 w = map.directional ? map.direction : normalize(m.q - map.origin);
    const Vec3 up = std::abs(w.y) < 0.9f ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
    m.across1 = normalize(cross(up, w));
    m.across2 = cross(w, m.across1);
    return m;
}

/// The caster depth the map holds in the direction of world point `x` (seen from the light),
/// or +infinity outside the map.
float caster_depth(const LightShadowMap& map, Vec3 x) {
    const ShadowMapFace& face =
        map.directional || map.cone ? map.faces.front() : map.faces[cube_face(x - map.origin)];
    const Vec4 clip = face.view.clip_from_world * Vec4(x, 1.0f);
    if (!(clip.w > 0.0f)) return k_no_caster;
    const Vec3 screen = transform_point(face.view.screen_from_clip, clip.xyz() / clip.w);
    if (!(screen.x >= 0.0f && screen.y >= 0.0f && screen.x < static_cast<float>(map.size) &&
          screen.y < static_cast<float>(map.size)))
        return k_no_caster;  // outside the map: no caster there
    return face.depth[static_cast<size_t>(screen.y) * static_cast<size_t>(map.size) +
                      static_cast<size_t>(screen.x)];
}

/// The lookup point moved (i, j) texels across the map, at the receiver's distance (for a cube
/// map, a texel's angle about the light).
Vec3 offset_lookup(const MapLookup& m, float i, float j) {
    return m.q + (i * m.texel) * m.across1 + (j * m.texel) * m.across2;
}

/// The fraction of a (2k + 1)² grid of lookups, `stride` texels apart around m, that see no
/// caster nearer than the receiver (percentage-closer filtering: Reeves, Salesin & Cook 1987).
float percentage_closer(const LightShadowMap& map, const MapLookup& m, int k, float stride) {
    // Neighbouring lookups on a receiver sloped by θ differ in depth by up to tan θ per texel.
    const float bias = m.texel * (k_constant_bias_texels + m.tan_theta * (1.0f + k * stride));
    int lit = 0;
    for (int j = -k; j <= k; ++j)
        for (int i = -k; i <= k; ++i)
            lit += m.depth <= caster_depth(map, offset_lookup(m, i * stride, j * stride)) + bias
                       ? 1
                       : 0;
    return static_cast<float>(lit) / static_cast<float>((2 * k + 1) * (2 * k + 1));
}

}  // namespace

bool lit_in_shadow_map(const LightShadowMap& map, Vec3 p, Vec3 n) {
    const MapLookup m = map_lookup(map, p, n);
    return m.depth <= caster_depth(map, m.q) + m.texel * (k_constant_bias_texels + m.tan_theta);
}

float pcf_shadow_fraction(const LightShadowMap& map, Vec3 p, Vec3 n) {
    return percentage_closer(map, map_lookup(map, p, n), k_pcf_radius_texels, 1.0f);
}

float pcss_shadow_fraction(const LightShadowMap& map, Vec3 p, Vec3 n, float light_radius) {
    if (map.directional || !(light_radius > 0.0f)) return pcf_shadow_fraction(map, p, n);
    MapLookup m = map_lookup(map, p, n);
    // Kernels wider than their lookups turn a texel-aligned grid into bands; a grid turned by an
    // angle hashed from the point turns them into fine noise instead (the same for any thread).
    const uint32_t hash = (std::bit_cast<uint32_t>(p.x) * 0x9e3779b1u) ^
                          (std::bit_cast<uint32_t>(p.y) * 0x85ebca77u) ^
                          (std::bit_cast<uint32_t>(p.z) * 0xc2b2ae3du);
    const float angle =
        static_cast<float>((hash ^ (hash >> 15)) * 0x2c1b3c6du >> 8) * (6.2831853f / 16777216.0f);
    const Vec3 a1 = m.across1, a2 = m.across2;
    m.across1 = std::cos(angle) * a1 + std::sin(angle) * a2;
    m.across2 = std::cos(angle) * a2 - std::sin(angle) * a1;
    // Texels are m.texel wide at the receiver's distance d_r; an occluder at depth d_b hides part
    // of a light of radius R from it when it lies within R (d_r − d_b) / d_b of the receiver's
    // line to the light's centre, measured at the receiver: up to 3R for d_b >= d_r / 4.
    const float max_radius = k_pcss_max_radius_fraction * static_cast<float>(map.size);
    const float search = std::min(3.0f * light_radius / m.texel, max_radius);
    const int k = k_pcss_search_steps;
    const float stride = std::max(search / k, 1.0f);
    const float bias = m.texel * (k_constant_bias_texels + m.tan_theta * (1.0f + k * stride));
    double blocker_sum = 0;
    int blockers = 0;
    for (int j = -k; j <= k; ++j)
        for (int i = -k; i <= k; ++i) {
            const float d = caster_depth(map, offset_lookup(m, i * stride, j * stride));
            if (d + bias < m.depth) {
                blocker_sum += d;
                ++blockers;
            }
        }
    if (blockers == 0) return 1.0f;
    // Fernando 2005: penumbra width w = R (d_r − d_b) / d_b at the receiver, by similar triangles.
    const float d_blocker = static_cast<float>(blocker_sum / blockers);
    const float penumbra = light_radius * (m.depth - d_blocker) / std::max(d_blocker, 1e-6f);
    const float radius = std::clamp(penumbra / m.texel, 1.0f, max_radius);
    const int steps = std::min(static_cast<int>(std::ceil(radius)), k_pcss_max_steps);
    return percentage_closer(map, m, steps, radius / static_cast<float>(steps));
}

bool plane_blocks_light(const Scene& scene, const LightShadowView& view, Vec3 p) {
    for (const Plane& plane : scene.planes) {
        if (!plane.casts_shadow) continue;
        const float side = dot(p - plane.point, plane.normal);
        // A point on the plane (the plane itself, as a receiver) is never behind it.
        if (!(std::abs(side) > 1e-4f * (1.0f + length(p - plane.point)))) continue;
        bool blocked = false;
        if (view.projection == ShadowProjection::parallel)
            blocked = side * dot(-view.direction, plane.normal) < 0.0f;
        else if (view.projection != ShadowProjection::none)
            blocked = side * dot(view.origin - plane.point, plane.normal) < 0.0f;
        if (blocked) return true;
    }
    return false;
}

}  // namespace hikari
