#include "hikari/integrators/whitted/whitted.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "hikari/bvh/scene_intersector.h"
#include "hikari/core/rng.h"
#include "hikari/frame/tiles.h"
#include "hikari/geometry/ray_offset.h"
#include "hikari/integrators/whitted/primary_hits.h"
#include "hikari/integrators/whitted/whitted_shade.h"
#include "hikari/shading/phong.h"
#include "hikari/shading/refraction.h"

namespace hikari {

namespace {

/// What every ray of a render reads, plus the ray count of the tile being rendered (each tile
/// works on its own copy, so counting needs no atomics per ray).
struct TraceContext {
    const Scene& scene;
    const SceneIntersector& intersector;
    int max_depth;
    uint64_t rays = 0;
};

/// The local (direct) illumination of a hit: ambient, then each light that a shadow ray
/// finds unblocked. `lit`, when given, holds the shadow rays' answers already (bit l: light l
/// unblocked), found in bulk for camera-ray hits by integrators/whitted/primary_hits.h.
Vec3 shade_local(TraceContext& ctx, const Material& m, Vec3 p, Vec3 n, Vec3 ng, Vec3 to_eye,
                 const uint8_t* lit) {
    Vec3 colour = shade_ambient(m, ctx.scene.ambient);
    const Vec3 shadow_origin = offset_ray_origin(p, ng);
    for (size_t l = 0; l < ctx.scene.lights.size(); ++l) {
        const LightSample ls = sample_light(ctx.scene.lights[l], p);
        if (dot(n, ls.to_light) <= 0.0f) continue;
        ++ctx.rays;
        const bool blocked =
            lit ? (*lit & (1u << l)) == 0
                : ctx.intersector.occluded({shadow_origin, ls.to_light}, {0.0f, ls.distance});
        if (blocked) continue;
        colour += shade_direct(m, n, ls.to_light, to_eye, ls.irradiance);
    }
    return colour;
}

/// The material at point p: `m` itself, or for a textured one a copy in `storage` with ka and kd
/// scaled by the texture's colour there (without the name: an empty string allocates nothing).
const Material& material_at(const Material& m, Vec3 p, Material& storage) {
    if (!m.texture) return m;
    const Vec3 c = m.texture->at(p);
    storage.ka = m.ka * c;
    storage.kd = m.kd * c;
    storage.ks = m.ks;
    storage.shininess = m.shininess;
    storage.reflectivity = m.reflectivity;
    storage.transparency = m.transparency;
    storage.ior = m.ior;
    return storage;
}

Vec3 trace(TraceContext& ctx, const Ray& ray, int segment, SurfaceHit* first_hit = nullptr);

/// What a ray that hits nothing sees.
Vec3 sky(const TraceContext& ctx, const Ray& ray) {
    return ctx.scene.sky.colour(ray.direction, ctx.scene.background);
}

/// Colour seen along `ray` (segment number `segment` of its path, primary = 1) whose nearest
/// hit is `hit`: local illumination, then the mirror and refracted rays.
Vec3 shade(TraceContext& ctx, const Ray& ray, const SurfaceHit& hit, int segment) {
    // Face the normals toward the incoming ray: planes and triangles are two-sided, and a ray
    // inside a sphere sees its inner side.
    const bool entering = dot(hit.geometric_normal, ray.direction) < 0.0f;
    const Vec3 ng = entering ? hit.geometric_normal : -hit.geometric_normal;
    Vec3 n = entering ? hit.shading_normal : -hit.shading_normal;
    if (dot(n, ray.direction) > 0.0f) n = ng;  // interpolated normal turned away: use the true one

    Material storage;
    const Material& m = material_at(ctx.scene.materials[hit.material], hit.position, storage);
    Vec3 colour = shade_local(ctx, m, hit.position, n, ng, -ray.direction, nullptr);
    if (segment >= ctx.max_depth) return colour;

    const Vec3 mirror = reflect(ray.direction, n);
    std::optional<Vec3> refracted;
    if (m.transparency > 0.0f)
        refracted = refract(ray.direction, n, entering ? 1.0f / m.ior : m.ior);
    // On total internal reflection the mirror ray takes the transmitted weight and the
    // reflectivity term is dropped (POV-Ray's rule), so the mirror ray is traced once.
    const bool total_internal = m.transparency > 0.0f && !refracted;
    const float mirror_weight = total_internal ? m.transparency : m.reflectivity;
    if (mirror_weight > 0.0f)
        colour +=
            mirror_weight * trace(ctx, {offset_ray_origin(hit.position, ng), mirror}, segment + 1);
    if (refracted)
        colour += m.transparency *
                  trace(ctx, {offset_ray_origin(hit.position, -ng), *refracted}, segment + 1);
    return colour;
}

/// Colour seen along `ray`, which is segment number `segment` of its path (primary = 1).
/// Returns the primary hit through `first_hit` when asked (for the AOVs).
Vec3 trace(TraceContext& ctx, const Ray& ray, int segment, SurfaceHit* first_hit) {
    ++ctx.rays;
    SurfaceHit hit;
    if (!ctx.intersector.closest(ray, {0.0f, k_infinity}, hit)) return sky(ctx, ray);
    if (first_hit) *first_hit = hit;
    return shade(ctx, ray, hit, segment);
}

/// One level of a tile's ray tree, breadth first, one array per field: each ray's own
/// contribution (local illumination at its hit, or the sky) and where its mirror and refracted
/// rays sit in the next level.
struct PathLevel {
    std::vector<float> colour[3];  ///< own contribution; after fold(), the whole colour seen
    std::vector<int32_t> mirror, refract;  ///< indices of the child rays in the next level, or -1
    std::vector<float> mirror_weight, refract_weight;  ///< where the child exists

