#include "hikari/bvh/wide_bvh_builder.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>
#include <tbb/blocked_range.h>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "hikari/core/cancel.h"
#include "hikari/core/memory_budget.h"
#include "hikari/core/parallel.h"

namespace hikari {
namespace {

// ---- Four-lane float vectors ----------------------------------------------------------------
// GCC/Clang vector extensions: one SSE register on x86, portable elsewhere. Lanes 0-2 are x, y,
// z; lane 3 rides along unused. Every operation is an exact IEEE min, max, add, sub or mul.

typedef float F4 __attribute__((vector_size(16)));
typedef int32_t I4 __attribute__((vector_size(16)));

inline F4 splat(float s) { return F4{s, s, s, s}; }
inline F4 vmin(F4 a, F4 b) { return a < b ? a : b; }
inline F4 vmax(F4 a, F4 b) { return a > b ? a : b; }
inline F4 to_f4(Vec3 p) { return F4{p.x, p.y, p.z, 0.0f}; }
/// Lane i of a vector in memory, read as a scalar (no round trip through a register).
inline float lane(const F4& v, int i) {
    float x;
    std::memcpy(&x, reinterpret_cast<const char*>(&v) + sizeof(float) * i, sizeof(float));
    return x;
}

/// An axis-aligned box in two vectors; empty() is min +inf, max -inf, as for Aabb.
struct Box4 {
    F4 lower, upper;

    static Box4 empty() { return {splat(k_infinity), splat(-k_infinity)}; }
    void extend(F4 lo, F4 hi) {
        lower = vmin(lower, lo);
        upper = vmax(upper, hi);
    }
    void extend(const Box4& b) { extend(b.lower, b.upper); }
    /// Half the surface area; meaningless for an empty box (callers skip those).
    float half_area() const {
        const F4 e = upper - lower;
        return e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
    }
    /// As an Aabb, -0 mapped to +0 so bounds are bitwise identical whatever order min/max ran in.
    Aabb to_aabb() const {
        const F4 lo = lower + splat(0.0f), hi = upper + splat(0.0f);
        return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
    }
};

// ---- Primitive references -------------------------------------------------------------------

/// A triangle as the builder moves it around: its box with its input index in the spare lane,
/// 32 bytes, so every pass over a range streams through memory (Embree's PrimRef; Wald 2007).
/// The index rides as the bits of a normal float (exponent bits forced on): the lane goes through
/// the centroid arithmetic too, and arithmetic on denormals costs a microcode assist each.
struct alignas(32) PrimRef {
    F4 lower;  ///< xyz: min corner; lane 3: the input index, encoded
    F4 upper;  ///< xyz: max corner; lane 3: 0

    static constexpr uint32_t k_id_mask = WideBvhRef::k_first_mask;
    static constexpr uint32_t k_id_tag = 0x40000000u;  ///< makes the bits a float in [2, 2^17)

