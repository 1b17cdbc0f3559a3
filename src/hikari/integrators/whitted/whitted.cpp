#include "hikari/integrators/whitted/whitted.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "hikari/bvh/scene_intersector.h"
#include "hikari/core/error.h"
#include "hikari/core/memory_budget.h"
#include "hikari/frame/subpixel.h"
#include "hikari/frame/tiles.h"
#include "hikari/geometry/ray_offset.h"
#include "hikari/integrators/hit_aovs.h"
#include "hikari/integrators/whitted/primary_hits.h"
#include "hikari/integrators/whitted/ray_cone.h"
#include "hikari/integrators/whitted/whitted_shade.h"
#include "hikari/integrators/whitted/whitted_surface.h"

namespace hikari {

namespace {

/// What rays see of the lights themselves: the area lights' faces (radiance L), and the
/// environment where a ray escapes.
struct Emitters {
    std::span<const Light> lights;  ///< the scene's
    bool areas = false;             ///< some light is an area light
    const EnvironmentLight* environment = nullptr;

    explicit Emitters(const Scene& scene)
        : lights(scene.lights),
          areas(scene.show_background && has_area_light(scene.lights)),
          environment(scene.show_background ? find_environment(scene.lights) : nullptr) {}
    bool any() const { return areas || environment; }
};

/// The ray tracer's shadow test at one hit: the front end's answers for point and directional
/// lights where it traced them (bit l of `lit`, when `lit_known`), else a shadow ray from
/// offset_ray_origin(position, geometric normal) toward the light; the samples of an area or
/// environment light as packets of rays from that one origin.
struct ShadowRays {
    const SceneIntersector& intersector;
    bool lit_known;
    uint32_t lit;
    /// false: nothing casts a shadow (TraceContext::shadow_rays_traced), every light is seen.
    bool traced = true;

    bool operator()(size_t l, const LightSample& light, const SurfacePoint<float>& s, bool) const {
        if (!traced) return true;
        if (lit_known && l < k_max_block_lights) return ((lit >> l) & 1u) != 0;
        const Ray shadow{offset_ray_origin(s.position, s.geometric_normal), light.to_light};
        return !intersector.occluded(shadow, {0.0f, light.distance});
    }

    /// The mask of samples[0, count) (count <= k_packet_size) whose shadow rays are unblocked,
    /// each exactly as operator() answers it.
    uint32_t many(size_t, const LightSample* samples, int count,
                  const SurfacePoint<float>& s) const {
        if (!traced) return count >= 32 ? ~0u : (1u << count) - 1;
        const Vec3 origin = offset_ray_origin(s.position, s.geometric_normal);
        RayPacket packet;
        for (int i = 0; i < static_cast<int>(k_packet_size); ++i) {
            const LightSample& sample = samples[i < count ? i : 0];
            packet.set(static_cast<uint32_t>(i), {origin, sample.to_light},
                       {0.0f, sample.distance});
        }
        const uint32_t active = count >= 32 ? ~0u : (1u << count) - 1;
        uint32_t open = active & ~intersector.occluded_by_triangles(packet, active);
        for (int i = 0; i < count; ++i)
            if (((open >> i) & 1u) != 0 &&
                intersector.occluded_by_spheres_and_planes(packet.ray(static_cast<uint32_t>(i)),
                                                           {0.0f, samples[i].distance}))
                open &= ~(1u << i);
        return open;
    }
};
static_assert(k_light_sample_batch <= static_cast<int>(k_packet_size));

/// What every ray of a render reads, plus the ray count of the tile being rendered (each tile
/// works on its own copy, so counting needs no atomics per ray).
struct TraceContext {
    const SceneIntersector& intersector;
    const WhittedScene& shading;
    const Scene& scene;
    CameraCones camera_cones;  ///< the camera rays' cones, by direction
    bool textured;             ///< some material has a texture: rays carry their cones
    int max_depth;
    const Emitters& emitters;  ///< what rays see of the lights themselves
    /// false where nothing casts a shadow: no shadow ray is traced, so none is counted (--stats).
    bool shadow_rays_traced = true;
    uint64_t rays = 0;
};

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

/// What a WaveTracer records of the rays it traces, level by level (whitted_ray_tree).
struct WaveRecord {
    struct Traced {
        Ray ray;
        bool hit = false;
        SurfaceHit surface;
    };
    std::vector<std::vector<Traced>> rays;  ///< per level, in the level's order
    std::vector<PathLevel> own;             ///< per level, the nodes before fold()
    std::vector<PathLevel> folded;          ///< per level, after fold(): the totals
};

/// The ray-tree nodes every thread holds at once, for the memory limit: a tree's breadth can
/// double at each level (a glass surface spawns a mirror and a refracted ray), so a deep
/// --max-depth between mirrors and glass is checked level by level rather than up front.
std::atomic<uint64_t> g_tree_nodes_held{0};

/// The most rays one level of the tree may hold per camera ray. Whitted's recursion is
/// exponential: a ray that meets glass between mirrors spawns a mirror and a refracted ray that
/// both come back, so a path of D segments can end in 2^(D-1) rays. A scene needs this many at
/// one level only past depth 17 with glass at every bounce; the tree is refused there at once
/// (the memory check alone lets it grow to the limit first, which a large limit makes
/// minutes of tracing).
constexpr size_t k_max_rays_per_camera_ray = size_t{1} << 16;

/// A tracer's share of g_tree_nodes_held, given back when its paths are finished.
class HeldTreeNodes {
  public:
    HeldTreeNodes() = default;
    HeldTreeNodes(const HeldTreeNodes&) = delete;
    HeldTreeNodes& operator=(const HeldTreeNodes&) = delete;
    ~HeldTreeNodes() { g_tree_nodes_held.fetch_sub(m_nodes); }

