#include "hikari/raster/shadow_volume.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "hikari/core/parallel.h"
#include "hikari/core/ray.h"
#include "hikari/frame/tiles.h"
#include "hikari/raster/clip.h"
#include "hikari/raster/cull.h"
#include "hikari/raster/half_space.h"
#include "hikari/raster/tile_bins.h"
#include "hikari/shading/lights.h"

namespace hikari {

namespace {

/// A position's exact bits, −0 folded into +0, as a key for welding.
struct PositionKey {
    std::array<uint32_t, 3> bits;
    bool operator==(const PositionKey&) const = default;
};

struct PositionKeyHash {
    size_t operator()(const PositionKey& k) const {
        uint64_t h = 0x9E3779B97F4A7C15ull;
        for (uint32_t b : k.bits) h = (h ^ b) * 0x100000001B3ull;
        return static_cast<size_t>(h ^ (h >> 29));
    }
};

PositionKey key_of(Vec3 p) {
    return {{std::bit_cast<uint32_t>(p.x + 0.0f), std::bit_cast<uint32_t>(p.y + 0.0f),
             std::bit_cast<uint32_t>(p.z + 0.0f)}};
}

/// One use of an edge by a triangle: the edge's welded end points (smaller first) and
/// whether the triangle, turned toward the light, runs along it from smaller to larger.
struct EdgeUse {
    uint64_t key;
    uint32_t triangle;  ///< index into the caster list
    uint8_t edge;       ///< 0, 1, 2: from corner k to corner k + 1 of the triangle as stored
    bool forward;
};

/// Union–find over triangles, to group them into connected parts.
struct Components {
    std::vector<uint32_t> parent;
    explicit Components(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    uint32_t root(uint32_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    }
    void join(uint32_t a, uint32_t b) { parent[root(a)] = root(b); }
};

/// The casters as a mesh: which of them bound a volume, and which of their edges are inside
/// the volumes' boundary (where two bounding triangles meet, their sides cancel).
struct CasterMesh {
    std::vector<uint32_t> triangles;  ///< indices into the TriangleSet
    std::vector<uint8_t> facing;      ///< faces the light (else it is turned to face it)
    std::vector<uint8_t> bounding;    ///< emits caps and sides
    std::vector<std::array<uint8_t, 3>> inner_edge;  ///< per edge: no side along it
};

/// Welds the casters' corners by exact position and sorts their edge uses, so that the uses
/// of one edge are neighbours. `corner` receives the welded corners.
std::vector<EdgeUse> edge_uses(const TriangleSet& tris, const CasterMesh& mesh,
                               std::vector<std::array<uint32_t, 3>>& corner) {
    const size_t n = mesh.triangles.size();
    std::unordered_map<PositionKey, uint32_t, PositionKeyHash> welded;
    corner.resize(n);
    std::vector<EdgeUse> uses;
    uses.reserve(3 * n);
    for (uint32_t i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k) {
            const Vec3 p = tris.positions[tris.indices[mesh.triangles[i]][k]];
            corner[i][k] =
                welded.emplace(key_of(p), static_cast<uint32_t>(welded.size())).first->second;
        }
        for (uint8_t k = 0; k < 3; ++k) {
            const uint32_t a = corner[i][k], b = corner[i][(k + 1) % 3];
            if (a == b) continue;  // a zero-length edge bounds nothing
            // A triangle facing away is turned to face the light: its edges run backward.
            const bool forward = (a < b) == (mesh.facing[i] != 0);
            uses.push_back({(uint64_t{std::min(a, b)} << 32) | std::max(a, b), i, k, forward});
        }
    }
    std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
        return x.key != y.key ? x.key < y.key : x.triangle < y.triangle;
    });
    return uses;
}