    void resize(size_t n) {
        for (std::vector<float>& c : colour) c.resize(n);
        mirror.resize(n), refract.resize(n), mirror_weight.resize(n), refract_weight.resize(n);
    }
    Vec3 colour_at(size_t i) const { return {colour[0][i], colour[1][i], colour[2][i]}; }
};

/// What one thread keeps between tiles (the blocks are too big for a worker's stack).
struct WaveScratch {
    PrimaryBlock block;
    std::vector<PathLevel> levels;
    std::vector<Ray> rays, next_rays;
    std::vector<Ray> next_refracted;  ///< the next level's refracted rays, until join_refracted
};

/// A tile's rays traced level by level (Boulos et al. 2007): the camera rays' hits as a block,
/// all hits of a level shaded together in lanes (integrators/whitted/whitted_shade.h), the mirror
/// and refracted rays they spawn gathered into the next level and traced as blocks of their own.
/// Then the colours are folded from the deepest level up in exactly the order shade() adds them, so
/// every pixel is bit-identical to the recursive trace.
class WaveTracer {
  public:
    WaveTracer(TraceContext& ctx, const PrimaryHitTracer& hits, const LaneShader& shader,
               WaveScratch& scratch)
        : m_ctx(ctx), m_hits(hits), m_shader(shader), m_s(scratch) {}

    /// Traces the camera rays of `tile` (at most one block); AOVs via `first_hits(block)` right
    /// after the camera rays' hits are known. Returns the level of the camera rays: the colour
    /// of pixel (x0 + x, y0 + y) is entry y * k_primary_block + x.
    template <class FirstHits>
    const PathLevel& trace_tile(const Tile& tile, FirstHits&& first_hits) {
        const int width = tile.x1 - tile.x0, height = tile.y1 - tile.y0;
        PrimaryBlock& block = m_s.block;
        m_hits.trace(tile.x0, tile.y0, width, height, block);
        first_hits(block);
        PathLevel& camera = level(0);
        camera.resize(k_primary_block_rays);
        // shade_block sets the nodes of the block's rays; a clipped tile's others must read as
        // leaves for fold().
        if (width < k_primary_block || height < k_primary_block) {
            std::fill(camera.mirror.begin(), camera.mirror.end(), -1);
            std::fill(camera.refract.begin(), camera.refract.end(), -1);
        }
        m_s.next_rays.clear();
        shade_block(block, width, k_primary_block_rays, 1, camera, 0);
        join_refracted(camera);
        int depth = 1;
        while (!m_s.next_rays.empty()) {
            std::swap(m_s.rays, m_s.next_rays);
            m_s.next_rays.clear();
            PathLevel& nodes = level(depth);
            nodes.resize(m_s.rays.size());
            ++depth;
            for (size_t first = 0; first < m_s.rays.size(); first += k_primary_block_rays) {
                const int count = static_cast<int>(
                    std::min<size_t>(k_primary_block_rays, m_s.rays.size() - first));
                m_hits.trace_rays(m_s.rays.data() + first, count, block);
                shade_block(block, k_lane_chunk, count, depth, nodes, first);
            }
            join_refracted(nodes);
        }
        fold(depth);
        return level(0);
    }

