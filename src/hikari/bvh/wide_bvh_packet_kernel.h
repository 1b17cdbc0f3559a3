#pragma once
// The packet traversal loop, written once as a template over 16-lane SIMD operations (`Ops`):
// the portable, AVX2 and AVX-512 kernels each instantiate it in their own translation unit,
// compiled for their instruction set (as wide_bvh_kernel.h does for single rays). Internal to
// wide_bvh_packet*.cpp.
//
// One call traces a group of alike rays: every direction has the same sign per axis (so the
// rays enter a box by the same faces) and the same watertight axis permutation (so the sheared
// triangle test runs on all lanes with one shuffle of vertex rows), and 1 / direction is finite.
// trace_packet splits a packet into such groups.
//
// Ops provides, all IEEE-exact and bit-identical across implementations:
//   V: 16 floats; load(const float*), store(float*, V), set1(float)
//   add, sub, mul, div, min, max: lane-wise; min(a, b) = a < b ? a : b, max alike
//   abs(V); sign(V): mask of the sign bits
//   lt, le, ge, eq, gt, neq(V, V): lane masks (ordered; neq is true for NaN)
//   select(mask, a, b): a where mask is set, else b
//   reduce_min, reduce_max(mask, V): over the lanes in mask (+inf / -inf when none)
//   store_masked(uint32_t* p, mask, x): p[i] = x for the lanes in mask
//   test_frustum(node, frustum, t_lo, t_hi, entry): mask of the children the frustum may meet
//     in [t_lo, t_hi]; entry[i] = a lower bound on where any of its rays enters child i

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "hikari/bvh/triangle_hit.h"
#include "hikari/bvh/wide_bvh.h"
#include "hikari/bvh/wide_bvh_packet.h"
#include "hikari/core/ray.h"
#include "hikari/geometry/triangle_intersect.h"