/// Every caster's prism (itself extruded away from the light, caps at both ends) bounds a
/// region the light cannot reach; their sum is the shadow. Where two bounding triangles share
/// an edge, run oppositely (turned toward the light), their sides coincide with opposite
/// orientation and cancel: only silhouettes and borders keep sides. A closed part of the mesh
/// (every edge shared by two triangles wound oppositely) is bounded by its light-facing
/// triangles alone — Crow's volume — since any ray through it crosses one of those.
CasterMesh caster_mesh(const TriangleSet& tris, const std::vector<uint8_t>& casters,
                       const std::vector<uint8_t>& facing_all) {
    CasterMesh mesh;
    for (uint32_t t = 0; t < tris.size(); ++t)
        if (casters[t]) {
            mesh.triangles.push_back(t);
            mesh.facing.push_back(facing_all[t]);
        }
    const size_t n = mesh.triangles.size();
    std::vector<std::array<uint32_t, 3>> corner;
    const std::vector<EdgeUse> uses = edge_uses(tris, mesh, corner);
    // Closed parts: joined across manifold edges; any other edge opens its triangles' part.
    std::vector<uint8_t> open(n, 0);
    Components parts(n);
    auto for_each_run = [&](auto&& fn) {
        for (size_t first = 0; first < uses.size();) {
            size_t last = first;
            while (last < uses.size() && uses[last].key == uses[first].key) ++last;
            fn(first, last);
            first = last;
        }
    };
    for_each_run([&](size_t first, size_t last) {
        const EdgeUse& u = uses[first];
        const bool manifold =
            last - first == 2 &&
            (corner[u.triangle][u.edge] < corner[u.triangle][(u.edge + 1) % 3]) !=
                (corner[uses[first + 1].triangle][uses[first + 1].edge] <
                 corner[uses[first + 1].triangle][(uses[first + 1].edge + 1) % 3]);
        if (manifold)
            parts.join(u.triangle, uses[first + 1].triangle);
        else
            for (size_t k = first; k < last; ++k) open[uses[k].triangle] = 1;
    });
    std::vector<uint8_t> open_part(n, 0);
    for (uint32_t i = 0; i < n; ++i)
        if (open[i]) open_part[parts.root(i)] = 1;
    mesh.bounding.resize(n);
    for (uint32_t i = 0; i < n; ++i)
        mesh.bounding[i] = mesh.facing[i] || open_part[parts.root(i)] ? 1 : 0;
    mesh.inner_edge.assign(n, {0, 0, 0});
    for_each_run([&](size_t first, size_t last) {
        if (last - first != 2) return;
        const EdgeUse& u = uses[first];
        const EdgeUse& v = uses[first + 1];
        if (u.forward != v.forward && mesh.bounding[u.triangle] && mesh.bounding[v.triangle]) {
            mesh.inner_edge[u.triangle][u.edge] = 1;
            mesh.inner_edge[v.triangle][v.edge] = 1;
        }
    });
    return mesh;
}

/// Builds the polygons of volumes for one light: `beyond(p)` is p's point at infinity, away
/// from the light (w = 0); `to_light(p)` the direction from p toward the light.
class VolumeBuilder {
  public:
    VolumeBuilder(const Light& light, std::vector<VolumePolygon>& out) : m_out(out) {
        const LightShadowView view = shadow_view(light);
        if (view.projection == ShadowProjection::parallel) {
            m_directional = true;
            m_direction = normalize(view.direction);
        } else {
            m_position = view.origin;
        }
    }

    bool faces_light(Vec3 a, Vec3 b, Vec3 c) const {
        const Vec3 to_light = m_directional ? -m_direction : m_position - a;
        return dot(face_normal(a, b, c), to_light) > 0.0f;
    }

    /// The front cap (a, b, c), facing the light, and its back cap at infinity.
    void caps(Vec3 a, Vec3 b, Vec3 c) {
        m_out.push_back({{Vec4(a, 1), Vec4(b, 1), Vec4(c, 1)}, 3});
        // A directional light's back cap shrinks to one point at infinity: no area.
        if (!m_directional) m_out.push_back({{beyond(a), beyond(c), beyond(b)}, 3});
    }

    /// The side of the volume along edge a → b of a front cap: b → a → a∞ → b∞.
    void side(Vec3 a, Vec3 b) {
        if (m_directional)
            m_out.push_back({{Vec4(b, 1), Vec4(a, 1), beyond(a)}, 3});
        else
            m_out.push_back({{Vec4(b, 1), Vec4(a, 1), beyond(a), beyond(b)}, 4});
    }

  private:
    Vec4 beyond(Vec3 p) const {
        return m_directional ? Vec4(m_direction, 0) : Vec4(p - m_position, 0);
    }