    uint32_t id() const { return std::bit_cast<uint32_t>(lower[3]) & k_id_mask; }
    void set_id(uint32_t id) { lower[3] = std::bit_cast<float>(id | k_id_tag); }
    /// Twice the centroid (min + max): the halving cancels out of the binning.
    F4 centroid2() const { return lower + upper; }
};
static_assert(sizeof(PrimRef) == 32);

/// Marks a triangle that can never be hit, before such triangles are dropped; no input index
/// is this large (build_wide_bvh takes fewer than k_max_triangles).
constexpr uint32_t k_unusable = PrimRef::k_id_mask;

/// A triangle can be hit only when its indices are in range, its vertices finite and its area
/// non-zero; then `ref` gets its box.
bool make_prim_ref(std::span<const Vec3> positions, const std::array<uint32_t, 3>& tri, uint32_t id,
                   PrimRef& ref) {
    const size_t n = positions.size();
    ref.lower = splat(0.0f);
    ref.upper = splat(0.0f);
    ref.set_id(k_unusable);
    if (tri[0] >= n || tri[1] >= n || tri[2] >= n) return false;
    const Vec3 p0 = positions[tri[0]], p1 = positions[tri[1]], p2 = positions[tri[2]];
    if (!is_finite(p0) || !is_finite(p1) || !is_finite(p2)) return false;
    if (cross(p1 - p0, p2 - p0) == Vec3(0.0f)) return false;
    const F4 a = to_f4(p0), b = to_f4(p1), c = to_f4(p2);
    ref.lower = vmin(vmin(a, b), c);
    ref.set_id(id);
    ref.upper = vmax(vmax(a, b), c);
    return true;
}

/// A box can be hit only when it is finite and not empty; then `ref` gets it.
bool make_prim_ref(const Aabb& box, uint32_t id, PrimRef& ref) {
    ref.lower = splat(0.0f);
    ref.upper = splat(0.0f);
    ref.set_id(k_unusable);
    if (!is_finite(box.min) || !is_finite(box.max) || box.empty()) return false;
    ref.lower = to_f4(box.min);
    ref.set_id(id);
    ref.upper = to_f4(box.max);
    return true;
}

// ---- Memory ---------------------------------------------------------------------------------
// First touches of fresh memory are the dearest part of a build on virtual machines (a page
// fault each 4 KiB, each a trap to the hypervisor); big buffers ask for 2 MiB pages, as Embree's
// allocator does, and are populated in one call where the kernel allows.

constexpr size_t k_huge_page = HugePageAllocator<char>::k_huge_page_bytes;

/// `v` resized to n value-initialized elements, big ones on 2 MiB pages.
template <class T, class Allocator>
void resize_on_huge_pages(std::vector<T, Allocator>& v, size_t n) {
    v.reserve(n);
    prepare_huge_pages(v.data(), n * sizeof(T), true);
    v.resize(n);
}

/// Uninitialized scratch memory: of 2 MiB or more, 2 MiB aligned on 2 MiB pages; smaller, on
/// whole 4 KiB pages (a 2 MiB page for a small mesh, zeroed by the kernel, would cost more than
/// the build). On Linux a mapping of its own, so no 4 KiB page left over from earlier use keeps
/// the kernel from backing it with 2 MiB pages.
class ScratchBlock {
  public:
    ScratchBlock(size_t bytes, bool populate) {
        constexpr size_t k_small_page = 4096;
        const bool huge = bytes >= k_huge_page;
        const size_t page = huge ? k_huge_page : k_small_page;
        m_size = (std::max<size_t>(bytes, 1) + page - 1) / page * page;
#if defined(__linux__)
        m_mapped_size = m_size + (huge ? k_huge_page : 0);
        m_mapped = mmap(nullptr, m_mapped_size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
                        -1, 0);
        if (m_mapped == MAP_FAILED) throw std::bad_alloc();
        const size_t misalignment = reinterpret_cast<uintptr_t>(m_mapped) % page;
        m_data = static_cast<char*>(m_mapped) + (page - misalignment) % page;
#else
        m_data = std::aligned_alloc(page, m_size);
        if (m_data == nullptr) throw std::bad_alloc();
#endif
        if (huge)
            prepare_huge_pages(m_data, m_size, populate);
        else if (populate)
            populate_pages(m_data, m_size);
    }
    ~ScratchBlock() {
#if defined(__linux__)
        munmap(m_mapped, m_mapped_size);
#else
        std::free(m_data);
#endif
    }
    ScratchBlock(const ScratchBlock&) = delete;
    ScratchBlock& operator=(const ScratchBlock&) = delete;

    void* data() const { return m_data; }
    size_t size() const { return m_size; }

  private:
    void* m_mapped = nullptr;
    size_t m_mapped_size = 0;
    void* m_data = nullptr;
    size_t m_size = 0;
};

/// Storage for the nodes of all subtrees while they are built, handed out in chunks from
/// scratch blocks. Only storage: which task gets which chunk depends on the threads, so
/// assemble() copies the nodes into the tree's own order.
class NodeArena {
  public:
    static constexpr uint32_t k_chunk = 32;  ///< nodes per chunk

    explicit NodeArena(size_t chunks_per_block)
        : m_block_chunks(std::max<size_t>(chunks_per_block, 8)) {}

    WideBvhNode* chunk() {
        const std::lock_guard lock(m_mutex);
        if (m_blocks.empty() || m_used == m_block_chunks) {
            m_blocks.push_back(std::make_unique<ScratchBlock>(
                m_block_chunks * k_chunk * sizeof(WideBvhNode), false));
            m_used = 0;
        }
        return static_cast<WideBvhNode*>(m_blocks.back()->data()) + k_chunk * m_used++;
    }

  private:
    size_t m_block_chunks;
    size_t m_used = 0;  ///< chunks handed out from the last block
    std::vector<std::unique_ptr<ScratchBlock>> m_blocks;
    std::mutex m_mutex;
};

// ---- Binned SAH (Wald 2007) -----------------------------------------------------------------

constexpr uint32_t k_max_bins = 32;

/// ceil(log2(n)) for n >= 1: the depth of a tree that halves n items down to single ones.
uint32_t ceil_log2(uint32_t n) { return static_cast<uint32_t>(std::bit_width(n - 1)); }

/// A range of PrimRefs still to be built, with what the SAH needs about it.
struct BuildRange {
    uint32_t begin = 0, end = 0;
    uint32_t depth = 0;  ///< depth in the binary tree of splits, for the depth limit
    Box4 bounds;         ///< box around the triangles
    Box4 centroids;      ///< box around their doubled centroids

    uint32_t size() const { return end - begin; }
};

/// Wald 2007, Sec 3.2: centroid c falls into bin floor(k1 (c - c_min)) with
/// k1 = K (1 - eps) / (c_max - c_min), clamped against rounding at c_max. The clamp comes before
/// the conversion, so NaN (from overflowing coordinates) lands in the last bin.
struct BinMapping {
    F4 origin;
    F4 scale;
    F4 last;  ///< K - 1

