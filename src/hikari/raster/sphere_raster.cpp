#include "hikari/raster/sphere_raster.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "hikari/geometry/intersect.h"

namespace hikari {

Ray PixelRays::at(int x, int y) const {
    if (from_camera)
        return camera_ray(frame, static_cast<float>(x) + 0.5f + sample_offset.x,
                          static_cast<float>(y) + 0.5f + sample_offset.y);
    // The texel centre's line, from its point on the near plane (NDC z = −1) to the far one.
    const float ndc_x = 2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(width) - 1.0f;
    const float ndc_y = 1.0f - 2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(height);
    const Vec4 h0 = world_from_clip * Vec4(ndc_x, ndc_y, -1.0f, 1.0f);
    const Vec4 h1 = world_from_clip * Vec4(ndc_x, ndc_y, 1.0f, 1.0f);
    const Vec3 o = h0.xyz() / h0.w;
    return {o, normalize(h1.xyz() / h1.w - o)};
}

PixelRays camera_pixel_rays(const Camera& camera, const RasterView& view) {
    PixelRays r;
    r.from_camera = true;
    r.frame = make_camera_frame(camera);
    r.sample_offset = view.sample_offset;
    r.width = view.width, r.height = view.height;
    return r;
}

PixelRays view_pixel_rays(const RasterView& view) {
    PixelRays r;
    r.from_camera = false;
    invert(view.clip_from_world, r.world_from_clip);
    r.width = view.width, r.height = view.height;
    return r;
}

namespace {

/// Every pixel whose ray may meet `s`: the screen bounds of the part of its bounding box in front
/// of the near plane (the sphere's part there lies in that convex polytope, and projection keeps
/// convex hulls of points in front of the eye), grown by one pixel, since the rays are made by
/// other arithmetic than the matrices. The pixels' rays start at the near plane (a shadow map's
/// texels) or at the eye with nothing nearer than the near plane (make_raster_view), so the cut
/// loses nothing; without it, a small sphere reaching across the eye's plane (beside a point
/// light, in a cube face) would have to be tried at every pixel.
PixelRect screen_bound(const Sphere& s, const RasterView& view) {
    const PixelRect whole{0, 0, view.width, view.height};
    float lo_x = k_infinity, lo_y = k_infinity, hi_x = -k_infinity, hi_y = -k_infinity;
    std::array<Vec4, 8> corner;
    for (int k = 0; k < 8; ++k) {
        const Vec3 p = s.center + s.radius * Vec3((k & 1) ? 1.0f : -1.0f, (k & 2) ? 1.0f : -1.0f,
                                                  (k & 4) ? 1.0f : -1.0f);
        corner[k] = view.clip_from_world * Vec4(p, 1.0f);
    }
    // Signed distance to the near plane in clip space (z = −w), ≥ 0 in front (raster/clip.h).
    auto near_distance = [](Vec4 c) { return c.z + c.w; };
    int kept = 0;
    auto take = [&](Vec4 c) {
        if (!(c.w > 0.0f)) return;
        ++kept;
        const Vec3 screen = transform_point(view.screen_from_clip, c.xyz() * (1.0f / c.w));
        lo_x = std::min(lo_x, screen.x), hi_x = std::max(hi_x, screen.x);
        lo_y = std::min(lo_y, screen.y), hi_y = std::max(hi_y, screen.y);
    };
    for (int k = 0; k < 8; ++k)
        if (near_distance(corner[k]) >= 0.0f) take(corner[k]);
    // Where the box's twelve edges cross the near plane.
    for (int k = 0; k < 8; ++k)
        for (const int bit : {1, 2, 4}) {
            if (k & bit) continue;
            const Vec4 a = corner[k], b = corner[k | bit];
            const float da = near_distance(a), db = near_distance(b);
            if ((da >= 0.0f) != (db >= 0.0f)) take(a + (b - a) * (da / (da - db)));
        }
    // Wholly behind the near plane: the pixels' rays never meet it.
    if (kept == 0) return {};
    if (!(std::isfinite(lo_x) && std::isfinite(lo_y) && std::isfinite(hi_x) && std::isfinite(hi_y)))
        return whole;
    // Pixel i is sampled at i + ½ in this (offset) screen space.
    const auto clamp_x = [&](float v) {
        return static_cast<int>(std::clamp(v, -1.0f, view.width + 1.0f));
    };
    const auto clamp_y = [&](float v) {
        return static_cast<int>(std::clamp(v, -1.0f, view.height + 1.0f));
    };
    PixelRect r;
    r.x0 = std::max(0, clamp_x(std::floor(lo_x - 0.5f)) - 1);
    r.y0 = std::max(0, clamp_y(std::floor(lo_y - 0.5f)) - 1);
    r.x1 = std::min(view.width, clamp_x(std::ceil(hi_x - 0.5f)) + 2);
    r.y1 = std::min(view.height, clamp_y(std::ceil(hi_y - 0.5f)) + 2);
    if (r.x1 <= r.x0 || r.y1 <= r.y0) return {};
    return r;
}

bool holds(const PixelRect& r, int x, int y) {
    return x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1;
}

}  // namespace

SphereRaster prepare_sphere_raster(std::span<const Sphere> spheres, const RasterView& view,
                                   PixelRays rays, uint32_t first_id) {
    SphereRaster out;
    out.spheres = spheres;
    out.rays = rays;
    out.clip_from_world = view.clip_from_world;
    out.orthographic = view.orthographic;
    out.first_id = first_id;
    out.bounds.reserve(spheres.size());
    for (const Sphere& s : spheres) out.bounds.push_back(screen_bound(s, view));
    // Bin the bounds to the tiles, counting then filling, so that each tile's list keeps the
    // spheres' order (ties go to the lower index, as in the ray tracer).
    out.tiles_x = (view.width + k_tile_size - 1) / k_tile_size;
    const int tiles_y = (view.height + k_tile_size - 1) / k_tile_size;
    out.tile_begin.assign(static_cast<size_t>(out.tiles_x) * tiles_y + 1, 0);
    auto for_tiles = [&](const PixelRect& b, auto&& fn) {
        const int x1 = std::min(b.x1, view.width), y1 = std::min(b.y1, view.height);
        if (b.x0 >= x1 || b.y0 >= y1) return;
        for (int ty = b.y0 / k_tile_size; ty <= (y1 - 1) / k_tile_size; ++ty)
            for (int tx = b.x0 / k_tile_size; tx <= (x1 - 1) / k_tile_size; ++tx)
                fn(static_cast<size_t>(ty) * out.tiles_x + tx);
    };
    for (const PixelRect& b : out.bounds)
        for_tiles(b, [&](size_t tile) { ++out.tile_begin[tile + 1]; });
    for (size_t t = 1; t < out.tile_begin.size(); ++t) out.tile_begin[t] += out.tile_begin[t - 1];
    out.tile_spheres.resize(out.tile_begin.back());
    std::vector<uint32_t> fill(out.tile_begin.begin(), out.tile_begin.end() - 1);
    for (uint32_t k = 0; k < out.bounds.size(); ++k)
        for_tiles(out.bounds[k], [&](size_t tile) { out.tile_spheres[fill[tile]++] = k; });
    return out;
}

float pixel_sphere_hit(const PixelRays& rays, const Sphere& sphere, int x, int y, Ray& ray) {
    ray = rays.at(x, y);
    return intersect_sphere(ray, sphere.center, sphere.radius, Interval{});
}

void draw_spheres_in_tile(const SphereRaster& raster, const Tile& tile, float* depth,
                          uint32_t* nearest, uint32_t* fragment_counts, int counts_width) {
    // The spheres that may show in this tile, in index order.
    const size_t bin = static_cast<size_t>(tile.y0 / k_tile_size) * raster.tiles_x +
                       static_cast<size_t>(tile.x0 / k_tile_size);
    const std::span<const uint32_t> here(raster.tile_spheres.data() + raster.tile_begin[bin],
                                         raster.tile_begin[bin + 1] - raster.tile_begin[bin]);
    if (here.empty()) return;
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x) {
            bool any = false;
            for (const uint32_t k : here) any = any || holds(raster.bounds[k], x, y);
            if (!any) continue;
            // SceneIntersector::closest_sphere: in index order, a later sphere wins only when
            // strictly nearer, so ties go to the lower index as in the ray tracer.
            const Ray ray = raster.rays.at(x, y);
            Interval range;
            int seen = -1;
            uint32_t met = 0;  // every sphere the ray meets, for the fragment count
            for (const uint32_t k : here) {
                if (!holds(raster.bounds[k], x, y)) continue;
                const Sphere& s = raster.spheres[k];
                if (fragment_counts) {
                    const float t_any = intersect_sphere(ray, s.center, s.radius, Interval{});
                    met += t_any == t_any ? 1 : 0;
                }
                const float t = intersect_sphere(ray, s.center, s.radius, range);
                if (t == t) range.max = t, seen = static_cast<int>(k);
            }
            if (fragment_counts) fragment_counts[static_cast<size_t>(y) * counts_width + x] += met;
            if (seen < 0) continue;
            // The depth key the triangles carry (ScreenVertex::inv_w inverted).
            const Vec4 clip = raster.clip_from_world * Vec4(ray.at(range.max), 1.0f);
            const float z = raster.orthographic ? 1.0f / (1.5f - 0.5f * clip.z / clip.w) : clip.w;
            const int i = (y - tile.y0) * k_tile_size + (x - tile.x0);
            // Alg 4.2's depth test, as for a triangle drawn after all the others.
            if (z < depth[i]) {
                depth[i] = z;
                nearest[i] = raster.first_id + static_cast<uint32_t>(seen);
            }
        }
}

}  // namespace hikari