    std::vector<VolumePolygon>& m_out;
    bool m_directional = false;
    Vec3 m_direction, m_position;
};

/// The plane through three homogeneous points, as (n, d) with n·x + d·w = 0 on it: the 4D
/// cross product (cofactors of the 3 × 4 matrix of the points), in double precision.
std::array<double, 4> plane_through(Vec4 p, Vec4 q, Vec4 r) {
    const double m[3][4] = {{p.x, p.y, p.z, p.w}, {q.x, q.y, q.z, q.w}, {r.x, r.y, r.z, r.w}};
    auto minor = [&](int c0, int c1, int c2) {
        return m[0][c0] * (m[1][c1] * m[2][c2] - m[1][c2] * m[2][c1]) -
               m[0][c1] * (m[1][c0] * m[2][c2] - m[1][c2] * m[2][c0]) +
               m[0][c2] * (m[1][c0] * m[2][c1] - m[1][c1] * m[2][c0]);
    };
    return {minor(1, 2, 3), -minor(0, 2, 3), minor(0, 1, 3), -minor(0, 1, 2)};
}

/// A piece of a volume polygon on screen, ready to rasterize.
struct StencilPiece {
    HalfSpaceTriangle setup;
    int8_t step;                  ///< +1: the camera sees the polygon's back; −1: its front
    std::array<double, 4> plane;  ///< the polygon's plane, for exact fragment depths
};

/// Projects one fan triangle of a volume polygon, clips it and appends its screen pieces.
void add_pieces(const Vec4 (&world)[3], const RasterView& view, std::vector<StencilPiece>& out) {
    const std::array<double, 4> plane = plane_through(world[0], world[1], world[2]);
    const ClipPolygon poly =
        clip_triangle(view.clip_from_world * world[0], view.clip_from_world * world[1],
                      view.clip_from_world * world[2]);
    if (poly.count < 3) return;
    std::array<ScreenVertex, k_max_clip_vertices> sv;
    for (int i = 0; i < poly.count; ++i) {
        const float inv_w = 1.0f / poly.v[i].w;
        sv[i] = {transform_point(view.screen_from_clip, poly.v[i].xyz() * inv_w), inv_w};
    }
    for (int i = 1; i + 1 < poly.count; ++i) {
        const ScreenTriangle t{{sv[0], sv[i], sv[i + 1]}, 0};
        const Vec3 e1 = t.v[1].position - t.v[0].position, e2 = t.v[2].position - t.v[0].position;
        // Counter-clockwise in the world shows clockwise on a screen whose y points down.
        const float area = e1.x * e2.y - e1.y * e2.x;
        StencilPiece piece{{}, static_cast<int8_t>(area > 0.0f ? 1 : -1), plane};
        if (area != 0.0f && setup_half_space(t, view.width, view.height, piece.setup))
            out.push_back(piece);
    }
}

}  // namespace

std::vector<VolumePolygon> shadow_volume_polygons(const TriangleSet& tris,
                                                  const std::vector<uint8_t>& casters,
                                                  const Light& light) {
    std::vector<VolumePolygon> out;
    VolumeBuilder volume(light, out);
    auto corners = [&](uint32_t t) {
        const auto& idx = tris.indices[t];
        return std::array<Vec3, 3>{tris.positions[idx[0]], tris.positions[idx[1]],
                                   tris.positions[idx[2]]};
    };
    std::vector<uint8_t> facing(tris.size(), 0);
    for (uint32_t t = 0; t < tris.size(); ++t) {
        const auto p = corners(t);
        if (casters[t]) facing[t] = volume.faces_light(p[0], p[1], p[2]) ? 1 : 0;
    }
    const CasterMesh mesh = caster_mesh(tris, casters, facing);
    for (uint32_t i = 0; i < mesh.triangles.size(); ++i) {
        if (!mesh.bounding[i]) continue;
        const auto p = corners(mesh.triangles[i]);
        // Turned to face the light; edge k of q is edge k of p, or its reverse.
        const bool turned = !mesh.facing[i];
        const std::array<Vec3, 3> q = turned ? std::array<Vec3, 3>{p[0], p[2], p[1]} : p;
        volume.caps(q[0], q[1], q[2]);
        for (int k = 0; k < 3; ++k) {
            // Turned, q's edge k (q_k → q_k+1) is p's edge 2 − k run backward.
            const int stored = turned ? 2 - k : k;
            if (!mesh.inner_edge[i][stored]) volume.side(q[k], q[(k + 1) % 3]);
        }
    }
    return out;
}