    BinMapping(const Box4& centroids, uint32_t bins) : origin(centroids.lower) {
        const F4 extent = centroids.upper - centroids.lower;
        scale = splat(0.0f);
        for (int a = 0; a < 3; ++a) {
            const float k1 = float(bins) * (1.0f - 1e-6f) / extent[a];
            scale[a] = extent[a] > 0.0f && std::isfinite(k1) ? k1 : 0.0f;  // 0: a flat axis
        }
        origin[3] = 0.0f;
        last = splat(float(bins - 1));
    }
    /// The bins of doubled centroid c2 along x, y and z. (c2 >= origin, so the scaled offset is
    /// never negative.)
    I4 operator()(F4 c2) const {
        return __builtin_convertvector(vmin((c2 - origin) * scale, last), I4);
    }
    /// True when the ref's bin along `axis` is below `bin`: the same arithmetic on one lane.
    bool below(const PrimRef& ref, int axis, float bin) const {
        return (lane(ref.lower, axis) + lane(ref.upper, axis) - lane(origin, axis)) *
                   lane(scale, axis) <
               bin;
    }
};

/// SAH bins along all three axes: bin i of axis a has box[a][i] and count[i][a] (counts by
/// bin, so the sweep adds all three axes at once).
struct Bins {
    uint32_t bin_count = 0;
    std::array<std::array<Box4, k_max_bins>, 3> box;
    std::array<I4, k_max_bins> count;

    explicit Bins(uint32_t bins) : bin_count(bins) {
        for (int a = 0; a < 3; ++a) std::fill_n(box[a].begin(), bin_count, Box4::empty());
        std::fill_n(count.begin(), bin_count, I4{0, 0, 0, 0});
    }
    void add(const PrimRef& ref, const BinMapping& mapping) {
        const I4 bin = mapping(ref.centroid2());
        for (int a = 0; a < 3; ++a) {
            box[a][bin[a]].extend(ref.lower, ref.upper);
            ++count[bin[a]][a];
        }
    }
    /// Bins refs [begin, end). Long runs alternate between two bin sets: neighbours often fall
    /// into the same bin, and would otherwise each wait for the other's store.
    void add(const PrimRef* refs, uint32_t begin, uint32_t end, const BinMapping& mapping) {
        uint32_t i = begin;
        if (end - begin >= 64) {
            Bins odd(bin_count);
            for (; i + 1 < end; i += 2) {
                add(refs[i], mapping);
                odd.add(refs[i + 1], mapping);
            }
            merge(odd);
        }
        for (; i < end; ++i) add(refs[i], mapping);
    }
    void merge(const Bins& b) {
        for (uint32_t i = 0; i < bin_count; ++i) {
            for (int a = 0; a < 3; ++a) box[a][i].extend(b.box[a][i]);
            count[i] += b.count[i];
        }
    }
};

/// Half the surface areas of three boxes at once, lane a for box a (the same arithmetic as
/// Box4::half_area, lane by lane).
inline F4 half_areas(const Box4& b0, const Box4& b1, const Box4& b2) {
    const F4 e0 = b0.upper - b0.lower, e1 = b1.upper - b1.lower, e2 = b2.upper - b2.lower;
    const F4 t0 = __builtin_shufflevector(e0, e1, 0, 4, 1, 5);  // x0 x1 y0 y1
    const F4 t1 = __builtin_shufflevector(e0, e1, 2, 6, 2, 6);  // z0 z1 z0 z1
    const F4 ex = __builtin_shufflevector(t0, e2, 0, 1, 4, 4);
    const F4 ey = __builtin_shufflevector(t0, e2, 2, 3, 5, 5);
    const F4 ez = __builtin_shufflevector(t1, e2, 0, 1, 6, 6);
    return ex * ey + ey * ez + ez * ex;
}

/// The best SAH split found: triangles in bins [0, bin) of `axis` go left.
struct Split {
    float cost = std::numeric_limits<float>::infinity();
    int axis = -1;
    uint32_t bin = 0;
};

/// A range split in two, with the bounds of each side gathered on the way.
struct Halves {
    uint32_t mid = 0;
    Box4 bounds[2] = {Box4::empty(), Box4::empty()};
    Box4 centroids[2] = {Box4::empty(), Box4::empty()};