    /// Adds `nodes` of a new level at `depth` of --max-depth `max_depth`, each `node_bytes`
    /// over all the arrays that hold it; InputError when all trees then exceed the limit.
    void add(size_t nodes, double node_bytes, int depth, int max_depth) {
        m_nodes += nodes;
        const uint64_t held = g_tree_nodes_held.fetch_add(nodes) + nodes;
        check_memory_need(static_cast<double>(held) * node_bytes,
                          fmt::format("the ray tree ({} rays at level {} of --max-depth {})", held,
                                      depth, max_depth));
    }

  private:
    uint64_t m_nodes = 0;
};

/// What one thread keeps between tiles (the blocks are too big for a worker's stack).
struct WaveScratch {
    PrimaryBlock block;
    std::vector<PathLevel> levels;
    std::vector<Ray> rays, next_rays;
    std::vector<Ray> next_refracted;  ///< the next level's refracted rays, until join_refracted
    /// The ray cones of `rays`, `next_rays` and `next_refracted`, entry for entry (empty when
    /// no material has a texture: nothing reads them).
    std::vector<RayCone> cones, next_cones, next_refracted_cones;
    // Jittered samples: each pixel's colour sum, and one sample's camera rays.
    std::vector<Vec3> sums;
    std::vector<Ray> camera_rays;
};

/// A tile's rays traced level by level (Boulos et al. 2007): the first rays' hits as a block,
/// all hits of a level shaded together in lanes (whitted_shade.h), the mirror and refracted
/// rays they spawn gathered into the next level and traced as blocks of their own. Then the
/// colours are folded from the deepest level up in the order Whitted's recursion adds them:
/// colour = local + mirror_weight × mirror colour + refract_weight × refracted colour.
class WaveTracer {
  public:
    WaveTracer(TraceContext& ctx, const PrimaryHitTracer& hits, const LaneShader& shader,
               WaveScratch& scratch, WaveRecord* record = nullptr)
        : m_ctx(ctx), m_hits(hits), m_shader(shader), m_s(scratch), m_record(record) {}

    /// Traces the camera rays through the pixel centres of `tile` (at most one block); AOVs via
    /// `first_hits(block)` right after their hits are known. Returns the level of the camera
    /// rays: the colour of pixel (x0 + x, y0 + y) is entry y * k_primary_block + x.
    template <class FirstHits>
    const PathLevel& trace_tile(const Tile& tile, FirstHits&& first_hits) {
        const int width = tile.x1 - tile.x0, height = tile.y1 - tile.y0;
        PrimaryBlock& block = m_s.block;
        m_camera_rays = static_cast<size_t>(width) * height;
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
        m_s.next_cones.clear();
        shade_block(block, width, k_primary_block_rays, 1, camera, 0, nullptr);
        return finish_paths(camera);
    }