  private:
    PathLevel& level(int index) {
        if (m_s.levels.size() <= static_cast<size_t>(index)) m_s.levels.resize(index + 1);
        return m_s.levels[index];
    }

    /// Shades the block's rays, which are of path segment `segment`, in place in its lanes, sets
    /// every field of their nodes (lane k is node first + k of `nodes`) and appends the rays they
    /// spawn to next_rays. The rays are the lanes k < count whose lane in their chunk is < width.
    void shade_block(PrimaryBlock& block, int width, int count, int segment, PathLevel& nodes,
                     size_t first) {
        const bool spawn = segment < m_ctx.max_depth;
        m_shader.shade(block.lanes, block.chunks * k_lane_chunk, spawn);
        for (int c = 0; c < block.chunks; ++c) {
            const detail::LaneChunk& lane = block.lanes.chunks[c];
            const size_t base = first + static_cast<size_t>(c) * k_lane_chunk;
            const int rays = std::min(width, count - c * k_lane_chunk);
            m_ctx.rays += static_cast<uint64_t>(rays);
            // Colours (the kernel's, shaded or the sky's).
            for (int a = 0; a < 3; ++a)
                std::copy_n(lane.colour[a], rays, nodes.colour[a].begin() + base);
            int32_t shadow_rays = 0, children = 0, scalar = 0;
            for (int j = 0; j < rays; ++j) {
                shadow_rays += lane.shadow_rays[j];
                scalar |= lane.scalar_specular[j];
                children += lane.children[j];
            }
            m_ctx.rays += static_cast<uint64_t>(shadow_rays);
            if (scalar != 0) shade_scalar_specular(block, c, rays, nodes, base);
            if (children != 0) {
                spawn_rays(lane, rays, nodes, base);
            } else {
                std::fill_n(nodes.mirror.begin() + base, rays, -1);
                std::fill_n(nodes.refract.begin() + base, rays, -1);
            }
        }
    }

    /// The lanes flagged scalar_specular in chunk c: a Phong exponent the lanes cannot raise
    /// exactly, shaded by the scalar code (their ray count is already in shadow_rays).
    void shade_scalar_specular(const PrimaryBlock& block, int c, int rays, PathLevel& nodes,
                               size_t base) {
        const detail::LaneChunk& lane = block.lanes.chunks[c];
        for (int j = 0; j < rays; ++j) {
            if (!lane.scalar_specular[j]) continue;  // 0 in lanes without a hit
            const int i = c * k_lane_chunk + j;
            TraceContext scalar = m_ctx;
            const SurfaceHit hit = block.hit(i);
            const uint8_t lit = block.lit(i);
            const Ray ray = block.ray(i);
            Material storage;
            const Material& m =
                material_at(m_ctx.scene.materials[hit.material], hit.position, storage);
            const Vec3 colour = shade_local(
                scalar, m, hit.position, {lane.normal[0][j], lane.normal[1][j], lane.normal[2][j]},
                {lane.facing_normal[0][j], lane.facing_normal[1][j], lane.facing_normal[2][j]},
                -ray.direction, &lit);
            for (int a = 0; a < 3; ++a) nodes.colour[a][base + j] = colour[a];
        }
    }

    /// The next level's rays of a chunk's lanes, and their nodes' indices and weights: mirror
    /// rays to next_rays, refracted rays to next_refracted (numbered there until
    /// join_refracted). Kept apart, the next level's blocks hold rays of one kind each: a glass
    /// surface's mirror rays mostly leave it and its refracted rays all meet it again from
    /// inside, so interleaved they would mix materials in every chunk of lanes.
    void spawn_rays(const detail::LaneChunk& lane, int rays, PathLevel& nodes, size_t base) {
        append_rays(lane.mirror_origin, lane.mirror_direction, lane.mirror_weight, rays,
                    m_s.next_rays, nodes.mirror.data() + base);
        append_rays(lane.refract_origin, lane.refract_direction, lane.refract_weight, rays,
                    m_s.next_refracted, nodes.refract.data() + base);
        std::copy_n(lane.mirror_weight, rays, nodes.mirror_weight.begin() + base);
        std::copy_n(lane.refract_weight, rays, nodes.refract_weight.begin() + base);
    }

