#include "hikari/bvh/bvh_builder.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <tbb/blocked_range.h>

#include "hikari/core/parallel.h"

namespace hikari {
namespace {

constexpr uint32_t k_max_bins = 32;

/// A triangle as the builder moves it around: its bounds and its input index together, so every
/// pass over a range reads memory sequentially (Embree's PrimRef; Wald 2007 Sec 3.1).
struct PrimRef {
    Aabb bounds;
    uint32_t id = 0;

    /// The centre of the bounds, as in Wald 2007.
    Vec3 centroid() const { return bounds.center(); }
};

/// Bounds of a range of triangles and of their centroids (the SAH bins by centroid).
struct RangeBounds {
    Aabb bounds;
    Aabb centroids;

    void extend(const RangeBounds& b) {
        bounds.extend(b.bounds);
        centroids.extend(b.centroids);
    }
};

/// One SAH bin: the triangles whose centroid falls into a slab of the centroid bounds.
struct Bin {
    Aabb bounds;
    uint32_t count = 0;
};

/// Bins along all three axes at once.
struct Bins {
    std::array<std::array<Bin, k_max_bins>, 3> axis;

    void merge(const Bins& b, uint32_t bin_count) {
        for (int a = 0; a < 3; ++a) {
            for (uint32_t i = 0; i < bin_count; ++i) {
                axis[a][i].bounds.extend(b.axis[a][i].bounds);
                axis[a][i].count += b.axis[a][i].count;
            }
        }
    }
};

/// Wald 2007, Sec 3.2: centroid c falls into bin floor(k1 (c - c_min)) with
/// k1 = K (1 - eps) / (c_max - c_min); the clamp guards against rounding at c_max.
struct BinMapping {
    Vec3 origin;
    Vec3 scale;
    uint32_t bin_count = 0;

    BinMapping(const Aabb& centroids, uint32_t bins) : origin(centroids.min), bin_count(bins) {
        const Vec3 extent = centroids.extent();
        for (int a = 0; a < 3; ++a) {
            const float k1 = float(bins) * (1.0f - 1e-6f) / extent[a];
            scale[a] = extent[a] > 0.0f && std::isfinite(k1) ? k1 : 0.0f;  // 0: a flat axis
        }
    }
    uint32_t operator()(Vec3 c, int axis) const {
        const float f = (c[axis] - origin[axis]) * scale[axis];
        if (!(f > 0.0f)) return 0;
        return f < float(bin_count - 1) ? static_cast<uint32_t>(f) : bin_count - 1;
    }
};

/// The best SAH split found: triangles in bins [0, bin) of `axis` go left.
struct Split {
    float cost = std::numeric_limits<float>::infinity();
    int axis = -1;
    uint32_t bin = 0;
};

/// ceil(log2(n)) for n >= 1: the depth of a tree that halves n items down to single ones.
uint32_t ceil_log2(uint32_t n) { return static_cast<uint32_t>(std::bit_width(n - 1)); }

/// Maps -0 to +0, so that bounds are bitwise identical whatever order min/max ran in.
Vec3 canonical_zero(Vec3 v) { return v + Vec3(0.0f); }

/// The recursive binned-SAH build over a permutation of triangle ids. Every node is written to
/// a slot fixed in advance (a subtree over n triangles owns 2n - 1 slots), so the slots, and the
/// tree, do not depend on which thread builds which subtree.
class BinnedSahBuilder {
  public:
    BinnedSahBuilder(const BvhBuildSettings& settings, std::span<PrimRef> refs,
                     std::span<BvhNode> slots)
        : m_refs(refs), m_slots(slots) {
        m_bin_count = std::clamp(settings.bin_count, 2u, k_max_bins);
        m_min_leaf = std::max(settings.min_leaf_size, 1u);
        m_max_leaf = std::clamp(settings.max_leaf_size, m_min_leaf, 255u);
        m_traversal_cost = settings.traversal_cost;
        m_parallel_threshold = std::max(settings.parallel_threshold, 2u);
    }

    /// Builds the subtree over m_ids[begin, end) into slot `slot`; its descendants go to the
    /// 2 (end - begin) - 2 slots starting at `region`.
    void build(uint32_t slot, uint32_t region, uint32_t begin, uint32_t end, uint32_t depth) {
        const uint32_t n = end - begin;
        const RangeBounds range = range_bounds(begin, end);
        BvhNode& node = m_slots[slot];
        node.bounds = range.bounds;
        if (n <= m_min_leaf) return make_leaf(node, begin, n);

        // Only balanced halving from here on fits the depth limit (and the traversal stack).
        const bool must_halve = depth + ceil_log2(n) + 1 >= k_bvh_max_depth;
        const Split split = must_halve ? Split{} : find_split(begin, end, range);
        const bool split_pays = split.axis >= 0 && split.cost < float(n);
        if (n <= m_max_leaf && !split_pays) return make_leaf(node, begin, n);

        int axis = split.axis;
        uint32_t mid = axis >= 0 ? partition(begin, end, range, split) : begin;
        if (mid == begin || mid == end) {
            axis = range.centroids.largest_axis();
            mid = median_split(begin, end, axis);
        }

        node.index = region;
        node.triangle_count = 0;
        node.split_axis = static_cast<uint8_t>(axis);
        const uint32_t left_count = mid - begin;
        const auto build_left = [&] { build(region, region + 2, begin, mid, depth + 1); };
        const auto build_right = [&] {
            build(region + 1, region + 2 * left_count, mid, end, depth + 1);
        };
        if (n > m_parallel_threshold) {
            hikari::parallel_invoke(build_left, build_right);
        } else {
            build_left();
            build_right();
        }
    }