    void add(int side, const PrimRef& ref) {
        bounds[side].extend(ref.lower, ref.upper);
        const F4 c = ref.centroid2();
        centroids[side].extend(c, c);
    }
    void merge(const Halves& h) {
        for (int s = 0; s < 2; ++s) {
            bounds[s].extend(h.bounds[s]);
            centroids[s].extend(h.centroids[s]);
        }
    }
};

// ---- Finishing a parallel partition -------------------------------------------------------
// After the blocks of a range are partitioned in place, in parallel, each block holds its
// left-goers then its right-goers; the right-goers left of the final midpoint must exchange
// places with the left-goers right of it. Planned serially from the block midpoints alone, so
// the exchanges, and the result, do not depend on the threads.

/// A run of consecutive PrimRefs: [first, first + count).
struct Run {
    uint32_t first, count;
};

/// The runs on the wrong side of a partition's final midpoint, each list in order.
struct MisplacedRuns {
    std::vector<Run> right;  ///< right-goers left of the midpoint
    std::vector<Run> left;   ///< left-goers right of it
};

/// The misplaced runs of [begin, end) with the final midpoint `mid`, once its blocks of `block`
/// refs are partitioned in place (block b split at parts[b].mid).
MisplacedRuns misplaced_runs(const std::vector<Halves>& parts, uint32_t begin, uint32_t end,
                             uint32_t mid, uint32_t block) {
    MisplacedRuns runs;
    for (uint32_t b = 0; b < parts.size(); ++b) {
        const uint32_t first = begin + b * block, last = std::min(end, first + block);
        const uint32_t split = parts[b].mid;
        // The block's right part [split, last) inside [begin, mid), its left part
        // [first, split) inside [mid, end).
        if (std::min(last, mid) > split) runs.right.push_back({split, std::min(last, mid) - split});
        if (split > std::max(first, mid))
            runs.left.push_back({std::max(first, mid), split - std::max(first, mid)});
    }
    return runs;
}

/// An exchange of [a, a + count) with [b, b + count).
struct RunSwap {
    uint32_t a, b, count;
};

/// Pairs the misplaced runs, in order, into exchanges of equal length, at most `max_count` each
/// (the two sides hold as many refs).
std::vector<RunSwap> pair_runs(const MisplacedRuns& runs, uint32_t max_count) {
    std::vector<RunSwap> swaps;
    size_t i = 0, j = 0;
    uint32_t used_i = 0, used_j = 0;
    while (i < runs.right.size() && j < runs.left.size()) {
        const Run& r = runs.right[i];
        const Run& l = runs.left[j];
        const uint32_t n = std::min({r.count - used_i, l.count - used_j, max_count});
        swaps.push_back({r.first + used_i, l.first + used_j, n});
        used_i += n;
        used_j += n;
        if (used_i == r.count) ++i, used_i = 0;
        if (used_j == l.count) ++j, used_j = 0;
    }
    return swaps;
}

/// The nodes one task built: a subtree whose big subtrees were built by tasks of their own.
/// Node indices are local until assembly gives the subtree its place in WideBvh::nodes, so the
/// tree does not depend on which thread built what.
struct Subtree {
    struct Link {
        uint32_t node = 0;  ///< local node whose child slot `slot` is `child`'s root
        uint32_t slot = 0;
        std::unique_ptr<Subtree> child;
    };
    std::vector<WideBvhNode*> chunks;  ///< node i is chunks[i / k_chunk][i % k_chunk]
    uint32_t size = 0;                 ///< nodes held; node 0 is the subtree's root
    std::vector<Link> links;
    uint32_t offset = 0;  ///< index of node 0 in WideBvh::nodes

    WideBvhNode& node(uint32_t i) const {
        return chunks[i / NodeArena::k_chunk][i % NodeArena::k_chunk];
    }
    /// Appends `n`; returns its local index.
    uint32_t push(NodeArena& arena, const WideBvhNode& n) {
        if (size % NodeArena::k_chunk == 0) chunks.push_back(arena.chunk());
        node(size) = n;
        return size++;
    }
};

/// Builds the wide tree straight from the PrimRefs: each node is a binned-SAH split (Wald 2007)
/// whose largest-area child is split again until there are eight children (Wald et al. 2008,
/// Sec 3; Embree's BVH8 builder, Wald et al. 2014), leaves written straight into their SoA
/// blocks. Every decision (split plane, serial or parallel partition, task or not) depends only
/// on the range, never on the threads, so the tree is the same for any thread count.
class WideSahBuilder {
  public:
    /// Over triangles (`indices` into `positions`, leaves written into out.triangle_data) or,
    /// with both spans empty, over boxes (leaves hold primitive ids only).
    WideSahBuilder(const BvhBuildSettings& settings, PrimRef* refs, std::span<const Vec3> positions,
                   std::span<const std::array<uint32_t, 3>> indices, NodeArena& arena, WideBvh& out)
        : m_refs(refs),
          m_arena(arena),
          m_positions(positions),
          m_indices(indices),
          m_triangle_data(out.triangle_data.data()),
          m_ids(out.triangle_ids.data()) {
        m_bin_count = std::clamp(settings.bin_count, 2u, k_max_bins);
        m_max_leaf = std::clamp(settings.max_leaf_size, 1u, WideBvhRef::k_max_leaf_size);
        m_task_threshold = std::max(settings.parallel_threshold, 2u);
        m_data_parallel_threshold = 4 * m_task_threshold;
    }