    /// Traces `count` rays from the camera (jittered samples): their colours are entries
    /// [0, count) of the level returned.
    const PathLevel& trace_camera_rays(const Ray* rays, size_t count) {
        PathLevel& camera = level(0);
        camera.resize(count);
        m_camera_rays = count;
        m_s.next_rays.clear();
        m_s.next_cones.clear();
        trace_level(rays, count, nullptr, 1, camera);
        return finish_paths(camera);
    }

  private:
    PathLevel& level(int index) {
        if (m_s.levels.size() <= static_cast<size_t>(index)) m_s.levels.resize(index + 1);
        return m_s.levels[index];
    }

    /// Once the first level is shaded: every deeper level traced and shaded, then the colours
    /// folded up into the first level's.
    const PathLevel& finish_paths(PathLevel& first) {
        join_refracted(first);
        if (m_record) m_record->own.push_back(first);
        HeldTreeNodes held;
        held.add(first.mirror.size(), node_bytes(), 1, m_ctx.max_depth);
        int depth = 1;
        while (!m_s.next_rays.empty()) {
            check_breadth(m_s.next_rays.size(), depth + 1);
            held.add(m_s.next_rays.size(), node_bytes(), depth + 1, m_ctx.max_depth);
            std::swap(m_s.rays, m_s.next_rays);
            std::swap(m_s.cones, m_s.next_cones);
            m_s.next_rays.clear();
            m_s.next_cones.clear();
            PathLevel& nodes = level(depth);
            nodes.resize(m_s.rays.size());
            ++depth;
            trace_level(m_s.rays.data(), m_s.rays.size(), m_s.cones.data(), depth, nodes);
            join_refracted(nodes);
            if (m_record) m_record->own.push_back(nodes);
        }
        fold(depth);
        if (m_record)
            for (int d = 0; d < depth; ++d) m_record->folded.push_back(level(d));
        return level(0);
    }

    /// Refuses a level of `rays` at `depth` that is broader than k_max_rays_per_camera_ray.
    void check_breadth(size_t rays, int depth) const {
        if (rays <= k_max_rays_per_camera_ray * std::max<size_t>(m_camera_rays, 1)) return;
        throw InputError(fmt::format(
            "the ray tree grows past {} rays per camera ray at level {} of --max-depth {}: "
            "surfaces that both reflect and refract, between mirrors, double it (lower "
            "--max-depth, or make them reflect or refract only)",
            k_max_rays_per_camera_ray, depth, m_ctx.max_depth));
    }

    /// The bytes one node of the tree takes over every array that holds it: its PathLevel
    /// entries, its ray in two ray lists, its cones, and what a WaveRecord copies of it.
    double node_bytes() const {
        constexpr double level = 3 * sizeof(float) + 2 * sizeof(int32_t) + 2 * sizeof(float);
        double bytes = level + 2 * sizeof(Ray);
        if (m_ctx.textured) bytes += 2 * sizeof(RayCone);
        if (m_record) bytes += sizeof(WaveRecord::Traced) + 2 * level + sizeof(RayTreeNode);
        return bytes;
    }

    /// Traces and shades `rays[0, count)`, which are of path segment `segment`, block by block
    /// into `nodes`; `cones` holds their ray cones (null: camera rays).
    void trace_level(const Ray* rays, size_t count, const RayCone* cones, int segment,
                     PathLevel& nodes) {
        PrimaryBlock& block = m_s.block;
        for (size_t first = 0; first < count; first += k_primary_block_rays) {
            const int n = static_cast<int>(std::min<size_t>(k_primary_block_rays, count - first));
            m_hits.trace_rays(rays + first, n, block);
            if (m_record) {
                if (m_record->rays.size() < static_cast<size_t>(segment))
                    m_record->rays.resize(static_cast<size_t>(segment));
                for (int k = 0; k < n; ++k)
                    m_record->rays[segment - 1].push_back(
                        {rays[first + k], block.found(k),
                         block.found(k) ? block.hit(k) : SurfaceHit{}});
            }
            shade_block(block, k_lane_chunk, n, segment, nodes, first, cones);
        }
    }