  private:
    void make_leaf(BvhNode& node, uint32_t begin, uint32_t n) const {
        node.index = begin;
        node.triangle_count = static_cast<uint16_t>(n);
    }

    RangeBounds range_bounds(uint32_t begin, uint32_t end) const {
        const auto accumulate = [this](uint32_t b, uint32_t e, RangeBounds acc) {
            for (uint32_t i = b; i < e; ++i) {
                acc.bounds.extend(m_refs[i].bounds);
                acc.centroids.extend(m_refs[i].centroid());
            }
            return acc;
        };
        if (end - begin <= m_parallel_threshold) return accumulate(begin, end, {});
        // min and max are exact in any order, so the reduction is deterministic.
        return hikari::parallel_reduce(
            tbb::blocked_range<uint32_t>(begin, end, 1024), RangeBounds{},
            [&](const tbb::blocked_range<uint32_t>& r, RangeBounds acc) {
                return accumulate(r.begin(), r.end(), acc);
            },
            [](RangeBounds a, const RangeBounds& b) {
                a.extend(b);
                return a;
            });
    }

    Bins fill_bins(uint32_t begin, uint32_t end, const BinMapping& mapping) const {
        const auto accumulate = [&](uint32_t b, uint32_t e, Bins& bins) {
            for (uint32_t i = b; i < e; ++i) {
                const PrimRef& ref = m_refs[i];
                const Vec3 c = ref.centroid();
                for (int a = 0; a < 3; ++a) {
                    Bin& bin = bins.axis[a][mapping(c, a)];
                    bin.bounds.extend(ref.bounds);
                    ++bin.count;
                }
            }
        };
        if (end - begin <= m_parallel_threshold) {
            Bins bins;
            accumulate(begin, end, bins);
            return bins;
        }
        // Counts add exactly and bounds merge exactly, so any split of the work gives the same
        // bins.
        return hikari::parallel_reduce(
            tbb::blocked_range<uint32_t>(begin, end, 4096), Bins{},
            [&](const tbb::blocked_range<uint32_t>& r, Bins bins) {
                accumulate(r.begin(), r.end(), bins);
                return bins;
            },
            [this](Bins a, const Bins& b) {
                a.merge(b, m_bin_count);
                return a;
            });
    }

    /// Wald 2007, Sec 3.3: the SAH cost C = C_trav + (A_L N_L + A_R N_R) / A in units of one
    /// triangle test, evaluated at every plane between bins on all three axes.
    Split find_split(uint32_t begin, uint32_t end, const RangeBounds& range) const {
        const float node_area = range.bounds.half_area();
        if (!(node_area > 0.0f) || !std::isfinite(node_area)) return {};
        const BinMapping mapping(range.centroids, m_bin_count);
        const Bins bins = fill_bins(begin, end, mapping);

        Split best;
        for (int a = 0; a < 3; ++a) {
            if (mapping.scale[a] == 0.0f) continue;  // all centroids in one plane
            const auto& axis_bins = bins.axis[a];
            // Sweep from the right: area and count of everything at or right of plane i.
            std::array<float, k_max_bins> right_area{};
            std::array<uint32_t, k_max_bins> right_count{};
            Aabb right;
            uint32_t count = 0;
            for (uint32_t i = m_bin_count - 1; i > 0; --i) {
                right.extend(axis_bins[i].bounds);
                count += axis_bins[i].count;
                right_area[i] = right.half_area();
                right_count[i] = count;
            }
            // Sweep from the left, pricing each plane.
            Aabb left;
            count = 0;
            for (uint32_t i = 1; i < m_bin_count; ++i) {
                left.extend(axis_bins[i - 1].bounds);
                count += axis_bins[i - 1].count;
                if (count == 0 || right_count[i] == 0) continue;
                const float cost =
                    left.half_area() * float(count) + right_area[i] * float(right_count[i]);
                if (cost < best.cost) best = {cost, a, i};
            }
        }
        if (best.axis >= 0) best.cost = m_traversal_cost + best.cost / node_area;
        return best;
    }