    /// Builds the tree over `range` into `out` (its node 0 when the root is inner); returns the
    /// root reference.
    uint32_t build(const BuildRange& range, Subtree& out) {
        throw_if_cancelled();  // SIGINT / SIGTERM: once per node, a relaxed load
        const Decision decision = decide(range);
        if (decision.leaf) return make_leaf(range);

        /* open children: split the largest-area inner child until eight (Wald et al. 2008) */
        std::array<Child, k_wide_bvh_width> children;
        uint32_t count = 2;
        split(range, decision.split, children[0], children[1]);
        while (count < k_wide_bvh_width) {
            int best = -1;
            float best_area = -1.0f;
            for (uint32_t i = 0; i < count; ++i) {
                if (!children[i].leaf && children[i].area > best_area) {
                    best = static_cast<int>(i);
                    best_area = children[i].area;
                }
            }
            if (best < 0) break;
            const Decision d = decide(children[best].range);
            if (d.leaf) {
                children[best].leaf = true;
                continue;
            }
            const BuildRange opened = children[best].range;
            std::move_backward(children.begin() + best + 1, children.begin() + count,
                               children.begin() + count + 1);
            split(opened, d.split, children[best], children[best + 1]);
            ++count;
        }
        return write_node(children, count, out);
    }

  private:
    struct Decision {
        bool leaf = true;
        Split split;
    };
    struct Child {
        BuildRange range;
        float area = 0.0f;
        bool leaf = false;  ///< decided to be a leaf; otherwise not decided yet
    };

    /// Writes the node over `children`; builds the small inner children here and the big ones
    /// (more than m_task_threshold triangles) as parallel tasks with subtrees of their own.
    uint32_t write_node(const std::array<Child, k_wide_bvh_width>& children, uint32_t count,
                        Subtree& out) {
        const uint32_t index = out.size;
        WideBvhNode node;
        for (int a = 0; a < 3; ++a) {
            node.bounds[2 * a].fill(k_infinity);
            node.bounds[2 * a + 1].fill(-k_infinity);
        }
        node.child.fill(WideBvhRef::k_empty);
        std::array<Subtree*, k_wide_bvh_width> tasks{};
        bool any_task = false;
        for (uint32_t i = 0; i < count; ++i) {
            const Aabb box = children[i].range.bounds.to_aabb();
            for (int a = 0; a < 3; ++a) {
                node.bounds[2 * a][i] = box.min[a];
                node.bounds[2 * a + 1][i] = box.max[a];
            }
            if (children[i].leaf) {
                node.child[i] = make_leaf(children[i].range);
            } else if (children[i].range.size() > m_task_threshold) {
                out.links.push_back({index, i, std::make_unique<Subtree>()});
                tasks[i] = out.links.back().child.get();
                any_task = true;
            }
        }
        out.push(m_arena, node);

        // The serial children go into `out`, which no task touches.
        const auto build_serial = [&] {
            for (uint32_t i = 0; i < count; ++i) {
                if (children[i].leaf || tasks[i] != nullptr) continue;
                const uint32_t ref = build(children[i].range, out);
                out.node(index).child[i] = ref;
            }
        };
        if (!any_task) {
            build_serial();
        } else {
            hikari::parallel_for(0u, count + 1, [&](uint32_t i) {
                if (i == count) return build_serial();
                if (tasks[i] == nullptr) return;
                build(children[i].range, *tasks[i]);
            });
        }
        return WideBvhRef::inner(index);
    }

    /// Leaf or split. A range that fits one leaf becomes one: the 8-wide leaf test costs about
    /// the same for 1 to 8 triangles, so a split, which adds a node visit, cannot pay (the SAH
    /// with leaf costs counted in SIMD blocks, as in Embree's builders; Wald et al. 2014). A
    /// larger range splits at the SAH's best plane, or at the median near the depth limit.
    Decision decide(const BuildRange& range) const {
        const uint32_t n = range.size();
        if (n <= m_max_leaf) return {};
        // Only balanced halving from here on fits the depth limit (and the traversal stack).
        const bool must_halve = range.depth + ceil_log2(n) + 1 >= k_bvh_max_depth;
        return {false, must_halve ? Split{} : find_split(range)};
    }