namespace hikari::packet_kernel {
// Internal linkage: each kernel translation unit compiles its own copy for its instruction set.
namespace {

/// Ize 2013's conservative exit scale, exactly as the single-ray kernel's (wide_bvh_kernel.h):
/// per ray, the packet culls a box only when the single-ray test would.
constexpr float k_exit_scale = [] {
    constexpr float e = std::numeric_limits<float>::epsilon() * 0.5f;
    return 1.0f + 2.0f * (3.0f * e / (1.0f - 3.0f * e));
}();

/// Interval bounds on a group's rays for the node test (interval arithmetic: Wald, Boulos &
/// Shirley 2007, Sec 4.2). Per axis the rays share the direction's sign, so every ray enters
/// by bounds row near_row and leaves by far_row; a ray's slab distance (b - o) * inv is
/// bounded below by min over the inverse-direction interval of (b - o_near) * inv and above
/// by the max of (b - o_far) * inv. Float rounding is monotone, so these bounds hold for the
/// rounded per-ray values too: the frustum keeps every box that some ray's own test keeps.
struct Frustum {
    std::array<int, 3> near_row, far_row;
    std::array<float, 3> o_near;          ///< max origin where the direction is positive, else min
    std::array<float, 3> o_far;           ///< min origin where the direction is positive, else max
    std::array<float, 3> inv_lo, inv_hi;  ///< range of 1 / direction over the group
};

/// A group's rays prepared for traversal, structure-of-arrays.
struct alignas(64) GroupRays {
    float origin[3][k_packet_size];
    float inv_dir[3][k_packet_size];  ///< 1 / direction, as the single-ray NodeRay
    float shear[3][k_packet_size];    ///< WatertightRay's sx, sy, sz
    float t_min[k_packet_size];
    int kx = 0, ky = 1, kz = 2;  ///< the group's watertight axis permutation
    Frustum frustum;
};

/// Prepares group `group` of `packet` (lanes with one sign pattern and one watertight
/// permutation: kz = axes % 3, kx and ky swapped when axes >= 3).
template <typename Ops>
void prepare(const RayPacket& packet, uint32_t group, int axes, GroupRays& r) {
    using V = typename Ops::V;
    const int kz = axes % 3;
    r.kz = kz, r.kx = (kz + 1) % 3, r.ky = (kz + 2) % 3;
    if (axes >= 3) std::swap(r.kx, r.ky);
    const V one = Ops::set1(1.0f);
    const uint32_t lane = static_cast<uint32_t>(std::countr_zero(group));
    for (int a = 0; a < 3; ++a) {
        const V o = Ops::load(packet.origin[a]);
        const V inv = Ops::div(one, Ops::load(packet.direction[a]));
        Ops::store(r.origin[a], o);
        Ops::store(r.inv_dir[a], inv);
        const bool negative = std::signbit(packet.direction[a][lane]);
        const float o_lo = Ops::reduce_min(group, o), o_hi = Ops::reduce_max(group, o);
        Frustum& f = r.frustum;
        f.near_row[a] = 2 * a + (negative ? 1 : 0);
        f.far_row[a] = 2 * a + (negative ? 0 : 1);
        f.o_near[a] = negative ? o_lo : o_hi;
        f.o_far[a] = negative ? o_hi : o_lo;
        f.inv_lo[a] = Ops::reduce_min(group, inv);
        f.inv_hi[a] = Ops::reduce_max(group, inv);
    }
    const V dz = Ops::load(packet.direction[r.kz]);
    Ops::store(r.shear[0], Ops::div(Ops::load(packet.direction[r.kx]), dz));
    Ops::store(r.shear[1], Ops::div(Ops::load(packet.direction[r.ky]), dz));
    Ops::store(r.shear[2], Ops::div(one, dz));
    Ops::store(r.t_min, Ops::load(packet.t_min));
}

/// The nearest hits found so far, per lane.
struct alignas(64) GroupHits {
    float t[k_packet_size];  ///< starts at the ray's t_max
    float u[k_packet_size];
    float v[k_packet_size];
    uint32_t slot[k_packet_size];  ///< triangle slot (index into WideBvh::triangle_ids)
    uint32_t found = 0;            ///< lanes with a hit
    uint32_t ties = 0;  ///< lanes that met a second triangle at exactly their nearest t: which
                        ///< one the single-ray kernel reports depends on its visiting order
};

/// The nearest hits' t, u, v, kept in registers while a leaf is tested.
template <typename Ops>
struct Nearest {
    typename Ops::V t, u, v;
};

/// The per-ray slab test of child `slot` of `node` for the lanes in `lanes`, exactly the
/// single-ray kernel's arithmetic (wide_bvh_kernel.h's test_node) on each lane.
template <typename Ops>
uint32_t test_box_lanes(const WideBvhNode& node, uint32_t slot, const GroupRays& r,
                        const float* t_max, uint32_t lanes) {
    using V = typename Ops::V;
    const Frustum& f = r.frustum;
    const auto slab = [&](int a, int row) {
        return Ops::mul(Ops::sub(Ops::set1(node.bounds[row][slot]), Ops::load(r.origin[a])),
                        Ops::load(r.inv_dir[a]));
    };
    V t0 = Ops::max(slab(0, f.near_row[0]), Ops::load(r.t_min));
    t0 = Ops::max(slab(1, f.near_row[1]), t0);
    t0 = Ops::max(slab(2, f.near_row[2]), t0);
    V t1 = Ops::min(slab(0, f.far_row[0]), Ops::load(t_max));
    t1 = Ops::min(slab(1, f.far_row[1]), t1);
    t1 = Ops::min(slab(2, f.far_row[2]), t1);
    return lanes & Ops::le(t0, Ops::mul(t1, Ops::set1(k_exit_scale)));
}

/// Steps 1-4 of Woop et al. 2013 for triangle i of a leaf block against every lane, the steps
/// and rounding as in triangle_intersect.h: the scaled barycentrics, their sum `det`, the
/// scaled distance, which lanes meet the triangle's interior (`inside`, det non-zero) and which
/// have an edge function exactly zero (`on_edge`: those need the reference test, Sec 4).
template <typename Ops>
struct ScaledHits {
    typename Ops::V e1, e2, det, t_scaled;
    uint32_t inside, on_edge;
};

template <typename Ops>
[[gnu::always_inline]] inline ScaledHits<Ops> scaled_hits(const GroupRays& r, const float* block,
                                                          uint32_t count, uint32_t i,
                                                          uint32_t lanes) {
    using V = typename Ops::V;
    const auto vertex = [&](int v, int axis) { return block[(3 * v + axis) * count + i]; };
    /* steps 1-2: vertices relative to the origins, sheared so each ray runs along +z */
    const V ox = Ops::load(r.origin[r.kx]), oy = Ops::load(r.origin[r.ky]),
            oz = Ops::load(r.origin[r.kz]);
    const V sx = Ops::load(r.shear[0]), sy = Ops::load(r.shear[1]);
    const V az = Ops::sub(Ops::set1(vertex(0, r.kz)), oz);
    const V bz = Ops::sub(Ops::set1(vertex(1, r.kz)), oz);
    const V cz = Ops::sub(Ops::set1(vertex(2, r.kz)), oz);
    const V ax = Ops::sub(Ops::sub(Ops::set1(vertex(0, r.kx)), ox), Ops::mul(sx, az));
    const V ay = Ops::sub(Ops::sub(Ops::set1(vertex(0, r.ky)), oy), Ops::mul(sy, az));
    const V bx = Ops::sub(Ops::sub(Ops::set1(vertex(1, r.kx)), ox), Ops::mul(sx, bz));
    const V by = Ops::sub(Ops::sub(Ops::set1(vertex(1, r.ky)), oy), Ops::mul(sy, bz));
    const V cx = Ops::sub(Ops::sub(Ops::set1(vertex(2, r.kx)), ox), Ops::mul(sx, cz));
    const V cy = Ops::sub(Ops::sub(Ops::set1(vertex(2, r.ky)), oy), Ops::mul(sy, cz));
    /* step 3: scaled barycentrics */
    const V e0 = Ops::sub(Ops::mul(cx, by), Ops::mul(cy, bx));
    const V e1 = Ops::sub(Ops::mul(ax, cy), Ops::mul(ay, cx));
    const V e2 = Ops::sub(Ops::mul(bx, ay), Ops::mul(by, ax));
    const V zero = Ops::set1(0.0f);
    const uint32_t on_edge = (Ops::eq(e0, zero) | Ops::eq(e1, zero) | Ops::eq(e2, zero)) & lanes;
    /* step 4: inside when all edge functions share a sign */
    const uint32_t negative = Ops::lt(e0, zero) | Ops::lt(e1, zero) | Ops::lt(e2, zero);
    const uint32_t positive = Ops::gt(e0, zero) | Ops::gt(e1, zero) | Ops::gt(e2, zero);
    // No branch on `inside`: for coherent rays whether a triangle is hit is a coin toss, and a
    // mispredicted branch costs more than the rest of the test.
    const V det = Ops::add(Ops::add(e0, e1), e2);
    /* step 5, scaled: the distance times det */
    const V sz = Ops::load(r.shear[2]);
    const V z0 = Ops::mul(e0, Ops::mul(sz, az)), z1 = Ops::mul(e1, Ops::mul(sz, bz)),
            z2 = Ops::mul(e2, Ops::mul(sz, cz));
    const V t_scaled = Ops::add(Ops::add(z0, z1), z2);
    // Within rounding of the origin: no hit (triangle_intersect.h, k_t_rounding).
    const V band = Ops::mul(Ops::set1(k_t_rounding),
                            Ops::add(Ops::add(Ops::abs(z0), Ops::abs(z1)), Ops::abs(z2)));
    const uint32_t inside = ~(negative & positive) & lanes & ~on_edge & Ops::neq(det, zero) &
                            Ops::gt(Ops::abs(t_scaled), band);
    return {e1, e2, det, t_scaled, inside, on_edge};
}

/// Woop et al. 2013 for one triangle against the lanes in `lanes` (scaled_hits, then the
/// division); lanes where an edge function is exactly zero take the reference test (its exact
/// fallback, Sec 4). Updates the nearest hits: t, u, v in `near` (registers, while a leaf is
/// tested), the rest in `h`. Returns the lanes whose nearest hit it became.
template <typename Ops>
uint32_t test_triangle(const RayPacket& packet, const GroupRays& r, const float* block,
                       uint32_t count, uint32_t i, uint32_t slot, uint32_t lanes,
                       Nearest<Ops>& near, GroupHits& h) {
    using V = typename Ops::V;
    const ScaledHits<Ops> s = scaled_hits<Ops>(r, block, count, i, lanes);
    uint32_t inside = s.inside;
    const uint32_t on_edge = s.on_edge;
    /* step 5: the hit distance */
    const V inv_det = Ops::div(Ops::set1(1.0f), s.det);
    const V t = Ops::mul(s.t_scaled, inv_det);
    inside &= Ops::lt(Ops::load(r.t_min), t);
    h.ties |= inside & h.found & Ops::eq(t, near.t);
    uint32_t nearer = inside & Ops::lt(t, near.t);
    near.t = Ops::select(nearer, t, near.t);
    near.u = Ops::select(nearer, Ops::mul(s.e1, inv_det), near.u);
    near.v = Ops::select(nearer, Ops::mul(s.e2, inv_det), near.v);
    Ops::store_masked(h.slot, nearer, slot);
    h.found |= nearer;
    if (on_edge == 0) return nearer;
    Ops::store(h.t, near.t), Ops::store(h.u, near.u), Ops::store(h.v, near.v);
    for (uint32_t m = on_edge; m != 0; m &= m - 1) {
        // A ray through an edge or vertex: rare, so the scalar reference test.
        const auto lane = static_cast<uint32_t>(std::countr_zero(m));
        Vec3 p0, p1, p2;
        load_leaf_triangle(block, count, i, p0, p1, p2);
        const auto hit = intersect_triangle(WatertightRay(packet.ray(lane)), p0, p1, p2,
                                            {r.t_min[lane], k_infinity});
        if (!hit) continue;
        const uint32_t bit = 1u << lane;
        if (hit->t == h.t[lane] && (h.found & bit)) h.ties |= bit;
        if (!(hit->t < h.t[lane])) continue;
        h.t[lane] = hit->t, h.u[lane] = hit->u, h.v[lane] = hit->v, h.slot[lane] = slot;
        h.found |= bit;
        nearer |= bit;
    }
    near = {Ops::load(h.t), Ops::load(h.u), Ops::load(h.v)};
    return nearer;
}

/// Fetches every child in `mask` of `node`, to be visited now: in a big mesh each is a cache
/// miss, and the misses then overlap instead of stalling one after the other.
inline void prefetch_children(const WideBvh& bvh, const WideBvhNode& node, uint32_t mask) {
    for (uint32_t m = mask; m != 0; m &= m - 1) {
        const uint32_t ref = node.child[std::countr_zero(m)];
        if (WideBvhRef::is_leaf(ref)) {
            const char* p = reinterpret_cast<const char*>(bvh.triangle_data.data() +
                                                          9 * size_t(WideBvhRef::leaf_first(ref)));
            const uint32_t bytes = 36 * WideBvhRef::leaf_count(ref);
            for (uint32_t b = 0; b < bytes; b += 64) __builtin_prefetch(p + b);
        } else {
            const char* p = reinterpret_cast<const char*>(bvh.nodes.data() + ref);
            for (uint32_t b = 0; b < sizeof(WideBvhNode); b += 64) __builtin_prefetch(p + b);
        }
    }
}

/// Tests every triangle of the leaf `ref` on the lanes `lanes`, each lane keeping its nearest hit
/// in `h`; when a lane found a nearer one, t_hi becomes the farthest any lane of `group` still
/// looks.
template <typename Ops>
[[gnu::always_inline]] inline void test_leaf(const RayPacket& packet, const GroupRays& r,
                                             const float* triangle_data, uint32_t ref,
                                             uint32_t lanes, uint32_t group, GroupHits& h,
                                             float& t_hi) {
    const uint32_t first = WideBvhRef::leaf_first(ref);
    const uint32_t count = WideBvhRef::leaf_count(ref);
    const float* block = triangle_data + 9 * size_t(first);
    Nearest<Ops> near{Ops::load(h.t), Ops::load(h.u), Ops::load(h.v)};
    uint32_t nearer = 0;
    for (uint32_t i = 0; i < count; ++i)
        nearer |= test_triangle<Ops>(packet, r, block, count, i, first + i, lanes, near, h);
    Ops::store(h.t, near.t), Ops::store(h.u, near.u), Ops::store(h.v, near.v);
    if (nearer != 0) t_hi = Ops::reduce_max(group, near.t);
}

/// A child deferred by the closest-hit loop.
struct StackEntry {
    uint32_t ref;
    float entry;      ///< no ray of the group enters it before this
    uint32_t parent;  ///< the node holding its box (the leaf test needs the box)
    uint32_t slot;    ///< its slot in that node
};

/// StackEntry::parent of the root, whose box is the frustum's own.
constexpr uint32_t k_no_parent = ~0u;

/// The traversal loop: a stack of (reference, entry bound, parent, slot). Inner nodes: the
/// frustum test of all eight children, hit children visited nearest (lower entry bound) first.
/// Leaves: the per-ray test of the leaf's box narrows the lanes, then every triangle is tested
/// on those lanes.
template <typename Ops>
void traverse(const WideBvh& bvh, const RayPacket& packet, uint32_t group, int axes, GroupHits& h) {
    GroupRays r;
    prepare<Ops>(packet, group, axes, r);
    Ops::store(h.t, Ops::load(packet.t_max));
    Ops::store(h.u, Ops::set1(0.0f)), Ops::store(h.v, Ops::set1(0.0f));

    const WideBvhNode* nodes = bvh.nodes.data();
    const float* triangle_data = bvh.triangle_data.data();
    const float t_lo = Ops::reduce_min(group, Ops::load(r.t_min));
    float t_hi = Ops::reduce_max(group, Ops::load(h.t));  // farthest a ray still looks

    std::array<StackEntry, k_wide_bvh_stack_size> stack;
    uint32_t stack_size = 0;
    alignas(32) std::array<float, k_wide_bvh_width> entry;

    StackEntry current{bvh.root, t_lo, k_no_parent, 0};
    for (;;) {
        if (!WideBvhRef::is_leaf(current.ref)) {
            /* inner node: the frustum against eight boxes, nearest hit child first */
            const WideBvhNode& node = nodes[current.ref];
            uint32_t mask = Ops::test_frustum(node, r.frustum, t_lo, t_hi, entry.data());
            prefetch_children(bvh, node, mask);
            if (mask != 0) {
                const auto first = static_cast<uint32_t>(std::countr_zero(mask));
                mask &= mask - 1;
                const uint32_t parent = current.ref;
                if (mask == 0) {
                    current = {node.child[first], entry[first], parent, first};
                    continue;
                }
                // Insertion sort by entry bound, then push farthest first.
                std::array<StackEntry, k_wide_bvh_width> hits;
                uint32_t n = 0;
                hits[n++] = {node.child[first], entry[first], parent, first};
                for (; mask != 0; mask &= mask - 1) {
                    const auto i = static_cast<uint32_t>(std::countr_zero(mask));
                    const StackEntry e{node.child[i], entry[i], parent, i};
                    uint32_t k = n++;
                    for (; k > 0 && hits[k - 1].entry > e.entry; --k) hits[k] = hits[k - 1];
                    hits[k] = e;
                }
                for (uint32_t k = n - 1; k > 0; --k) stack[stack_size++] = hits[k];
                current = hits[0];
                continue;
            }
        } else {
            /* leaf: the lanes whose own slab test keeps its box, then its triangles */
            uint32_t lanes = group;
            if (current.parent != k_no_parent)
                lanes = test_box_lanes<Ops>(nodes[current.parent], current.slot, r, h.t, group);
            if (lanes != 0)
                test_leaf<Ops>(packet, r, triangle_data, current.ref, lanes, group, h, t_hi);
        }

        /* pop the next node some ray may still enter before its nearest hit */
        bool popped = false;
        const float limit = t_hi * k_exit_scale;
        while (stack_size > 0 && !popped) {
            current = stack[--stack_size];
            popped = current.entry <= limit;
        }
        if (!popped) return;
    }
}

/// Whether each lane in `lanes` meets triangle i of a leaf block inside its interval (t_min,
/// t_max), exactly triangle_occludes's answer (geometry/triangle_intersect.h): the distance
/// compared before the division (scaled_distance_inside), lanes with an edge function exactly zero
/// by the reference test itself.
template <typename Ops>
uint32_t occludes_triangle(const RayPacket& packet, const GroupRays& r, const float* t_max,
                           const float* block, uint32_t count, uint32_t i, uint32_t lanes) {
    using V = typename Ops::V;
    const ScaledHits<Ops> s = scaled_hits<Ops>(r, block, count, i, lanes);
    // scaled_distance_inside: the signed distance times |det| against the bounds times |det|.
    const V abs_det = Ops::abs(s.det);
    const V t_signed = Ops::select(Ops::lt(s.det, Ops::set1(0.0f)),
                                   Ops::sub(Ops::set1(0.0f), s.t_scaled), s.t_scaled);
    uint32_t occluded = s.inside & Ops::lt(Ops::mul(Ops::load(r.t_min), abs_det), t_signed) &
                        Ops::lt(t_signed, Ops::mul(Ops::load(t_max), abs_det));
    for (uint32_t m = s.on_edge; m != 0; m &= m - 1) {
        // A ray through an edge or vertex: rare, so the scalar reference test.
        const auto lane = static_cast<uint32_t>(std::countr_zero(m));
        Vec3 p0, p1, p2;
        load_leaf_triangle(block, count, i, p0, p1, p2);
        if (triangle_occludes(WatertightRay(packet.ray(lane)), p0, p1, p2,
                              {r.t_min[lane], t_max[lane]}))
            occluded |= 1u << lane;
    }
    return occluded;
}

/// A child deferred by the any-hit loop.
struct AnyStackEntry {
    uint32_t ref;
    uint32_t lanes;  ///< the lanes whose slab test keeps its box
};

/// The any-hit loop (shadow rays): at an inner node the frustum test of all eight children,
/// then each child the frustum keeps tested for the lanes still looking (Wald et al. 2001's
/// active lanes): a child is entered only with the lanes whose own slab test keeps its box,
/// and skipped when there are none. Shadow rays from a row of surface points do not share an
/// origin, and their frustum alone keeps dozens of leaves near the surface that no single ray
/// enters (0.2-0.3 lanes per leaf visit on the bunny and bumpy1m). A lane that meets a
/// triangle is done; children are taken in slot order. Returns the lanes of `group` that met
/// a triangle. Every lane's answer is its own any-hit answer: a box is skipped for a lane only
/// when that lane's single-ray test would skip it, and which triangle answers does not matter.
template <typename Ops>
uint32_t traverse_any(const WideBvh& bvh, const RayPacket& packet, uint32_t group, int axes) {
    GroupRays r;
    prepare<Ops>(packet, group, axes, r);
    const WideBvhNode* nodes = bvh.nodes.data();
    const float* triangle_data = bvh.triangle_data.data();
    const float t_lo = Ops::reduce_min(group, Ops::load(r.t_min));
    const float t_hi = Ops::reduce_max(group, Ops::load(packet.t_max));

    std::array<AnyStackEntry, k_wide_bvh_stack_size> stack;
    uint32_t stack_size = 0;
    alignas(32) std::array<float, k_wide_bvh_width> entry;

    uint32_t open = group;  // lanes that have met no triangle yet
    AnyStackEntry current{bvh.root, group};
    for (;;) {
        const uint32_t lanes = current.lanes & open;
        if (lanes == 0) {
            // every lane that entered this box has met a triangle since it was pushed
        } else if (!WideBvhRef::is_leaf(current.ref)) {
            /* inner node: the frustum against eight boxes, then each kept child per lane */
            const WideBvhNode& node = nodes[current.ref];
            uint32_t mask = Ops::test_frustum(node, r.frustum, t_lo, t_hi, entry.data());
            std::array<AnyStackEntry, k_wide_bvh_width> children;
            uint32_t n = 0, entered = 0;
            for (; mask != 0; mask &= mask - 1) {
                const auto i = static_cast<uint32_t>(std::countr_zero(mask));
                const uint32_t child_lanes = test_box_lanes<Ops>(node, i, r, packet.t_max, lanes);
                if (child_lanes == 0) continue;
                children[n++] = {node.child[i], child_lanes};
                entered |= 1u << i;
            }
            prefetch_children(bvh, node, entered);
            if (n != 0) {
                for (uint32_t k = n - 1; k > 0; --k) stack[stack_size++] = children[k];
                current = children[0];
                continue;
            }
        } else {
            /* leaf: its triangles against the lanes that entered its box */
            const uint32_t first = WideBvhRef::leaf_first(current.ref);
            const uint32_t count = WideBvhRef::leaf_count(current.ref);
            const float* block = triangle_data + 9 * size_t(first);
            uint32_t testing = lanes;
            for (uint32_t i = 0; i < count && testing != 0; ++i) {
                const uint32_t hit =
                    occludes_triangle<Ops>(packet, r, packet.t_max, block, count, i, testing);
                testing &= ~hit;
                open &= ~hit;
            }
            if (open == 0) return group;
        }
        if (stack_size == 0) return group & ~open;
        current = stack[--stack_size];
    }
}

/// Sorts the lanes `active` of `packet` into groups of alike rays (one direction octant and
/// one watertight permutation) and calls trace(group, axes) for each group of at least
/// `min_group` lanes; `single` gets the lanes the caller must trace with the single-ray kernel
/// instead (small groups, rays whose 1 / direction may overflow, odd intervals).
template <typename Ops, typename Trace>
void for_each_group(const RayPacket& packet, uint32_t active, uint32_t min_group, uint32_t& single,
                    const Trace& trace) {
    using V = typename Ops::V;
    /* per lane: may it go in a packet, its direction's signs and its dominant axis */
    uint32_t ok = active & Ops::eq(Ops::load(packet.t_min), Ops::load(packet.t_min)) &
                  Ops::eq(Ops::load(packet.t_max), Ops::load(packet.t_max));
    uint32_t negative[3];
    V abs_dir[3];
    const V inf = Ops::set1(k_infinity);
    for (int a = 0; a < 3; ++a) {
        const V d = Ops::load(packet.direction[a]);
        abs_dir[a] = Ops::abs(d);
        negative[a] = Ops::sign(d);
        // Below 1e-30, 1 / d may overflow, and inf * 0 = NaN would defeat the bounds.
        ok &= Ops::lt(Ops::abs(Ops::load(packet.origin[a])), inf) & Ops::lt(abs_dir[a], inf) &
              Ops::ge(abs_dir[a], Ops::set1(1e-30f));
    }
    // WatertightRay's rule: kz is the first axis of largest |d|.
    const uint32_t kz0 = Ops::ge(abs_dir[0], abs_dir[1]) & Ops::ge(abs_dir[0], abs_dir[2]);
    const uint32_t kz1 = ~kz0 & Ops::ge(abs_dir[1], abs_dir[2]);
    const std::array<uint32_t, 5> traits = {negative[0], negative[1], negative[2], kz0, kz1};
    single = active & ~ok;

    while (ok != 0) {
        /* the group of the first remaining lane: the lanes agreeing with it on every trait */
        const uint32_t lead = ok & -ok;
        uint32_t group = ok;
        for (uint32_t t : traits) group &= (t & lead) ? t : ~t;
        ok &= ~group;
        if (uint32_t(std::popcount(group)) < min_group) {
            single |= group;
            continue;
        }
        const int kz = (kz0 & lead) ? 0 : (kz1 & lead) ? 1 : 2;
        trace(group, kz + ((negative[kz] & lead) ? 3 : 0));
    }
}

/// Traces the lanes `active` of `packet`: sorts them into groups of one direction octant and
/// one watertight permutation and traces each group of at least `min_group` lanes as a packet.
/// Fills the lanes of `out` that hit and returns them; `single` gets the lanes the caller must
/// trace with the single-ray kernel instead (small groups, rays whose 1 / direction may
/// overflow, odd intervals, and ties).
template <typename Ops>
uint32_t trace_packet(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                      uint32_t min_group, PacketHit& out, uint32_t& single) {
    uint32_t found = 0, ties = 0;
    for_each_group<Ops>(packet, active, min_group, single, [&](uint32_t group, int axes) {
        GroupHits h;
        traverse<Ops>(bvh, packet, group, axes, h);
        for (uint32_t m = h.found; m != 0; m &= m - 1) {
            const auto lane = static_cast<uint32_t>(std::countr_zero(m));
            out.t[lane] = h.t[lane], out.u[lane] = h.u[lane], out.v[lane] = h.v[lane];
            out.triangle[lane] = bvh.triangle_ids[h.slot[lane]];
        }
        found |= h.found;
        // Two triangles at exactly the nearest t: the single-ray kernel reports the first in
        // its own visiting order, so it must answer.
        ties |= h.ties;
    });
    single |= ties;
    return found & ~single;
}

/// The any-hit form of trace_packet: the lanes of `active` whose ray meets a triangle inside
/// its interval; `single` as for trace_packet (no ties: any triangle answers).
template <typename Ops>
uint32_t trace_packet_any(const WideBvh& bvh, const RayPacket& packet, uint32_t active,
                          uint32_t min_group, uint32_t& single) {
    uint32_t occluded = 0;
    for_each_group<Ops>(packet, active, min_group, single, [&](uint32_t group, int axes) {
        occluded |= traverse_any<Ops>(bvh, packet, group, axes);
    });
    return occluded;
}

}  // namespace
}  // namespace hikari::packet_kernel