    /// Appends to `to`, in lane order, the rays of lanes [0, rays) whose weight is positive, and
    /// sets index[j] to lane j's ray's place in `to`, or -1 for none. Every lane's ray is
    /// written and only the existing ones are kept: no branch per lane, whose outcome changes
    /// from lane to lane along an object's outline.
    static void append_rays(const float (&origin)[3][k_lane_chunk],
                            const float (&direction)[3][k_lane_chunk], const float* weight,
                            int rays, std::vector<Ray>& to, int32_t* index) {
        int32_t any = 0;
        for (int j = 0; j < rays; ++j) any |= weight[j] > 0.0f ? 1 : 0;
        if (any == 0) {
            std::fill_n(index, rays, -1);
            return;
        }
        size_t count = to.size();
        to.resize(count + static_cast<size_t>(rays));
        Ray* const out = to.data();
        for (int j = 0; j < rays; ++j) {
            out[count] = {{origin[0][j], origin[1][j], origin[2][j]},
                          {direction[0][j], direction[1][j], direction[2][j]}};
            const bool exists = weight[j] > 0.0f;
            index[j] = exists ? static_cast<int32_t>(count) : -1;
            count += exists ? 1 : 0;
        }
        to.resize(count);
    }

    /// Once a level is shaded: its refracted rays appended after its mirror rays, and the
    /// nodes' refract indices moved with them.
    void join_refracted(PathLevel& nodes) {
        if (m_s.next_refracted.empty()) return;
        const auto offset = static_cast<int32_t>(m_s.next_rays.size());
        for (int32_t& index : nodes.refract)
            if (index >= 0) index += offset;
        m_s.next_rays.insert(m_s.next_rays.end(), m_s.next_refracted.begin(),
                             m_s.next_refracted.end());
        m_s.next_refracted.clear();
    }

    /// Adds each level's colours into their parents', deepest first, as shade() adds them:
    /// colour += mirror_weight * mirror colour, then += transparency * refracted colour.
    void fold(int depth) {
        for (int d = depth - 2; d >= 0; --d) {
            const PathLevel& children = m_s.levels[d + 1];
            PathLevel& nodes = m_s.levels[d];
            for (size_t i = 0; i < nodes.mirror.size(); ++i) {
                if (nodes.mirror[i] < 0 && nodes.refract[i] < 0) continue;
                Vec3 colour = nodes.colour_at(i);
                if (nodes.mirror[i] >= 0)
                    colour += nodes.mirror_weight[i] *
                              children.colour_at(static_cast<size_t>(nodes.mirror[i]));
                if (nodes.refract[i] >= 0)
                    colour += nodes.refract_weight[i] *
                              children.colour_at(static_cast<size_t>(nodes.refract[i]));
                for (int a = 0; a < 3; ++a) nodes.colour[a][i] = colour[a];
            }
        }
    }