    /// Wald 2007, Sec 3.3: the plane between bins, on any axis, with the least SAH cost
    /// A_L N_L + A_R N_R (C_trav and the division by A do not change which plane wins).
    Split find_split(const BuildRange& range) const {
        const float node_area = range.bounds.half_area();
        if (!(node_area > 0.0f) || !std::isfinite(node_area)) return {};
        const uint32_t bin_count = bins_for(range.size());
        const BinMapping mapping(range.centroids, bin_count);
        if (mapping.scale[0] == 0.0f && mapping.scale[1] == 0.0f && mapping.scale[2] == 0.0f)
            return {};  // all centroids coincide
        Bins bins(bin_count);
        fill_bins(range, mapping, bins);

        // Sweep from the right: areas and counts of everything at or right of plane i, for the
        // three axes at once (lane a: axis a).
        std::array<F4, k_max_bins> right_area;
        std::array<I4, k_max_bins> right_count;
        std::array<Box4, 3> side = {Box4::empty(), Box4::empty(), Box4::empty()};
        I4 count = {0, 0, 0, 0};
        for (uint32_t i = bin_count - 1; i > 0; --i) {
            for (int a = 0; a < 3; ++a) side[a].extend(bins.box[a][i]);
            count += bins.count[i];
            right_area[i] = half_areas(side[0], side[1], side[2]);
            right_count[i] = count;
        }
        // Sweep from the left, pricing each plane; the first cheapest plane wins per axis.
        side = {Box4::empty(), Box4::empty(), Box4::empty()};
        count = I4{0, 0, 0, 0};
        F4 best_cost = splat(k_infinity);
        I4 best_bin = {0, 0, 0, 0};
        const I4 zero = {0, 0, 0, 0};
        for (uint32_t i = 1; i < bin_count; ++i) {
            for (int a = 0; a < 3; ++a) side[a].extend(bins.box[a][i - 1]);
            count += bins.count[i - 1];
            const F4 cost =
                half_areas(side[0], side[1], side[2]) * __builtin_convertvector(count, F4) +
                right_area[i] * __builtin_convertvector(right_count[i], F4);
            const I4 better = (count != zero) & (right_count[i] != zero) & (cost < best_cost);
            best_cost = better ? cost : best_cost;
            best_bin = better ? I4{int32_t(i), int32_t(i), int32_t(i), int32_t(i)} : best_bin;
        }
        Split best;
        for (int a = 0; a < 3; ++a) {
            if (mapping.scale[a] == 0.0f) continue;  // all centroids in one plane
            if (best_cost[a] < best.cost)
                best = {best_cost[a], a, static_cast<uint32_t>(best_bin[a])};
        }
        return best;
    }

    /// Wald 2007, Sec 3.4: few triangles need few bins; the bin count follows the range size,
    /// so binning and partition agree on it.
    uint32_t bins_for(uint32_t n) const { return std::clamp(n, 4u, m_bin_count); }

    void fill_bins(const BuildRange& range, const BinMapping& mapping, Bins& bins) const {
        if (range.size() <= m_data_parallel_threshold) {
            bins.add(m_refs, range.begin, range.end, mapping);
            return;
        }
        // Counts add exactly and boxes merge exactly, so any split of the work gives the same
        // bins.
        bins = hikari::parallel_reduce(
            tbb::blocked_range<uint32_t>(range.begin, range.end, 4096), bins,
            [&](const tbb::blocked_range<uint32_t>& r, Bins partial) {
                partial.add(m_refs, r.begin(), r.end(), mapping);
                return partial;
            },
            [](Bins a, const Bins& b) {
                a.merge(b);
                return a;
            });
    }

    /// Splits `range` at `best` (or at the median when the SAH found nothing that separates).
    void split(const BuildRange& range, const Split& best, Child& left, Child& right) {
        Halves h;
        if (best.axis >= 0) {
            const BinMapping mapping(range.centroids, bins_for(range.size()));
            const auto goes_left = [&mapping, axis = best.axis,
                                    bin = float(best.bin)](const PrimRef& ref) {
                return mapping.below(ref, axis, bin);
            };
            h = range.size() > m_data_parallel_threshold
                    ? partition_parallel(range.begin, range.end, goes_left)
                    : partition(range.begin, range.end, goes_left);
        }
        if (best.axis < 0 || h.mid == range.begin || h.mid == range.end) h = median_split(range);
        left = {{range.begin, h.mid, range.depth + 1, h.bounds[0], h.centroids[0]},
                h.bounds[0].half_area()};
        right = {{h.mid, range.end, range.depth + 1, h.bounds[1], h.centroids[1]},
                 h.bounds[1].half_area()};
    }

    /// In-place two-pointer partition (Hoare), gathering the bounds of both sides (in locals,
    /// so that they stay in registers).
    template <class GoesLeft>
    Halves partition(uint32_t begin, uint32_t end, const GoesLeft& goes_left) const {
        Box4 bounds[2] = {Box4::empty(), Box4::empty()};
        Box4 centroids[2] = {Box4::empty(), Box4::empty()};
        const auto add = [&](int side, const PrimRef& ref) {
            bounds[side].extend(ref.lower, ref.upper);
            const F4 c = ref.centroid2();
            centroids[side].extend(c, c);
        };
        PrimRef* l = m_refs + begin;
        PrimRef* r = m_refs + end;
        for (;;) {
            for (; l < r && goes_left(*l); ++l) add(0, *l);
            for (; l < r && !goes_left(r[-1]); --r) add(1, r[-1]);
            if (l == r) break;
            --r;
            std::swap(*l, *r);
            add(0, *l++);
            add(1, *r);
        }
        Halves h;
        h.mid = static_cast<uint32_t>(l - m_refs);
        for (int side = 0; side < 2; ++side) {
            h.bounds[side] = bounds[side];
            h.centroids[side] = centroids[side];
        }
        return h;
    }

