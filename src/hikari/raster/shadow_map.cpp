#include "hikari/raster/shadow_map.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "hikari/core/memory_budget.h"
#include "hikari/core/parallel.h"
#include "hikari/frame/tiles.h"
#include "hikari/raster/cull.h"
#include "hikari/raster/shadow_map_lookup.h"
#include "hikari/raster/sphere_raster.h"
#include "hikari/raster/zbuffer.h"
#include "hikari/shading/lights.h"

namespace hikari {

namespace {

constexpr float k_no_caster = std::numeric_limits<float>::infinity();

/// The casters alone: their triangles (the scene's vertex arrays, the casting triangles'
/// indices) for the light's vertex stage, and their exact spheres.
struct Casters {
    TriangleSet triangles;
    std::vector<Sphere> spheres;

    bool empty() const { return triangles.indices.empty() && spheres.empty(); }
};

Casters caster_scene(const RasterScene& raster, const std::vector<uint8_t>& casters) {
    Casters out;
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

/// The bounds of the vertices that the casters' triangles use and of their exact spheres, in
/// the orthonormal frame (origin, u, v, w).
Aabb bounds_in_frame(const Casters& scene, Vec3 origin, Vec3 u, Vec3 v, Vec3 w) {
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

/// What the faces of one build reuse: the casters' projection and the Z-buffer's setup and
/// bins, grown to size by the first face and drawn into again by the others.
struct FaceScratch {
    ScreenProjection projection;
    ZBufferWorkspace zbuffer;
    const FaceDepthDrawer* drawer = nullptr;  ///< null: zbuffer_draw
};

/// The NDC coordinate of texel centre i of `size` (x; y runs the other way, which the callers
/// below only square or take from the matrix).
float texel_ndc(int i, int size) { return 2.0f * (static_cast<float>(i) + 0.5f) / size - 1.0f; }

/// Turns the Z-buffer's depth key of a face (raster/zbuffer.h: view depth 1 / inv_w) at texel
/// (x, y) into the map's depth. Under perspective the key is the distance along the face's axis,
/// and the distance from the light is that times the length of the texel ray's direction scaled
/// to unit axis component, √(1 + (x_ndc / P₀₀)² + (y_ndc / P₁₁)²); both squares are kept per
/// column and row. Under a parallel projection the key is 1 / (1.5 − 0.5 z_ndc)
/// (RasterView::orthographic), and the depth along the light's rays is affine in the NDC
/// coordinates: its terms in x and y are kept per column and row.
struct KeyToDepth {
    bool parallel = false;
    std::vector<float> column, row;  ///< perspective: the squares; parallel: the affine terms
    float per_z_ndc = 0;             ///< parallel: the depth's term in z_ndc

    KeyToDepth(const ShadowMapFace& face, Vec3 origin, Vec3 direction) {
        const int size = face.view.width;
        parallel = face.view.orthographic;
        column.resize(size);
        row.resize(size);
        const Mat4& w = face.world_from_clip;
        const auto along = [&](int c) { return dot(Vec3(w(0, c), w(1, c), w(2, c)), direction); };
        for (int i = 0; i < size; ++i) {
            const float x = texel_ndc(i, size), y = -texel_ndc(i, size);
            if (parallel) {
                column[i] = along(0) * x;
                row[i] = along(1) * y;
            } else {
                const float a = x / face.view.clip_from_view(0, 0);
                const float b = y / face.view.clip_from_view(1, 1);
                column[i] = a * a;
                row[i] = b * b;
            }
        }
        per_z_ndc = along(2);
        if (parallel) row_offset = dot(Vec3(w(0, 3), w(1, 3), w(2, 3)) - origin, direction);
    }

    float operator()(int x, int y, float key) const {
        if (!parallel) return key * std::sqrt(1.0f + column[x] + row[y]);
        const float z_ndc = 3.0f - 2.0f / key;
        return column[x] + row[y] + row_offset + per_z_ndc * z_ndc;
    }

  private:
    float row_offset = 0;
};

/// Renders `view` over `casters` by the vertex stage and the Z-buffer's tile rasterizer, depth
/// only (exact spheres drawn per texel, raster/sphere_raster.h), then turns each texel's depth key
/// into the map's depth (KeyToDepth; on a sphere, its exact hit along the texel's ray).
/// `depth_of(hit)` turns a world point into the map's depth, `origin` and `direction` are the
/// map's. A face in whose view no caster lies is left empty, undrawn.
template <class DepthOf>
ShadowMapFace render_face(const Casters& casters, const RasterView& view, Vec3 origin,
                          Vec3 direction, FaceScratch& scratch, DepthOf depth_of) {
    ShadowMapFace face;
    face.view = view;
    invert(view.clip_from_world, face.world_from_clip);
    ScreenProjection& projection = scratch.projection;
    projection.indexed_allowed = !scratch.drawer;
    project_to_screen(casters.triangles, view, /*cull_back_faces=*/false, projection);
    const SphereRaster spheres =
        prepare_sphere_raster(casters.spheres, view, view_pixel_rays(view), 0);
    const bool no_triangles = !projection.indexed && projection.triangles.empty();
    if (no_triangles && spheres.tile_spheres.empty()) return face;
    const size_t texels = static_cast<size_t>(view.width) * static_cast<size_t>(view.height);
    face.depth.resize(texels);
    if (scratch.drawer)
        (*scratch.drawer)(projection.triangles, view.width, view.height, face.depth.data());
    else if (projection.indexed)
        zbuffer_draw(
            IndexedScreenTriangles{projection.screen.data(), casters.triangles.indices.data(),
                                   casters.triangles.indices.size()},
            view.width, view.height, scratch.zbuffer, nullptr, face.depth.data());
    else
        zbuffer_draw(projection.triangles, view.width, view.height, scratch.zbuffer, nullptr,
                     face.depth.data());
    const KeyToDepth key_to_depth(face, origin, direction);
    for_each_tile(
        view.width, view.height, nullptr,
        [&](const Tile& tile) {
            std::array<float, k_tile_size * k_tile_size> key;
            std::array<uint32_t, k_tile_size * k_tile_size> seen;
            seen.fill(k_no_triangle);
            for (int y = tile.y0; y < tile.y1; ++y)
                std::copy_n(face.depth.data() + static_cast<size_t>(y) * view.width + tile.x0,
                            tile.x1 - tile.x0, key.data() + (y - tile.y0) * k_tile_size);
            draw_spheres_in_tile(spheres, tile, key.data(), seen.data());
            for (int y = tile.y0; y < tile.y1; ++y)
                for (int x = tile.x0; x < tile.x1; ++x) {
                    const int i = (y - tile.y0) * k_tile_size + (x - tile.x0);
                    float depth = k_no_caster;
                    if (spheres.is_sphere(seen[i])) {
                        Ray ray;
                        const Sphere& s = spheres.spheres[seen[i]];
                        const float t = pixel_sphere_hit(spheres.rays, s, x, y, ray);
                        if (t == t) depth = depth_of(ray.at(t));
                    } else if (key[i] < k_no_caster) {
                        depth = key_to_depth(x, y, key[i]);
                    }
                    face.depth[static_cast<size_t>(y) * view.width + x] = depth;
                }
        },
        /*report_tiles=*/false);
    return face;
}

/// A directional light's orthographic map over all the casters: fitted to their bounds in the
/// light's view, so that it serves every receiver, whatever the camera sees.
std::optional<LightShadowMap> directional_map(Vec3 travel, const Casters& casters, int size,
                                              FaceScratch& scratch) {
    if (casters.empty()) return std::nullopt;
    LightShadowMap map;
    map.directional = true;
    map.direction = normalize(travel);
    map.size = size;
    // The light's view: looking along its travel direction, w toward the light.
    const Vec3 w = -map.direction;
    const Vec3 up = std::abs(w.y) < 0.9f ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
    const Vec3 u = normalize(cross(up, w));
    const Vec3 v = cross(w, u);
    // The map's reference point: the casters' centre.
    map.origin =
        bounds_in_frame(casters, Vec3(0.0f), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)).center();
    const Aabb caster_box = bounds_in_frame(casters, map.origin, u, v, w);
    const float x0 = caster_box.min.x, x1 = caster_box.max.x;
    const float y0 = caster_box.min.y, y1 = caster_box.max.y;
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
    map.faces.push_back(
        render_face(casters, view, origin, direction, scratch,
                    [origin, direction](Vec3 hit) { return dot(hit - origin, direction); }));
    return map;
}

/// The nearest and farthest distances from `position` of the bounds of `casters`.
std::pair<float, float> caster_distances(Vec3 position, const Casters& casters) {
    const Aabb bounds =
        bounds_in_frame(casters, Vec3(0.0f), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1));
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
ShadowMapFace perspective_face(const Casters& casters, Vec3 position, Vec3 axis, Vec3 up,
                               float fov_y, float near_plane, float far_dist, int size,
                               FaceScratch& scratch) {
    RasterView view;
    view.eye = position;
    view.width = view.height = size;
    view.near_plane = near_plane;
    view.far_plane = 1.01f * far_dist + near_plane;
    view.view_from_world = look_at(position, position + axis, up);
    view.clip_from_view = perspective(fov_y, 1.0f, view.near_plane, view.far_plane);
    view.screen_from_clip = viewport(size, size);
    view.clip_from_world = view.clip_from_view * view.view_from_world;
    return render_face(casters, view, position, axis, scratch,
                       [position](Vec3 hit) { return length(hit - position); });
}

/// A point light's cube map: six 90° views along ±x, ±y, ±z, in that order (face 2a + (d_a < 0)
/// holds the directions whose largest component is axis a). Faces that see no caster stay
/// undrawn.
std::optional<LightShadowMap> point_map(Vec3 position, const Casters& casters, int size,
                                        FaceScratch& scratch) {
    if (casters.empty()) return std::nullopt;
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
        map.faces.push_back(perspective_face(casters, position, axis, up, 90.0f, near_plane,
                                             far_dist, size, scratch));
    }
    return map;
}

/// Degrees added to a spot light's cone for its map, so that filtered lookups at the cone's edge
/// stay inside the map; the map's half-angle stays under 85°.
constexpr float k_cone_map_margin = 2.0f;
constexpr float k_max_cone_map_half_angle = 85.0f;

/// A spot light's map: one perspective face from the light along its axis, over its cone (what
/// the light does not reach needs no map).
std::optional<LightShadowMap> cone_map(const LightShadowView& light, const Casters& casters,
                                       int size, FaceScratch& scratch) {
    if (casters.empty()) return std::nullopt;
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
                                         near_plane, far_dist, size, scratch));
    return map;
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

namespace {

/// The map of one light over `casters` (null when it casts none).
std::shared_ptr<const LightShadowMap> light_map(const LightShadowView& view, const Casters& casters,
                                                int size, FaceScratch& scratch) {
    std::optional<LightShadowMap> map;
    switch (view.projection) {
        case ShadowProjection::parallel:
            map = directional_map(view.direction, casters, size, scratch);
            break;
        case ShadowProjection::cube:  // area lights: their centre
            map = point_map(view.origin, casters, size, scratch);
            break;
        case ShadowProjection::cone:
            map = cone_map(view, casters, size, scratch);
            break;
        case ShadowProjection::none:
            break;
    }
    return map ? std::make_shared<const LightShadowMap>(std::move(*map)) : nullptr;
}

/// What a light's map is drawn from beyond the geometry, spelled exactly (floats by their bits):
/// its projection, position, direction and cone, the map size, and the casters' triangle
/// counts per object (a sphere's tessellation follows the camera under flat and Gouraud
/// shading, and its triangle count grows with its segments).
std::string map_version(const LightShadowView& view, int size, const std::string& casters) {
    const auto bits = [](float f) { return std::bit_cast<uint32_t>(f); };
    return fmt::format("{} {:x},{:x},{:x} {:x},{:x},{:x} {:x} {} {}",
                       static_cast<int>(view.projection), bits(view.origin.x), bits(view.origin.y),
                       bits(view.origin.z), bits(view.direction.x), bits(view.direction.y),
                       bits(view.direction.z), bits(view.half_angle), size, casters);
}

/// The casters of `raster` as runs of triangles per object id and exact spheres (map_version).
std::string caster_counts(const RasterScene& raster, const std::vector<uint8_t>& casters) {
    std::string out;
    const std::vector<uint32_t>& id = raster.triangles.id;
    size_t run = 0;
    for (size_t t = 0; t < id.size(); ++t) {
        if (!casters[t]) continue;
        ++run;
        if (t + 1 == id.size() || id[t + 1] != id[t]) {
            out += fmt::format("{}:{} ", id[t], run);
            run = 0;
        }
    }
    for (const Sphere& s : raster.spheres)
        if (s.casts_shadow) out += fmt::format("s{} ", s.id);
    return out;
}

/// Counts the faces and texels of `map` drawn in this render (--stats).
void count_drawn(const LightShadowMap& map, RenderStats& stats) {
    for (const ShadowMapFace& face : map.faces) {
        if (face.depth.empty()) continue;
        ++stats.shadow_map_faces;
        stats.shadow_map_texels += face.depth.size();
    }
}

}  // namespace

ShadowMaps build_shadow_maps(const Scene& scene, const RasterScene& raster,
                             const std::vector<uint8_t>& casters, int size,
                             const FaceDepthDrawer* drawer) {
    check_shadow_map_memory(scene, raster, size);
    ShadowMaps maps;
    maps.lights.resize(scene.lights.size());
    const Casters caster_triangles = caster_scene(raster, casters);
    FaceScratch scratch;
    scratch.drawer = drawer;
    for (size_t l = 0; l < scene.lights.size(); ++l)
        maps.lights[l] = light_map(shadow_view(scene.lights[l]), caster_triangles, size, scratch);
    return maps;
}

std::shared_ptr<const ShadowMaps> shadow_maps_for_render(
    const Scene& scene, const RasterScene& raster, int size, BuildCache* cache,
    SharedShadowMaps* shared, RenderStats* stats, const FaceDepthDrawer* drawer) {
    if (shared && shared->maps) return shared->maps;
    const std::vector<uint8_t> casting = shadow_casting_triangles(scene, raster);
    auto maps = std::make_shared<ShadowMaps>();
    if (!cache || cache->scene() != &scene) {
        *maps = build_shadow_maps(scene, raster, casting, size, drawer);
        if (stats)
            for (const auto& map : maps->lights)
                if (map) count_drawn(*map, *stats);
    } else {
        // A session: each light's map kept under its index until what it is drawn from changes.
        check_shadow_map_memory(scene, raster, size);
        const std::string counts = caster_counts(raster, casting);
        std::optional<Casters> casters;  // made for the first map to draw
        FaceScratch scratch;
        scratch.drawer = drawer;
        for (const Light& light : scene.lights) {
            const LightShadowView view = shadow_view(light);
            bool built = false;
            auto map = cache->get_version<std::shared_ptr<const LightShadowMap>>(
                fmt::format("shadow map {}", maps->lights.size()), map_version(view, size, counts),
                SceneParts::geometry,
                [&] {
                    if (!casters) casters.emplace(caster_scene(raster, casting));
                    return light_map(view, *casters, size, scratch);
                },
                &built);
            if (stats && *map) {
                if (built)
                    count_drawn(**map, *stats);
                else
                    ++stats->shadow_maps_kept;
            }
            maps->lights.push_back(*map);
        }
    }
    if (shared) shared->maps = maps;
    return maps;
}

bool lit_in_shadow_map(const LightShadowMap& map, Vec3 p, Vec3 n) { return lit_in_map(map, p, n); }

float pcf_shadow_fraction(const LightShadowMap& map, Vec3 p, Vec3 n) {
    return percentage_closer(map, map_lookup(map, p, n), k_pcf_radius_texels, 1.0f);
}

float pcss_shadow_fraction(const LightShadowMap& map, Vec3 p, Vec3 n, float light_radius) {
    return pcss_fraction(map, p, n, light_radius);
}

bool plane_blocks_light(const Scene& scene, const LightShadowView& view, Vec3 p) {
    return planes_block_light(scene.planes.data(), scene.planes.size(), view, p);
}

}  // namespace hikari