    /// The ray cone of node `i` of the level being shaded, whose cones are `cones` (null:
    /// camera rays, whose direction is `direction`).
    RayCone cone_of(const RayCone* cones, size_t i, Vec3 direction) const {
        return cones ? cones[i] : m_ctx.camera_cones(direction);
    }

    /// Shades the block's rays, which are of path segment `segment`, in place in its lanes, sets
    /// every field of their nodes (lane k is node first + k of `nodes`) and appends the rays they
    /// spawn to next_rays. The rays are the lanes k < count whose lane in their chunk is < width.
    /// Node i's ray cone is cones[i] (null: camera rays).
    void shade_block(PrimaryBlock& block, int width, int count, int segment, PathLevel& nodes,
                     size_t first, const RayCone* cones) {
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
                scalar |= lane.scalar_only[j] | (block.shadows_known ? 0 : lane.active[j]);
                children += lane.children[j];
            }
            if (m_ctx.shadow_rays_traced) m_ctx.rays += static_cast<uint64_t>(shadow_rays);
            if (scalar != 0) shade_one_ray_at_a_time(block, c, rays, nodes, base, cones);
            if (m_ctx.emitters.any()) {
                see_emitters(block, c, rays, nodes, base);
                children = 0;
                for (int j = 0; j < rays; ++j) children += lane.children[j];
            }
            if (children != 0) {
                spawn_rays(lane, rays, nodes, base, cones);
            } else {
                std::fill_n(nodes.mirror.begin() + base, rays, -1);
                std::fill_n(nodes.refract.begin() + base, rays, -1);
            }
        }
    }

    /// The colours of chunk c's hits that the lanes could not shade (a material without a lane
    /// form, or shadow rays the block did not trace: more than k_max_block_lights lights),
    /// from the same generic code on one ray at a time; their shadow rays are already counted.
    /// These also get texture coordinates and their footprint, from the rays' cones.
    void shade_one_ray_at_a_time(const PrimaryBlock& block, int c, int rays, PathLevel& nodes,
                                 size_t base, const RayCone* cones) {
        const detail::LaneChunk& lane = block.lanes.chunks[c];
        for (int j = 0; j < rays; ++j) {
            if (!lane.active[j] || (block.shadows_known && !lane.scalar_only[j])) continue;
            const int i = c * k_lane_chunk + j;
            const Vec3 direction = block.ray(i).direction;
            const DirectLighting<float> direct =
                shade_hit(direction, block.hit(i), cone_of(cones, base + j, direction),
                          block.shadows_known, block.lit(i));
            for (int a = 0; a < 3; ++a) nodes.colour[a][base + j] = direct.colour[a];
            // The lanes counted the point and directional lights' shadow rays; these add the
            // area and environment lights' samples.
            if (m_ctx.shadow_rays_traced)
                m_ctx.rays +=
                    static_cast<uint64_t>(std::max(0, direct.tested - lane.shadow_rays[j]));
        }
    }

    /// Where chunk c's rays see a light itself: a light's face nearer than the hit takes the
    /// node's colour (and the hit spawns nothing), an escaping ray sees the environment.
    void see_emitters(PrimaryBlock& block, int c, int rays, PathLevel& nodes, size_t base) const {
        detail::LaneChunk& lane = block.lanes.chunks[c];
        for (int j = 0; j < rays; ++j) {
            const Ray ray = block.ray(c * k_lane_chunk + j);
            const bool hit = lane.active[j] != 0;
            std::optional<Vec3> seen =
                m_ctx.emitters.areas ? light_face_seen(m_ctx.emitters.lights, ray.origin,
                                                       ray.direction, hit ? lane.t[j] : k_infinity)
                                     : std::nullopt;
            if (!seen && !hit && m_ctx.emitters.environment)
                seen = m_ctx.emitters.environment->radiance_from(ray.direction);
            if (!seen) continue;
            for (int a = 0; a < 3; ++a) nodes.colour[a][base + j] = (*seen)[a];
            lane.mirror_weight[j] = lane.refract_weight[j] = 0.0f;
            lane.children[j] = 0;
        }
    }