    /// A deterministic parallel partition: fixed blocks are partitioned in place in parallel,
    /// then the right-going refs left of the final midpoint swap, in order, with the left-going
    /// refs right of it. The result depends only on the input, not on the threads.
    template <class GoesLeft>
    Halves partition_parallel(uint32_t begin, uint32_t end, const GoesLeft& goes_left) const {
        constexpr uint32_t k_block = 8192;
        const uint32_t blocks = (end - begin + k_block - 1) / k_block;
        /* partition each block in place, and merge what they found */
        std::vector<Halves> parts(blocks);
        hikari::parallel_for(0u, blocks, [&](uint32_t b) {
            parts[b] =
                partition(begin + b * k_block, std::min(end, begin + (b + 1) * k_block), goes_left);
        });
        Halves h;
        uint32_t mid = begin;
        for (const Halves& p : parts) {
            h.merge(p);
            mid += p.mid - (begin + uint32_t(&p - parts.data()) * k_block);
        }
        h.mid = mid;

        /* exchange the misplaced runs */
        const std::vector<RunSwap> swaps =
            pair_runs(misplaced_runs(parts, begin, end, mid, k_block), k_block);
        hikari::parallel_for(size_t(0), swaps.size(), [&](size_t s) {
            std::swap_ranges(m_refs + swaps[s].a, m_refs + swaps[s].a + swaps[s].count,
                             m_refs + swaps[s].b);
        });
        return h;
    }

    /// The fallback when the SAH finds no split: halves the range at the median centroid along
    /// the widest centroid axis, ties broken by id so the result is deterministic.
    Halves median_split(const BuildRange& range) const {
        const F4 extent = range.centroids.upper - range.centroids.lower;
        const int axis =
            extent[0] >= extent[1] && extent[0] >= extent[2] ? 0 : (extent[1] >= extent[2] ? 1 : 2);
        const uint32_t mid = range.begin + range.size() / 2;
        std::nth_element(m_refs + range.begin, m_refs + mid, m_refs + range.end,
                         [axis](const PrimRef& a, const PrimRef& b) {
                             const float ca = a.centroid2()[axis], cb = b.centroid2()[axis];
                             return ca < cb || (ca == cb && a.id() < b.id());
                         });
        Halves h;
        h.mid = mid;
        for (uint32_t i = range.begin; i < range.end; ++i) h.add(i < mid ? 0 : 1, m_refs[i]);
        return h;
    }

    /// Writes the leaf's ids and, for triangles, its SoA block: nine rows of `count` floats at
    /// 9 * first.
    uint32_t make_leaf(const BuildRange& range) const {
        const uint32_t first = range.begin, count = range.size();
        for (uint32_t i = 0; i < count; ++i) m_ids[first + i] = m_refs[first + i].id();
        if (m_indices.empty()) return WideBvhRef::leaf(first, count);
        float* block = m_triangle_data + 9 * size_t(first);
        for (uint32_t i = 0; i < count; ++i) {
            const uint32_t id = m_ids[first + i];
            const auto& tri = m_indices[id];
            for (int v = 0; v < 3; ++v) {
                const Vec3 p = m_positions[tri[v]];
                block[(3 * v + 0) * count + i] = p.x;
                block[(3 * v + 1) * count + i] = p.y;
                block[(3 * v + 2) * count + i] = p.z;
            }
        }
        return WideBvhRef::leaf(first, count);
    }