    uint32_t partition(uint32_t begin, uint32_t end, const RangeBounds& range,
                       const Split& split) const {
        const BinMapping mapping(range.centroids, m_bin_count);
        const auto first = m_refs.begin();
        const auto mid = std::partition(first + begin, first + end, [&](const PrimRef& ref) {
            return mapping(ref.centroid(), split.axis) < split.bin;
        });
        return static_cast<uint32_t>(mid - first);
    }

    /// The fallback when the SAH finds no split: halves the range at the median centroid,
    /// ties broken by id so the result is deterministic.
    uint32_t median_split(uint32_t begin, uint32_t end, int axis) const {
        const auto first = m_refs.begin();
        const uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(first + begin, first + mid, first + end,
                         [&](const PrimRef& a, const PrimRef& b) {
                             const float ca = a.centroid()[axis];
                             const float cb = b.centroid()[axis];
                             return ca < cb || (ca == cb && a.id < b.id);
                         });
        return mid;
    }

    std::span<PrimRef> m_refs;
    std::span<BvhNode> m_slots;
    uint32_t m_bin_count = 16;
    uint32_t m_min_leaf = 1;
    uint32_t m_max_leaf = 8;
    float m_traversal_cost = 2.0f;
    uint32_t m_parallel_threshold = 4096;
};

/// A triangle can be hit only when its indices are in range, its vertices finite and its
/// area non-zero.
bool is_usable(std::span<const Vec3> positions, const std::array<uint32_t, 3>& tri) {
    const size_t n = positions.size();
    if (tri[0] >= n || tri[1] >= n || tri[2] >= n) return false;
    const Vec3 p0 = positions[tri[0]], p1 = positions[tri[1]], p2 = positions[tri[2]];
    if (!is_finite(p0) || !is_finite(p1) || !is_finite(p2)) return false;
    return !(cross(p1 - p0, p2 - p0) == Vec3(0.0f));
}

/// Copies the slot tree into depth-first order (children adjacent, first child's subtree
/// first), dropping the unused slots.
std::vector<BvhNode> compact(std::span<const BvhNode> slots) {
    std::vector<BvhNode> nodes;
    nodes.reserve(slots.size());
    nodes.push_back(slots[0]);
    std::vector<std::pair<uint32_t, uint32_t>> todo{{0u, 0u}};  // (slot, node)
    while (!todo.empty()) {
        const auto [slot, index] = todo.back();
        todo.pop_back();
        const BvhNode& node = slots[slot];
        nodes[index].bounds = {canonical_zero(node.bounds.min), canonical_zero(node.bounds.max)};
        if (node.is_leaf()) continue;
        const auto first = static_cast<uint32_t>(nodes.size());
        nodes[index].index = first;
        nodes.push_back(slots[node.index]);
        nodes.push_back(slots[node.index + 1]);
        todo.emplace_back(node.index + 1, first + 1);
        todo.emplace_back(node.index, first);
    }
    nodes.shrink_to_fit();
    return nodes;
}

}  // namespace

Bvh build_bvh(std::span<const Vec3> positions, std::span<const std::array<uint32_t, 3>> indices,
              const BvhBuildSettings& settings) {
    if (indices.size() >= std::numeric_limits<uint32_t>::max() / 2) {
        throw std::length_error("build_bvh: too many triangles for 32-bit node indices");
    }
    const auto input_count = static_cast<uint32_t>(indices.size());

    // Per-triangle bounds (their centres are the centroids, as in Wald 2007).
    std::vector<Aabb> bounds(input_count);
    std::vector<uint8_t> usable(input_count);
    hikari::parallel_for(tbb::blocked_range<uint32_t>(0, input_count, 4096), [&](const auto& r) {
        for (uint32_t i = r.begin(); i < r.end(); ++i) {
            usable[i] = is_usable(positions, indices[i]);
            if (!usable[i]) continue;
            for (uint32_t k : indices[i]) bounds[i].extend(positions[k]);
        }
    });
    std::vector<PrimRef> refs;
    refs.reserve(input_count);
    for (uint32_t i = 0; i < input_count; ++i) {
        if (usable[i]) refs.push_back({bounds[i], i});
    }
    if (refs.empty()) return {};

    // Build into fixed slots, then lay the tree out depth-first.
    const auto count = static_cast<uint32_t>(refs.size());
    std::vector<BvhNode> slots(2 * size_t(count) - 1);
    BinnedSahBuilder(settings, refs, slots).build(0, 1, 0, count, 0);
    std::vector<uint32_t> ids(count);
    for (uint32_t i = 0; i < count; ++i) ids[i] = refs[i].id;

    Bvh bvh;
    bvh.nodes = compact(slots);
    bvh.triangles.resize(count);
    bvh.triangle_ids = std::move(ids);
    for (uint32_t i = 0; i < count; ++i) {
        const auto& tri = indices[bvh.triangle_ids[i]];
        bvh.triangles[i] = {positions[tri[0]], positions[tri[1]], positions[tri[2]]};
    }
    return bvh;
}

}  // namespace hikari