    /// The local illumination of one hit seen along `direction` by a ray with cone `cone` (its
    /// texture coordinates and footprint, where the material has a texture); light l is visible
    /// where bit l of `lit` is set when `lit_known`, else where its shadow ray finds nothing in the
    /// way.
    DirectLighting<float> shade_hit(Vec3 direction, const SurfaceHit& hit, const RayCone& cone,
                                    bool lit_known, uint32_t lit) const {
        WhittedHit<float> h{direction, hit.position, hit.geometric_normal, hit.shading_normal,
                            static_cast<int32_t>(hit.material)};
        if (m_ctx.shading.materials[hit.material].texture) {
            const SurfaceUv uv = m_ctx.intersector.surface_uv(hit);
            const UvFootprint footprint =
                cone_footprint(cone.width_at(hit.t), direction, hit.geometric_normal, uv);
            h.u = uv.uv.x, h.v = uv.uv.y;
            h.du_dx = footprint.du_dx, h.dv_dx = footprint.dv_dx;
            h.du_dy = footprint.du_dy, h.dv_dy = footprint.dv_dy;
            h.dp_dx = footprint.dp_dx, h.dp_dy = footprint.dp_dy;
        }
        if (m_ctx.shading.materials[hit.material].vertex_colours)
            h.vertex_colour = m_ctx.intersector.surface_colour(hit);
        const ShadowRays visible{m_ctx.intersector, lit_known, lit, m_ctx.shadow_rays_traced};
        return shade_whitted_hit<float>(m_ctx.shading, h, true, visible).direct;
    }

    /// The next level's rays of a chunk's lanes, and their nodes' indices and weights: mirror
    /// rays to next_rays, refracted rays to next_refracted (numbered there until
    /// join_refracted). Kept apart, the next level's blocks hold rays of one kind each: a glass
    /// surface's mirror rays mostly leave it and its refracted rays all meet it again from
    /// inside, so interleaved they would mix materials in every chunk of lanes.
    void spawn_rays(const detail::LaneChunk& lane, int rays, PathLevel& nodes, size_t base,
                    const RayCone* cones) {
        append_rays(lane.mirror_origin, lane.mirror_direction, lane.mirror_weight, rays,
                    m_s.next_rays, nodes.mirror.data() + base);
        append_rays(lane.refract_origin, lane.refract_direction, lane.refract_weight, rays,
                    m_s.next_refracted, nodes.refract.data() + base);
        for (int j = 0; j < rays && m_ctx.textured; ++j)
            if (lane.mirror_weight[j] > 0.0f || lane.refract_weight[j] > 0.0f)
                spawn_cones(
                    lane, j,
                    cone_of(cones, base + j,
                            {lane.direction[0][j], lane.direction[1][j], lane.direction[2][j]}));
        std::copy_n(lane.mirror_weight, rays, nodes.mirror_weight.begin() + base);
        std::copy_n(lane.refract_weight, rays, nodes.refract_weight.begin() + base);
    }

    /// The curvature of the surface lane j hit, positive where it bulges toward its geometric
    /// normal: a sphere's 1 / radius, a triangle's from its vertex normals, a plane's 0.
    float object_curvature(const detail::LaneChunk& lane, int j) const {
        const Scene& scene = m_ctx.scene;
        if (lane.object[j] == 1) {
            const TriangleSet& tris = scene.triangles;
            const auto& [i0, i1, i2] = tris.indices[lane.triangle[j]];
            const Vec3 p0 = tris.positions[i0], p1 = tris.positions[i1], p2 = tris.positions[i2];
            // Vertex normals may point either way of the lecture's N: measure along N.
            const float side = dot(cross(p1 - p0, p2 - p1), tris.normals[i0]) < 0.0f ? -1.0f : 1.0f;
            return side * triangle_curvature(
                              {p0, p1, p2}, {tris.normals[i0], tris.normals[i1], tris.normals[i2]});
        }
        const int32_t sphere = lane.object[j] - 2;
        if (sphere >= 0 && static_cast<size_t>(sphere) < scene.spheres.size())
            return 1.0f / scene.spheres[sphere].radius;
        return 0.0f;
    }