    PrimRef* m_refs;
    NodeArena& m_arena;
    std::span<const Vec3> m_positions;
    std::span<const std::array<uint32_t, 3>> m_indices;
    float* m_triangle_data;
    uint32_t* m_ids;
    uint32_t m_bin_count = 16;
    uint32_t m_max_leaf = 8;
    uint32_t m_task_threshold = 4096;
    uint32_t m_data_parallel_threshold = 4 * 4096;
};

/// The PrimRefs of the usable primitives [0, n), in input order (make_ref(i, ref) fills ref
/// and says whether primitive i is usable), and the root range over them. Fixed blocks in
/// parallel; the bounds merge exactly, so the result is thread-independent.
template <class MakeRef>
BuildRange make_prim_refs(uint32_t n, const MakeRef& make_ref, PrimRef* refs) {
    constexpr uint32_t k_block = 4096;
    const uint32_t blocks = (n + k_block - 1) / k_block;
    struct Part {
        Box4 bounds = Box4::empty(), centroids = Box4::empty();
        uint32_t usable = 0;
    };
    std::vector<Part> parts(blocks);
    hikari::parallel_for(0u, blocks, [&](uint32_t b) {
        Part& part = parts[b];
        for (uint32_t i = b * k_block; i < std::min(n, (b + 1) * k_block); ++i) {
            if (!make_ref(i, refs[i])) continue;
            ++part.usable;
            part.bounds.extend(refs[i].lower, refs[i].upper);
            const F4 c = refs[i].centroid2();
            part.centroids.extend(c, c);
        }
    });
    BuildRange root{0, 0, 0, Box4::empty(), Box4::empty()};
    for (const Part& p : parts) {
        root.end += p.usable;
        root.bounds.extend(p.bounds);
        root.centroids.extend(p.centroids);
    }
    if (root.end < n) {  // rare: drop the unusable ones, keeping the order
        (void)std::remove_if(refs, refs + n, [](const PrimRef& r) { return r.id() == k_unusable; });
    }
    return root;
}

/// Lays the subtrees out one after another, depth first, and copies them into `nodes` with
/// their local indices made global.
void assemble(Subtree& root, HugePageVector<WideBvhNode>& nodes) {
    std::vector<Subtree*> order;
    uint32_t total = 0;
    std::vector<Subtree*> todo{&root};
    while (!todo.empty()) {
        Subtree* s = todo.back();
        todo.pop_back();
        s->offset = total;
        total += s->size;
        order.push_back(s);
        for (size_t i = s->links.size(); i-- > 0;) todo.push_back(s->links[i].child.get());
    }
    resize_on_huge_pages(nodes, total);
    hikari::parallel_for(size_t(0), order.size(), [&](size_t k) {
        const Subtree& s = *order[k];
        WideBvhNode* out = nodes.data() + s.offset;
        for (uint32_t i = 0; i < s.size; ++i) {
            out[i] = s.node(i);
            for (uint32_t& c : out[i].child)
                if (!WideBvhRef::is_leaf(c)) c += s.offset;  // k_empty counts as a leaf
        }
        for (const Subtree::Link& link : s.links)
            out[link.node].child[link.slot] = WideBvhRef::inner(link.child->offset);
    });
}

/// The tree over the PrimRefs [0, n) that make_ref makes (see make_prim_refs): over
/// triangles when `indices` is not empty, over bare boxes otherwise.
template <class MakeRef>
WideBvh build_over(size_t n, const MakeRef& make_ref, std::span<const Vec3> positions,
                   std::span<const std::array<uint32_t, 3>> indices,
                   const BvhBuildSettings& settings) {
    if (n >= WideBvhRef::k_max_triangles)
        throw std::length_error("build_wide_bvh: too many primitives for the reference encoding");
    if (n == 0) return {};
    const bool triangles = !indices.empty();
    // Everything the build takes at its peak: the references, the leaf data and ids, and the
    // nodes (about one per 8 primitives, counted as one per 4 for the scratch arena's slack).
    const double leaf_bytes = triangles ? 9 * sizeof(float) : 0.0;
    check_memory_need(
        double(n) * (sizeof(PrimRef) + leaf_bytes + sizeof(uint32_t) + sizeof(WideBvhNode) / 4.0),
        fmt::format("the BVH of {} {}", n, triangles ? "triangles" : "primitives"));
    const ScratchBlock refs_block(n * sizeof(PrimRef), true);
    auto* const refs = static_cast<PrimRef*>(refs_block.data());
    const BuildRange root = make_prim_refs(static_cast<uint32_t>(n), make_ref, refs);
    WideBvh wide;
    if (root.size() == 0) return wide;

    // The 8 floats of padding stay 0; every other float is written by its leaf.
    if (triangles)
        resize_on_huge_pages(wide.triangle_data, 9 * size_t(root.size()) + k_wide_bvh_width);
    resize_on_huge_pages(wide.triangle_ids, root.size());
    // A first block with room for one node per 8 primitives (trees here have about one per 15)
    // and a part-used chunk per subtree; more blocks if it fills up.
    const size_t subtrees = 2 * size_t(root.size()) / std::max(settings.parallel_threshold, 2u);
    NodeArena arena(root.size() / (8 * NodeArena::k_chunk) + subtrees);
    WideSahBuilder builder(settings, refs, positions, indices, arena, wide);
    Subtree top;
    wide.root = builder.build(root, top);
    if (!WideBvhRef::is_leaf(wide.root)) assemble(top, wide.nodes);
    wide.root_bounds = root.bounds.to_aabb();
    return wide;
}

}  // namespace

WideBvh build_wide_bvh(std::span<const Vec3> positions,
                       std::span<const std::array<uint32_t, 3>> indices,
                       const BvhBuildSettings& settings) {
    return build_over(
        indices.size(),
        [&](uint32_t i, PrimRef& ref) { return make_prim_ref(positions, indices[i], i, ref); },
        positions, indices, settings);
}

WideBvh build_wide_bvh_over_boxes(std::span<const Aabb> boxes, const BvhBuildSettings& settings) {
    return build_over(
        boxes.size(), [&](uint32_t i, PrimRef& ref) { return make_prim_ref(boxes[i], i, ref); }, {},
        {}, settings);
}

}  // namespace hikari