    TraceContext& m_ctx;
    const PrimaryHitTracer& m_hits;
    const LaneShader& m_shader;
    WaveScratch& m_s;
};

/// Strata for `n` jittered samples: the most square grid cols × rows = n.
void strata(int n, int& cols, int& rows) {
    cols = static_cast<int>(std::sqrt(static_cast<double>(n)));
    while (n % cols != 0) --cols;
    rows = n / cols;
}

}  // namespace

Framebuffer render_whitted(const Scene& scene, Film film, const RenderSettings& settings,
                           const WhittedSettings& whitted) {
    const Camera& cam = scene.camera;
    // Every pixel is set below (by its tile), so 8-bit colour may start unwritten: its pages are
    // first touched by the tiles, in parallel.
    Framebuffer fb(std::move(film), cam.width, cam.height, settings.aov_buffers);
    const SceneIntersector intersector(scene);
    const TraceContext shared{scene, intersector, whitted.max_depth};
    if (RenderStats* stats = settings.stats) {
        const WideBvh& bvh = intersector.bvh();
        stats->bvh_triangles = bvh.triangle_count();
        stats->bvh_nodes = bvh.nodes.size();
        stats->bvh_bytes = bvh.memory_bytes();
        stats->bvh_build_us = static_cast<uint64_t>(intersector.build_ms() * 1000.0);
    }
    const CameraFrame frame = make_camera_frame(cam);
    const int spp = whitted.samples_per_pixel;
    int cols = 1, rows = 1;
    strata(spp, cols, rows);

    // One ray per pixel: the tile's camera rays and their nearest hits are found together
    // (integrators/whitted/primary_hits.h, SIMD), then each pixel is shaded from its hit as trace()
    // would.
    const PrimaryHitTracer primary(intersector, scene, frame);
    const LaneShader shader(scene);
    const auto store_aovs = [&](size_t i, const Ray& centre, const SurfaceHit& first) {
        if (!settings.aov_buffers || !(first.t < k_infinity)) return;
        fb.depth[i] = first.t;
        fb.id[i] = first.id + 1;
        fb.normal[i] = dot(first.shading_normal, centre.direction) < 0.0f ? first.shading_normal
                                                                          : -first.shading_normal;
    };
    static_assert(k_tile_size <= k_primary_block);

    for_each_tile(cam.width, cam.height, settings.control, [&](const Tile& tile) {
        TraceContext ctx = shared;
        if (spp == 1 && whitted.primary_blocks && shader.supported()) {
            thread_local std::unique_ptr<WaveScratch> scratch;
            if (!scratch) scratch = std::make_unique<WaveScratch>();
            WaveTracer wave(ctx, primary, shader, *scratch);
            const PathLevel& colours = wave.trace_tile(tile, [&](const PrimaryBlock& block) {
                if (!settings.aov_buffers) return;
                for (int y = tile.y0; y < tile.y1; ++y)
                    for (int x = tile.x0; x < tile.x1; ++x) {
                        const int k = (y - tile.y0) * k_primary_block + (x - tile.x0);
                        if (block.found(k))
                            store_aovs(static_cast<size_t>(y) * cam.width + x, block.ray(k),
                                       block.hit(k));
                    }
            });
            for (int y = tile.y0; y < tile.y1; ++y) {
                const size_t row = static_cast<size_t>(y - tile.y0) * k_primary_block;
                fb.set_colors(static_cast<size_t>(y) * cam.width + tile.x0,
                              colours.colour[0].data() + row, colours.colour[1].data() + row,
                              colours.colour[2].data() + row,
                              static_cast<size_t>(tile.x1 - tile.x0));
            }
            if (settings.stats) settings.stats->rays_traced += ctx.rays;
            return;
        }
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x) {
                const size_t i = static_cast<size_t>(y) * cam.width + x;
                const auto fx = static_cast<float>(x), fy = static_cast<float>(y);
                SurfaceHit first;
                first.t = k_infinity;
                const Ray centre = camera_ray(frame, fx + 0.5f, fy + 0.5f);
                Vec3 sum(0.0f);
                if (spp == 1) {
                    sum = trace(ctx, centre, 1, &first);
                } else {
                    // The AOVs describe the pixel centre; colour averages jittered samples, one
                    // in each stratum, from a stream seeded by the pixel alone.
                    intersector.closest(centre, {0.0f, k_infinity}, first);
                    ++ctx.rays;
                    Pcg32 rng(i, 0x68696b617269ULL);
                    for (int s = 0; s < spp; ++s) {
                        const int column = s % cols, row = s / cols;
                        const float sx = (static_cast<float>(column) + rng.next_float()) / cols;
                        const float sy = (static_cast<float>(row) + rng.next_float()) / rows;
                        sum += trace(ctx, camera_ray(frame, fx + sx, fy + sy), 1);
                    }
                    sum = sum / static_cast<float>(spp);
                }
                fb.set_color(i, sum);
                store_aovs(i, centre, first);
            }
        if (settings.stats) settings.stats->rays_traced += ctx.rays;
    });
    return fb;
}

}  // namespace hikari