    /// The ray cones of lane j's mirror and refracted rays (where they exist), after those of
    /// the lanes before it: the incoming cone's width at the hit, its spread bent by the
    /// surface's curvature (object_curvature).
    void spawn_cones(const detail::LaneChunk& lane, int j, const RayCone& incoming) {
        const float width = incoming.width_at(lane.t[j]);
        const Vec3 d{lane.direction[0][j], lane.direction[1][j], lane.direction[2][j]};
        const Vec3 ng{lane.geometric_normal[0][j], lane.geometric_normal[1][j],
                      lane.geometric_normal[2][j]};
        const bool entering = dot(ng, d) < 0.0f;
        // Object code 1 is a triangle, 2 + i sphere i: convex seen from outside, concave from
        // inside.
        const float curvature = (entering ? 1.0f : -1.0f) * object_curvature(lane, j);
        if (lane.mirror_weight[j] > 0.0f)
            m_s.next_cones.push_back(reflected_cone(incoming, width, curvature));
        if (lane.refract_weight[j] > 0.0f) {
            const Vec3 n{lane.shading_normal[0][j], lane.shading_normal[1][j],
                         lane.shading_normal[2][j]};
            const Vec3 t{lane.refract_direction[0][j], lane.refract_direction[1][j],
                         lane.refract_direction[2][j]};
            const float ior = m_ctx.shading.materials[lane.material[j]].ior;
            m_s.next_refracted_cones.push_back(
                refracted_cone(incoming, width, curvature, entering ? 1.0f / ior : ior,
                               std::abs(dot(d, n)), std::abs(dot(t, n))));
        }
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
        m_s.next_cones.insert(m_s.next_cones.end(), m_s.next_refracted_cones.begin(),
                              m_s.next_refracted_cones.end());
        m_s.next_refracted.clear();
        m_s.next_refracted_cones.clear();
    }

    /// Adds each level's colours into their parents', deepest first, as the recursion adds
    /// them: colour += mirror_weight * mirror colour, then += refract_weight * refracted colour.
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
    WaveRecord* m_record;
    size_t m_camera_rays = 1;  ///< of the tile or sample being traced
};

/// Everything a render's tiles share.
struct WhittedRender {
    const Scene& scene;
    const RenderSettings& settings;
    const WhittedSettings& whitted;
    Framebuffer& fb;
    const CameraFrame frame;
    bool built_intersector = true;  ///< false: kept from an earlier render (settings.cache)
    const std::shared_ptr<const SceneIntersector> kept_intersector;
    const SceneIntersector& intersector;
    /// For analytic area-light shadows; null without them.
    const std::shared_ptr<const OccluderSet> occluders;
    const WhittedScene shading;
    const Emitters emitters;
    const PrimaryHitTracer primary;
    const LaneShader shader;

    WhittedRender(const Scene& s, const RenderSettings& r, const WhittedSettings& w, Framebuffer& f)
        : scene(s),
          settings(r),
          whitted(w),
          fb(f),
          frame(make_camera_frame(s.camera)),
          kept_intersector(scene_intersector(s, r.cache, &built_intersector)),
          intersector(*kept_intersector),
          occluders(w.analytic_area_shadows ? shadow_occluders(s, r.cache) : nullptr),
          shading(s, w.light_samples, occluders.get()),
          emitters(s),
          primary(intersector, s, frame),
          shader(shading) {}

    /// The AOVs of pixel i from the hit of the ray through its centre.
    void store_aovs(size_t i, const Ray& centre, const SurfaceHit& first) const {
        store_hit_aovs(fb, i, centre.direction, first);
    }