std::vector<uint8_t> stencil_shadow_mask(std::span<const VolumePolygon> polygons,
                                         const RasterView& view, const CameraFrame& frame,
                                         std::span<const float> depth) {
    const int width = view.width, height = view.height;
    std::vector<StencilPiece> pieces;
    for (const VolumePolygon& polygon : polygons)
        for (int k = 1; k + 1 < polygon.count; ++k) {
            const Vec4 fan[3] = {polygon.v[0], polygon.v[k], polygon.v[k + 1]};
            add_pieces(fan, view, pieces);
        }
    std::vector<HalfSpaceTriangle> setup(pieces.size());
    std::vector<uint32_t> home(pieces.size());
    for (size_t i = 0; i < pieces.size(); ++i) {
        setup[i] = pieces[i].setup;
        home[i] = home_tile(setup[i], width);
    }
    TileBins bins;
    bin_triangles(setup, home, width, height, bins);

    std::vector<uint8_t> mask(static_cast<size_t>(width) * height, 0);
    for_each_tile(width, height, nullptr, [&](const Tile& tile) {
        constexpr int k_pixels = k_tile_size * k_tile_size;
        std::array<int32_t, k_pixels> stencil{};
        // The tile's camera rays and visible depths (+infinity: nothing seen, nothing counts).
        std::array<Vec3, k_pixels> ray, origin;
        std::array<float, k_pixels> seen;
        seen.fill(k_infinity);
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x) {
                const int i = (y - tile.y0) * k_tile_size + (x - tile.x0);
                const Ray r = camera_ray(frame, x + 0.5f, y + 0.5f);
                ray[i] = r.direction;
                origin[i] = r.origin;  // the eye, or a point of an orthographic image plane
                seen[i] = depth[static_cast<size_t>(y) * width + x];
            }
        const size_t bin = bins.tile_at(tile.x0, tile.y0);
        bins.for_each(bin, [&](uint32_t piece_index) {
            const StencilPiece& piece = pieces[piece_index];
            const auto& pl = piece.plane;
            if (pl[0] == 0.0 && pl[1] == 0.0 && pl[2] == 0.0) {
                // A cap at infinity lies behind every visible point.
                for_each_covered_pixel(piece.setup, tile.x0, tile.y0, tile.x1, tile.y1,
                                       [&](int x, int y, float, float, float) {
                                           const int i =
                                               (y - tile.y0) * k_tile_size + (x - tile.x0);
                                           if (seen[i] < k_infinity) stencil[i] += piece.step;
                                       });
                return;
            }
            for_each_covered_pixel(piece.setup, tile.x0, tile.y0, tile.x1, tile.y1,
                                   [&](int x, int y, float, float, float) {
                                       const int i = (y - tile.y0) * k_tile_size + (x - tile.x0);
                                       if (!(seen[i] < k_infinity)) return;
                                       const Vec3 d = ray[i], o = origin[i];
                                       const double at_eye =
                                           pl[0] * o.x + pl[1] * o.y + pl[2] * o.z + pl[3];
                                       const double along = pl[0] * d.x + pl[1] * d.y + pl[2] * d.z;
                                       double t = -at_eye / along;
                                       // Behind the eye or undefined only through rounding at
                                       // infinity: far away.
                                       if (!(t > 0.0) || !std::isfinite(t))
                                           t = std::numeric_limits<double>::infinity();
                                       // z-fail: only fragments not in front of the visible point
                                       // count. The point's own face, a front cap, counts too
                                       // (relative tolerance): the surface on the boundary of its
                                       // volume is outside it.
                                       if (t >= seen[i] * (1.0 - 1e-4)) stencil[i] += piece.step;
                                   });
        });
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x)
                mask[static_cast<size_t>(y) * width + x] =
                    stencil[(y - tile.y0) * k_tile_size + (x - tile.x0)] != 0 ? 1 : 0;
    });
    return mask;
}

}  // namespace hikari