    /// The AOVs of the tile's pixels whose centre ray hit something.
    void store_block_aovs(const Tile& tile, const PrimaryBlock& block) const {
        if (!settings.aov_buffers) return;
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x) {
                const int k = (y - tile.y0) * k_primary_block + (x - tile.x0);
                if (block.found(k))
                    store_aovs(static_cast<size_t>(y) * scene.camera.width + x, block.ray(k),
                               block.hit(k));
            }
    }

    /// One ray through each pixel centre.
    void render_centres(const Tile& tile, WaveTracer& wave) const {
        const PathLevel& colours = wave.trace_tile(
            tile, [&](const PrimaryBlock& block) { store_block_aovs(tile, block); });
        for (int y = tile.y0; y < tile.y1; ++y) {
            const size_t row = static_cast<size_t>(y - tile.y0) * k_primary_block;
            fb.set_colors(static_cast<size_t>(y) * scene.camera.width + tile.x0,
                          colours.colour[0].data() + row, colours.colour[1].data() + row,
                          colours.colour[2].data() + row, static_cast<size_t>(tile.x1 - tile.x0));
        }
    }

    /// `spp` stratified jittered samples per pixel, one in each stratum, at the same points in
    /// every pixel (frame/subpixel.h, as the raster methods take them); the AOVs describe the
    /// pixel centre.
    void render_samples(const Tile& tile, WaveTracer& wave, WaveScratch& scratch) const {
        const int spp = whitted.samples_per_pixel, width = scene.camera.width;
        if (settings.aov_buffers) {
            primary.trace(tile.x0, tile.y0, tile.x1 - tile.x0, tile.y1 - tile.y0, scratch.block);
            store_block_aovs(tile, scratch.block);
        }
        std::vector<Vec3>& sums = scratch.sums;
        sums.assign(tile_pixels(tile), Vec3(0.0f));
        for (int s = 0; s < spp; ++s) {
            std::vector<Ray>& rays = scratch.camera_rays;
            rays.clear();
            const Vec2 offset = subpixel_sample(s, spp);
            for (int y = tile.y0; y < tile.y1; ++y)
                for (int x = tile.x0; x < tile.x1; ++x)
                    rays.push_back(camera_ray(frame, static_cast<float>(x) + offset.x,
                                              static_cast<float>(y) + offset.y));
            const PathLevel& colours = wave.trace_camera_rays(rays.data(), rays.size());
            for (size_t k = 0; k < sums.size(); ++k) sums[k] += colours.colour_at(k);
        }
        for (int y = tile.y0, k = 0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x, ++k)
                fb.set_color(static_cast<size_t>(y) * width + x, sums[k] / static_cast<float>(spp));
    }

    static size_t tile_pixels(const Tile& tile) {
        return static_cast<size_t>(tile.x1 - tile.x0) * static_cast<size_t>(tile.y1 - tile.y0);
    }
};

/// `scene` with no primitive casting a shadow: shadow rays pass through every primitive that
/// does not cast, so every light reaches every point (`--shadows none`).
Scene without_shadow_casters(Scene scene) {
    for (Sphere& s : scene.spheres) s.casts_shadow = false;
    for (Plane& p : scene.planes) p.casts_shadow = false;
    scene.triangles.casts_shadow.assign(scene.triangles.size(), 0);
    return scene;
}

/// Whether a material of `scene` has a texture (whose footprint the rays' cones give).
bool has_texture(const Scene& scene) {
    return std::any_of(scene.materials.begin(), scene.materials.end(),
                       [](const Material& m) { return m.texture.has_value(); });
}

}  // namespace

std::vector<RayTreeNode> whitted_ray_tree(const Scene& scene, const WhittedSettings& whitted, int x,
                                          int y) {
    // The render's objects, one pixel's centre ray through the render's tracer.
    Framebuffer fb(Film(1, 1, FilmFormat::linear), 1, 1, false);
    const Scene one = whitted.shadow_rays ? scene : without_shadow_casters(scene);
    const RenderSettings settings;
    const WhittedRender render(one, settings, whitted, fb);
    TraceContext ctx{render.intersector,      render.shading,   one,
                     CameraCones(one.camera), has_texture(one), whitted.max_depth,
                     render.emitters};
    WaveScratch scratch;
    WaveRecord record;
    WaveTracer wave(ctx, render.primary, render.shader, scratch, &record);
    const Ray centre =
        camera_ray(render.frame, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
    wave.trace_camera_rays(&centre, 1);

    // Breadth first: level d's entries become nodes; each node tells its children (entries of
    // level d + 1, by index) who their parent is.
    struct Link {
        int parent = -1;
        RayTreeNode::Kind kind = RayTreeNode::Kind::camera;
        float weight = 1.0f;
    };
    size_t nodes = 0;
    for (const auto& level : record.rays) nodes += level.size();
    check_memory_need(static_cast<double>(nodes) * (sizeof(RayTreeNode) + sizeof(Link)),
                      fmt::format("the ray tree of one pixel ({} rays)", nodes));
    std::vector<RayTreeNode> tree;
    tree.reserve(nodes);
    std::vector<std::vector<Link>> links(record.rays.size());
    for (size_t d = 0; d < record.rays.size(); ++d) links[d].resize(record.rays[d].size());
    for (size_t d = 0; d < record.rays.size(); ++d)
        for (size_t i = 0; i < record.rays[d].size(); ++i) {
            const WaveRecord::Traced& traced = record.rays[d][i];
            const int self = static_cast<int>(tree.size());
            RayTreeNode& node = tree.emplace_back();
            node.depth = static_cast<int>(d);
            node.parent = links[d][i].parent;
            node.kind = links[d][i].kind;
            node.weight = links[d][i].weight;
            node.ray = traced.ray;
            node.hit = traced.hit;
            node.surface = traced.surface;
            node.local = record.own[d].colour_at(i);
            node.total = record.folded[d].colour_at(i);
            const PathLevel& own = record.own[d];
            if (d + 1 < links.size()) {
                if (own.mirror[i] >= 0)
                    links[d + 1][static_cast<size_t>(own.mirror[i])] = {
                        self, RayTreeNode::Kind::mirror, own.mirror_weight[i]};
                if (own.refract[i] >= 0)
                    links[d + 1][static_cast<size_t>(own.refract[i])] = {
                        self, RayTreeNode::Kind::refracted, own.refract_weight[i]};
            }
            if (!node.hit) continue;
            // The shadow rays toward the point and directional lights, cast as the tracer casts
            // them: from the hit turned to face the ray (face_the_ray), by ShadowRays.
            const WhittedHit<float> h{node.ray.direction, node.surface.position,
                                      node.surface.geometric_normal, node.surface.shading_normal,
                                      static_cast<int32_t>(node.surface.material)};
            MaskOf<float> entering{};
            const SurfacePoint<float> point = face_the_ray<float>(h, entering);
            const ShadowRays shadows{render.intersector, false, 0};
            for (uint32_t l = 0; l < one.lights.size(); ++l) {
                if (!is_delta_light(one.lights[l])) continue;
                const LightSample light = sample_light<float>(one.lights[l], point.position);
                ShadowRayRecord r{l, dot(point.normal, light.to_light) > 0.0f, false};
                if (r.facing) r.blocked = !shadows(l, light, point, true);
                node.shadow_rays.push_back(r);
            }
        }
    return tree;
}

Framebuffer render_whitted(const Scene& scene, Film film, const RenderSettings& settings,
                           const WhittedSettings& whitted) {
    if (!whitted.shadow_rays) {
        // No shadows: the same render of a scene where nothing casts one.
        WhittedSettings with_rays = whitted;
        with_rays.shadow_rays = true;
        return render_whitted(without_shadow_casters(scene), std::move(film), settings, with_rays);
    }
    const Camera& cam = scene.camera;
    // Every pixel is set below (by its tile), so 8-bit colour may start unwritten: its pages are
    // first touched by the tiles, in parallel.
    Framebuffer fb(std::move(film), cam.width, cam.height, settings.aov_buffers);
    const WhittedRender render(scene, settings, whitted, fb);
    report_bvh_stats(render.intersector, settings.stats, render.built_intersector);
    static_assert(k_tile_size <= k_primary_block);

    for_each_tile(cam.width, cam.height, settings.control, [&](const Tile& tile) {
        TraceContext ctx{render.intersector,        render.shading,         scene,
                         CameraCones(scene.camera), has_texture(scene),     whitted.max_depth,
                         render.emitters,           casts_any_shadow(scene)};
        thread_local std::unique_ptr<WaveScratch> scratch;
        if (!scratch) scratch = std::make_unique<WaveScratch>();
        WaveTracer wave(ctx, render.primary, render.shader, *scratch);
        if (whitted.samples_per_pixel == 1)
            render.render_centres(tile, wave);
        else
            render.render_samples(tile, wave, *scratch);
        if (settings.stats) settings.stats->rays_traced += ctx.rays;
    });
    return fb;
}

}  // namespace hikari
