#include "hikari/io/models/mesh_builder.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <optional>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "hikari/core/cancel.h"
#include "hikari/core/error.h"
#include "hikari/core/huge_page_allocator.h"
#include "hikari/core/memory_budget.h"
#include "hikari/core/parallel.h"
#include "hikari/core/parallel_pages.h"
#include "hikari/geometry/polygon_triangulation.h"

namespace hikari {
namespace {

/// A triangle kept for the output: vertex indices of the PolygonMesh, its face, outline edges.
struct PendingTriangle {
    std::array<uint32_t, 3> v;
    uint32_t face;
    uint8_t edge_flags;
};

/// A large working array whose elements are all written (in parallel) before they are read:
/// left unwritten when made (no zero pass by one thread), in huge pages where the system grants
/// them (fewer page faults).
template <class T>
using WorkArray = std::vector<T, UninitializedHugePageAllocator<T>>;
using PendingTriangles = WorkArray<PendingTriangle>;

/// v.resize(n), its new pages mapped first, by all threads (populate_pages) rather than faulted in
/// one by one as the resize writes them: on a virtual machine a fault costs several times more.
template <class T>
void mapped_resize(std::vector<T>& v, size_t n) {
    v.reserve(n);
    populate_pages_in_parallel(v.data() + v.size(), (n - std::min(n, v.size())) * sizeof(T));
    v.resize(n);
}

/// "FILE:LINE: " where the face's line is known, else "FILE: ".
std::string face_where(const std::filesystem::path& file, const PolygonMesh& mesh, size_t face) {
    if (face < mesh.face_line.size() && mesh.face_line[face] > 0)
        return fmt::format("{}:{}: ", file.string(), mesh.face_line[face]);
    return fmt::format("{}: ", file.string());
}

/// Twice the triangle's area (the length of N = (P2 - P1) x (P3 - P2), lecture Fig 4.3); zero or
/// not finite for a triangle that cannot be drawn.
float doubled_area(Vec3 p1, Vec3 p2, Vec3 p3) { return length(cross(p2 - p1, p3 - p2)); }

/// Faces per chunk of the parallel passes: fixed, so what the chunks find, joined in chunk
/// order, does not depend on the thread count.
constexpr size_t k_chunk_faces = 16384;

/// What one chunk of faces gives: its triangles, and what it has to report.
struct TriangulatedChunk {
    std::vector<PendingTriangle> triangles;
    size_t degenerate = 0;
    std::vector<size_t> crossing_faces;  ///< faces that cross themselves, in order
};

/// Faces [f0, f1) split into triangles, in face order; degenerate triangles dropped and counted.
void triangulate_chunk(const std::filesystem::path& file, const PolygonMesh& mesh, size_t f0,
                       size_t f1, TriangulatedChunk& out) {
    const size_t vertex_count = mesh.positions.size();
    const uint32_t corner_begin = mesh.face_start[f0], corner_end = mesh.face_start[f1];
    out.triangles.reserve(
        corner_end - corner_begin >= 2 * (f1 - f0) ? corner_end - corner_begin - 2 * (f1 - f0) : 0);
    std::vector<PolygonTriangle> local;
    std::vector<Vec3> outline;
    throw_if_cancelled();  // SIGINT / SIGTERM
    for (size_t f = f0; f < f1; ++f) {
        const uint32_t begin = mesh.face_start[f], end = mesh.face_start[f + 1];
        const uint32_t n = end - begin;
        if (n < 3 || n > k_max_face_corners)
            throw InputError(face_where(file, mesh, f) +
                             fmt::format("face {} has {} corner{}; a face needs 3 to {}", f + 1, n,
                                         n == 1 ? "" : "s", k_max_face_corners));
        for (uint32_t k = begin; k < end; ++k) {
            if (mesh.corners[k] >= vertex_count)
                throw InputError(face_where(file, mesh, f) +
                                 fmt::format("face {} refers to vertex {}, but the file has {}",
                                             f + 1, mesh.corners[k], vertex_count));
        }
        local.clear();
        if (n == 3) {
            local.push_back({{0, 1, 2}, 7});
        } else {
            outline.clear();
            for (uint32_t k = begin; k < end; ++k)
                outline.push_back(mesh.positions[mesh.corners[k]]);
            if (triangulate_polygon(outline, local) == PolygonShape::SelfIntersecting)
                out.crossing_faces.push_back(f);
        }
        for (const PolygonTriangle& t : local) {
            const PendingTriangle p{
                {mesh.corners[begin + t.corner[0]], mesh.corners[begin + t.corner[1]],
                 mesh.corners[begin + t.corner[2]]},
                static_cast<uint32_t>(f),
                t.edge_flags};
            const float area2 = doubled_area(mesh.positions[p.v[0]], mesh.positions[p.v[1]],
                                             mesh.positions[p.v[2]]);
            if (!(area2 > 0.0f) || !std::isfinite(area2)) {
                ++out.degenerate;
                continue;
            }
            out.triangles.push_back(p);
        }
    }
}

/// Every face split into triangles, in face order; degenerate triangles dropped and counted.
/// Chunks of faces are triangulated in parallel and joined in order; the first bad face in file
/// order is the one reported, as a loop over the faces would.
PendingTriangles triangulate_faces(const std::filesystem::path& file, const PolygonMesh& mesh,
                                   MeshData& out) {
    const size_t faces = mesh.face_count();
    std::vector<TriangulatedChunk> chunks((faces + k_chunk_faces - 1) / k_chunk_faces);
    parallel_chunks(faces, k_chunk_faces, [&](size_t c, size_t f0, size_t f1) {
        triangulate_chunk(file, mesh, f0, f1, chunks[c]);
    });
    std::vector<size_t> offset(chunks.size() + 1, 0);
    for (size_t c = 0; c < chunks.size(); ++c)
        offset[c + 1] = offset[c] + chunks[c].triangles.size();
    PendingTriangles triangles(offset.back());
    hikari::parallel_for(size_t{0}, chunks.size(), [&](size_t c) {
        std::copy(chunks[c].triangles.begin(), chunks[c].triangles.end(),
                  triangles.begin() + static_cast<std::ptrdiff_t>(offset[c]));
        chunks[c].triangles = {};
    });
    size_t crossing_faces = 0;
    for (const TriangulatedChunk& chunk : chunks) {
        out.degenerate_skipped += chunk.degenerate;
        for (const size_t f : chunk.crossing_faces) {
            if (crossing_faces < 3)
                out.warnings.push_back(
                    face_where(file, mesh, f) +
                    fmt::format("face {} crosses itself; its triangles may cover area outside "
                                "its outline",
                                f + 1));
            ++crossing_faces;
        }
    }
    if (crossing_faces > 3)
        out.warnings.push_back(
            fmt::format("{}: {} more faces cross themselves", file.string(), crossing_faces - 3));
    return triangles;
}

/// A vertex shared by more triangles than this is where a flood of copies of one triangle shows
/// itself; a model's own fans (a sphere's pole, a disc's centre) rarely reach it, and when they
/// do their triangles differ.
constexpr uint32_t k_crowded_vertex = 64;

/// Drops repeats of a triangle (the same three vertices in the same turning order, the same
/// material) among the triangles whose three vertices are all crowded, keeping the first, and
/// returns how many. A BVH cannot separate triangles that coincide, so without this a file of
/// 100,000 copies of one triangle (800 KB) made every ray that meets it test all of them (48 s
/// for an 800 × 600 image); a repeat draws nothing the first copy does not. Repeats at
/// uncrowded vertices cost little and are kept, so ordinary meshes are not searched.
size_t drop_repeated_triangles(const PolygonMesh& mesh, PendingTriangles& triangles) {
    // How many triangle corners each vertex has (exact integer sums: any order gives them).
    std::vector<uint32_t> sharing(mesh.positions.size(), 0);
    hikari::parallel_for(size_t{0}, triangles.size(), [&](size_t t) {
        for (const uint32_t v : triangles[t].v)
            std::atomic_ref<uint32_t>(sharing[v]).fetch_add(1, std::memory_order_relaxed);
    });
    std::vector<uint32_t> crowded;
    for (size_t i = 0; i < triangles.size(); ++i) {
        const std::array<uint32_t, 3>& v = triangles[i].v;
        if (sharing[v[0]] > k_crowded_vertex && sharing[v[1]] > k_crowded_vertex &&
            sharing[v[2]] > k_crowded_vertex)
            crowded.push_back(static_cast<uint32_t>(i));
    }
    if (crowded.size() < 2) return 0;
    // The triangle's vertices turned to start at the smallest index, and its material.
    const auto key = [&](uint32_t i) {
        const std::array<uint32_t, 3>& v = triangles[i].v;
        const int r = v[0] < v[1] && v[0] < v[2] ? 0 : (v[1] < v[2] ? 1 : 2);
        const int32_t material =
            mesh.face_material.empty() ? -1 : mesh.face_material[triangles[i].face];
        return std::tuple{v[r], v[(r + 1) % 3], v[(r + 2) % 3], material};
    };
    std::sort(crowded.begin(), crowded.end(), [&](uint32_t a, uint32_t b) {
        const auto ka = key(a), kb = key(b);
        return ka != kb ? ka < kb : a < b;
    });
    std::vector<uint8_t> repeat(triangles.size(), 0);
    size_t dropped = 0;
    for (size_t k = 1; k < crowded.size(); ++k) {
        if (key(crowded[k]) == key(crowded[k - 1])) {
            repeat[crowded[k]] = 1;
            ++dropped;
        }
    }
    if (dropped == 0) return 0;
    size_t kept = 0;
    for (size_t i = 0; i < triangles.size(); ++i)
        if (!repeat[i]) triangles[kept++] = triangles[i];
    triangles.resize(kept);
    return dropped;
}

bool is_usable_normal(Vec3 n) {
    const float l = dot(n, n);
    return l > 0.0f && std::isfinite(l);
}

/// Equal to the bit (so -0 and 0 differ, and a NaN equals itself): normals computed from the same
/// faces in the same order share a vertex, any other pair does not.
bool same_bits(Vec3 a, Vec3 b) {
    return std::bit_cast<uint32_t>(a.x) == std::bit_cast<uint32_t>(b.x) &&
           std::bit_cast<uint32_t>(a.y) == std::bit_cast<uint32_t>(b.y) &&
           std::bit_cast<uint32_t>(a.z) == std::bit_cast<uint32_t>(b.z);
}

/// Numbers the distinct keys met at one point (face normals, or smoothing groups) in order of
/// first appearance, in time linear in the corners however many there are: the previous key is
/// tried first (copies of a face come in runs), a short list is searched, a hash map beyond.
template <class Key>
class KeyNumbering {
  public:
    void clear() {
        m_keys.clear();
        if (!m_map.empty()) m_map = {};  // not clear(): that would wipe all its buckets each time
        m_last = 0;
    }
    /// The key's number, a new one (= count() before the call) if it was not seen yet.
    uint32_t number(const Key& key) {
        if (m_last < m_keys.size() && m_keys[m_last] == key) return m_last;
        if (m_keys.size() <= k_list_limit) {
            const auto found = std::find(m_keys.begin(), m_keys.end(), key);
            if (found != m_keys.end()) return m_last = uint32_t(found - m_keys.begin());
            if (m_keys.size() == k_list_limit)  // the list is full: index it from now on
                for (uint32_t k = 0; k < m_keys.size(); ++k) m_map.emplace(m_keys[k], k);
        } else if (const auto found = m_map.find(key); found != m_map.end()) {
            return m_last = found->second;
        }
        m_last = uint32_t(m_keys.size());
        if (m_keys.size() >= k_list_limit) m_map.emplace(key, m_last);
        m_keys.push_back(key);
        return m_last;
    }
    uint32_t count() const { return uint32_t(m_keys.size()); }

  private:
    struct Hash {
        size_t operator()(const Key& key) const {
            uint64_t h = 0x9e3779b97f4a7c15ull;
            for (uint32_t part : key) h = (h ^ part) * 0xff51afd7ed558ccdull;
            return size_t(h ^ (h >> 32));
        }
    };
    static constexpr size_t k_list_limit = 16;
    std::vector<Key> m_keys;
    std::unordered_map<Key, uint32_t, Hash> m_map;
    uint32_t m_last = 0;
};

/// The bits of a face normal, as a key: equal normals smooth exactly alike.
std::array<uint32_t, 3> normal_key(Vec3 n) {
    return {std::bit_cast<uint32_t>(n.x), std::bit_cast<uint32_t>(n.y),
            std::bit_cast<uint32_t>(n.z)};
}

/// Computes the normal of each corner (3 per triangle) that needs one: the sum of the unit face
/// normals around its point that it is smoothed with — those of its own smoothing group, or
/// those within the crease angle of its own face — each weighted by the triangle's angle at the
/// point (Thürmer & Wüthrich 1998), so a polygon counts the same however it was triangulated.
///
/// Done corner by corner, that sum visits every face at the point, so a point shared by n faces
/// costs n² (ten million faces on four vertices never finish). Corners whose sums are equal are
/// therefore summed once per point: those of one smoothing group, and those whose faces have
/// bit-identical normals (copies of a face, or a flat fan), each in the same order as corner by
/// corner, so the result does not change by a bit. That leaves a cost of (distinct normals ×
/// faces) at each point: always paid up to k_always_exact_directions distinct normals, and
/// beyond (a cone's apex, the pole of a finely divided sphere) while the mesh's budget of such
/// work lasts (k_exact_budget_base + k_exact_budget_per_corner × corners, far more than any
/// modelled mesh spends). Once it is spent (only a hostile file), the crease test at a point with
/// that many normals is made between direction cells (crease_cell) instead of between faces:
/// linear time, within a cell's width of the exact rule.
class CornerNormals {
  public:
    CornerNormals(const PolygonMesh& mesh, const PendingTriangles& triangles,
                  const MeshOptions& options)
        : m_mesh(mesh), m_triangles(triangles) {
        m_unit_normal.resize(triangles.size());
        m_corner_angle.resize(triangles.size());
        throw_if_cancelled();  // SIGINT / SIGTERM
        hikari::parallel_for(size_t{0}, triangles.size(), [&](size_t t) {
            const auto& v = triangles[t].v;
            const Vec3 p[3] = {mesh.positions[v[0]], mesh.positions[v[1]], mesh.positions[v[2]]};
            m_unit_normal[t] = normalize(cross(p[1] - p[0], p[2] - p[1]));
            for (int k = 0; k < 3; ++k) {
                const Vec3 a = normalize(p[(k + 1) % 3] - p[k]),
                           b = normalize(p[(k + 2) % 3] - p[k]);
                m_corner_angle[t][k] = std::acos(std::clamp(dot(a, b), -1.0f, 1.0f));
            }
        });
        m_by_groups = std::any_of(mesh.smoothing_group.begin(), mesh.smoothing_group.end(),
                                  [](uint32_t g) { return g != 0; });
        const float crease = std::clamp(options.crease_angle_degrees, 0.0f, 180.0f);
        m_min_cos = std::cos(crease * static_cast<float>(M_PI) / 180.0f) - 1e-6f;
        weld_positions();
        index_corners_by_point();
        share_sums();
    }

    Vec3 normal(size_t t, int slot) const {
        const uint32_t shared =
            m_shared_sum_of.empty() ? k_sum_at_corner : m_shared_sum_of[3 * t + slot];
        Vec3 sum;
        if (shared == k_sum_at_corner) {
            sum = sum_at_corner(t, slot);
        } else if (shared == k_sum_own_face) {
            sum = Vec3(0.0f);
            sum += weighted_normal(uint32_t(3 * t + slot));
        } else {
            sum = m_shared_sums[shared];
        }
        return is_usable_normal(sum) ? normalize(sum) : m_unit_normal[t];
    }

    /// Every corner's normal(t, slot) into normals[3 t + slot], point by point in parallel:
    /// the faces around a point are gathered once for all its corners (a corner by corner walk
    /// gathers them again for each), and each sum runs in the same corner order as normal()'s.
    void all_normals(WorkArray<Vec3>& normals) const {
        normals.resize(3 * m_triangles.size());
        hikari::parallel_for(
            tbb::blocked_range<size_t>(0, m_start.size() - 1, 1024),
            [&](const tbb::blocked_range<size_t>& points) {
                std::vector<Vec3> unit, weighted;
                for (size_t p = points.begin(); p != points.end(); ++p) {
                    const uint32_t begin = m_start[p], end = m_start[p + 1];
                    unit.clear();
                    weighted.clear();
                    for (uint32_t k = begin; k < end; ++k) {
                        unit.push_back(m_unit_normal[m_around[k] / 3]);
                        weighted.push_back(weighted_normal(m_around[k]));
                    }
                    for (uint32_t k = begin; k < end; ++k) {
                        const uint32_t corner = m_around[k];
                        const size_t t = corner / 3;
                        if (!m_shared_sum_of.empty() &&
                            m_shared_sum_of[corner] != k_sum_at_corner) {
                            normals[corner] = normal(t, int(corner % 3));
                            continue;
                        }
                        Vec3 sum(0.0f);
                        for (uint32_t o = begin; o < end; ++o) {
                            const uint32_t other = m_around[o] / 3;
                            if (other == t ||
                                (m_by_groups ? smoothed_together(t, other)
                                             : within_crease(unit[k - begin], unit[o - begin])))
                                sum += weighted[o - begin];
                        }
                        normals[corner] = is_usable_normal(sum) ? normalize(sum) : m_unit_normal[t];
                    }
                }
            });
    }

  private:
    /// m_shared_sum_of: the corner's own face alone (a face outside every smoothing group).
    static constexpr uint32_t k_sum_own_face = UINT32_MAX;
    /// m_shared_sum_of: the corner's crease sum, made when asked for (the only corner at its point
    /// with its face normal; the usual case, and no memory for it).
    static constexpr uint32_t k_sum_at_corner = UINT32_MAX - 1;
    /// Up to this many distinct face normals at a point, the crease test is made between faces.
    static constexpr uint32_t k_always_exact_directions = 32;
    /// The work (distinct normals × faces, summed over points) allowed for points with more.
    static constexpr double k_exact_budget_base = 268435456.0;  // 2^28: a 16384-gon's pole
    static constexpr double k_exact_budget_per_corner = 32.0;
    /// Direction cells per cube face edge: 6 × 4 × 4 cells of 22.5 degrees or less.
    static constexpr int k_cells_per_edge = 4;
    static constexpr int k_cell_count = 6 * k_cells_per_edge * k_cells_per_edge;

    uint32_t point_of(uint32_t vertex) const { return m_point[vertex]; }

    /// A corner's term of the sum: its face's unit normal times the face's angle at the corner.
    Vec3 weighted_normal(uint32_t corner) const {
        return m_corner_angle[corner / 3][corner % 3] * m_unit_normal[corner / 3];
    }

    /// Whether faces of these unit normals are smoothed together by the crease angle: a face is
    /// always smoothed with its copies, even one so small that its normal is not quite of unit
    /// length.
    bool within_crease(Vec3 a, Vec3 b) const { return dot(a, b) >= m_min_cos || same_bits(a, b); }

    bool smoothed_together(size_t a, size_t b) const {
        if (m_by_groups) {
            const uint32_t g = m_mesh.smoothing_group[m_triangles[a].face];
            return g != 0 && g == m_mesh.smoothing_group[m_triangles[b].face];
        }
        return within_crease(m_unit_normal[a], m_unit_normal[b]);
    }

    /// The sum of one corner, in corner order, over the corners at its point.
    Vec3 sum_at_corner(size_t t, int slot) const {
        const uint32_t point = point_of(m_triangles[t].v[slot]);
        Vec3 sum(0.0f);
        for (uint32_t k = m_start[point]; k < m_start[point + 1]; ++k) {
            const uint32_t other = m_around[k] / 3;
            if (other == t || smoothed_together(t, other)) sum += weighted_normal(m_around[k]);
        }
        return sum;
    }

    /// The crease sum, in corner order, of the terms at `point` smoothed with a face of normal n.
    Vec3 crease_sum(uint32_t point, Vec3 n) const {
        Vec3 sum(0.0f);
        for (uint32_t k = m_start[point]; k < m_start[point + 1]; ++k)
            if (within_crease(n, m_unit_normal[m_around[k] / 3]))
                sum += weighted_normal(m_around[k]);
        return sum;
    }

    /// Numbers the distinct positions: vertices at exactly the same place are one point, so a
    /// file that splits its vertices per face (at texture seams, or everywhere, as some PLY
    /// exporters do) is still smoothed across them.
    void weld_positions() {
        const size_t n = m_mesh.positions.size();
        std::vector<uint32_t> order(n);
        for (size_t i = 0; i < n; ++i) order[i] = uint32_t(i);
        auto bits = [&](uint32_t i) {
            std::array<uint32_t, 3> b{};
            std::memcpy(b.data(), &m_mesh.positions[i], sizeof(Vec3));
            return b;
        };
        // a strict total order (ties broken by index): the same result on any thread count
        hikari::parallel_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
            return std::pair(bits(a), a) < std::pair(bits(b), b);
        });
        m_point.resize(n);
        uint32_t point = 0;
        for (size_t k = 0; k < n; ++k) {
            if (k > 0 && bits(order[k]) != bits(order[k - 1])) ++point;
            m_point[order[k]] = point;
        }
    }

    /// m_around[m_start[p] .. m_start[p + 1]) lists the corners at point p, as 3 × triangle +
    /// corner, in increasing order.
    void index_corners_by_point() {
        uint32_t points = 0;
        for (const PendingTriangle& t : m_triangles)
            for (uint32_t v : t.v) points = std::max(points, point_of(v) + 1);
        m_start.assign(size_t{points} + 1, 0);
        for (const PendingTriangle& t : m_triangles)
            for (uint32_t v : t.v) ++m_start[point_of(v) + 1];
        for (size_t p = 0; p < points; ++p) m_start[p + 1] += m_start[p];
        m_around.resize(m_start[points]);
        std::vector<uint32_t> fill(m_start.begin(), m_start.end() - 1);
        for (size_t t = 0; t < m_triangles.size(); ++t)
            for (uint32_t k = 0; k < 3; ++k)
                m_around[fill[point_of(m_triangles[t].v[k])]++] = uint32_t(3 * t + k);
    }

    /// Fills m_shared_sum_of and m_shared_sums at the points of more than
    /// k_always_exact_directions corners (at the others, corner by corner costs little).
    void share_sums() {
        m_exact_budget =
            k_exact_budget_base + k_exact_budget_per_corner * static_cast<double>(m_around.size());
        size_t work = 0;
        for (uint32_t p = 0; p + 1 < m_start.size(); ++p) {
            const uint32_t begin = m_start[p], end = m_start[p + 1];
            work += end - begin;
            if (work >= 65536) {
                work = 0;
                throw_if_cancelled();  // SIGINT / SIGTERM
            }
            if (end - begin <= k_always_exact_directions) continue;
            if (m_shared_sum_of.empty()) m_shared_sum_of.assign(m_around.size(), k_sum_at_corner);
            if (m_by_groups)
                share_group_sums(begin, end);
            else
                share_crease_sums(p, begin, end);
        }
    }

    /// Smoothing groups: one sum per group at the point, each made in corner order as the corner
    /// by corner sum makes it; faces outside every group (group 0) keep their own normal.
    void share_group_sums(uint32_t begin, uint32_t end) {
        m_groups.clear();
        const uint32_t first_sum = uint32_t(m_shared_sums.size());
        for (uint32_t k = begin; k < end; ++k) {
            const uint32_t corner = m_around[k];
            const uint32_t g = m_mesh.smoothing_group[m_triangles[corner / 3].face];
            if (g == 0) {
                m_shared_sum_of[corner] = k_sum_own_face;
                continue;
            }
            const uint32_t group = m_groups.number({g});
            if (first_sum + group == m_shared_sums.size()) m_shared_sums.emplace_back(0.0f);
            m_shared_sums[first_sum + group] += weighted_normal(corner);
            m_shared_sum_of[corner] = first_sum + group;
        }
    }

    /// Crease angle: the corners of faces with bit-identical normals have one sum, made once.
    void share_crease_sums(uint32_t point, uint32_t begin, uint32_t end) {
        // Number the directions; each corner's number waits in m_shared_sum_of until replaced.
        m_directions.clear();
        m_direction_count.clear();
        for (uint32_t k = begin; k < end; ++k) {
            const uint32_t d = m_directions.number(normal_key(m_unit_normal[m_around[k] / 3]));
            if (d == m_direction_count.size()) m_direction_count.push_back(0);
            ++m_direction_count[d];
            m_shared_sum_of[m_around[k]] = d;
        }
        if (m_directions.count() > k_always_exact_directions) {
            const double work = double(m_directions.count()) * double(end - begin);
            if (work > m_exact_budget) {
                share_cell_sums(begin, end);
                return;
            }
            m_exact_budget -= work;
        }
        m_direction_sum.assign(m_directions.count(), k_sum_at_corner);
        for (uint32_t k = begin; k < end; ++k) {
            const uint32_t d = m_shared_sum_of[m_around[k]];
            if (m_direction_count[d] < 2) {  // the only face of its direction: made when asked
                m_shared_sum_of[m_around[k]] = k_sum_at_corner;
                continue;
            }
            if (m_direction_sum[d] == k_sum_at_corner) {
                m_direction_sum[d] = uint32_t(m_shared_sums.size());
                m_shared_sums.push_back(crease_sum(point, m_unit_normal[m_around[k] / 3]));
            }
            m_shared_sum_of[m_around[k]] = m_direction_sum[d];
        }
    }

    /// The direction cell of a unit vector: the face of the cube around the sphere that its
    /// largest component points to, and a square of that face (a cube map).
    static int crease_cell(Vec3 n) {
        const float c[3] = {n.x, n.y, n.z};
        int axis = 0;
        for (int i = 1; i < 3; ++i)
            if (std::fabs(c[i]) > std::fabs(c[axis])) axis = i;
        const float major = std::fabs(c[axis]);
        auto square = [&](float minor) {
            const float at = (minor / major + 1.0f) * 0.5f * k_cells_per_edge;
            return std::clamp(static_cast<int>(at), 0, k_cells_per_edge - 1);
        };
        const int face = 2 * axis + (c[axis] < 0.0f ? 1 : 0);
        return (face * k_cells_per_edge + square(c[(axis + 1) % 3])) * k_cells_per_edge +
               square(c[(axis + 2) % 3]);
    }

    /// Many face directions at one point: the faces are gathered into direction cells, and a
    /// corner's sum is that of the cells whose mean direction is within the crease angle of its
    /// own cell's (in double, so the order of the terms hardly matters).
    void share_cell_sums(uint32_t begin, uint32_t end) {
        struct Cell {
            std::array<double, 3> direction{}, sum{};
            uint32_t shared = k_sum_at_corner;
        };
        std::array<Cell, k_cell_count> cells{};
        std::array<int, k_cell_count> used{};
        int used_count = 0;
        for (uint32_t k = begin; k < end; ++k) {
            const uint32_t corner = m_around[k];
            const Vec3 n = m_unit_normal[corner / 3], w = weighted_normal(corner);
            const int c = crease_cell(n);
            if (cells[c].shared == k_sum_at_corner) {
                cells[c].shared = 0;
                used[used_count++] = c;
            }
            for (int i = 0; i < 3; ++i) {
                cells[c].direction[i] += n[i];
                cells[c].sum[i] += w[i];
            }
        }
        std::array<Vec3, k_cell_count> mean{};
        for (int u = 0; u < used_count; ++u) {
            const auto& d = cells[used[u]].direction;
            const Vec3 sum{float(d[0]), float(d[1]), float(d[2])};
            mean[used[u]] = is_usable_normal(sum) ? normalize(sum) : Vec3(0.0f);
        }
        for (int u = 0; u < used_count; ++u) {
            std::array<double, 3> total{};
            for (int v = 0; v < used_count; ++v) {
                if (u != v && dot(mean[used[u]], mean[used[v]]) < m_min_cos) continue;
                for (int i = 0; i < 3; ++i) total[i] += cells[used[v]].sum[i];
            }
            cells[used[u]].shared = uint32_t(m_shared_sums.size());
            m_shared_sums.emplace_back(float(total[0]), float(total[1]), float(total[2]));
        }
        for (uint32_t k = begin; k < end; ++k)
            m_shared_sum_of[m_around[k]] =
                cells[crease_cell(m_unit_normal[m_around[k] / 3])].shared;
    }

    const PolygonMesh& m_mesh;
    const PendingTriangles& m_triangles;
    WorkArray<Vec3> m_unit_normal;
    WorkArray<std::array<float, 3>> m_corner_angle;
    WorkArray<uint32_t> m_point, m_around;
    std::vector<uint32_t> m_start;
    bool m_by_groups = false;
    float m_min_cos = -1.0f;
    /// Per corner (3 × triangle + corner): an index into m_shared_sums, or k_sum_own_face or
    /// k_sum_at_corner; empty while no point needs it.
    std::vector<uint32_t> m_shared_sum_of;
    std::vector<Vec3> m_shared_sums;
    double m_exact_budget = 0.0;  ///< what is left of the exact crease tests' budget
    /// Scratch of share_sums(), kept to reuse its memory from point to point.
    KeyNumbering<std::array<uint32_t, 1>> m_groups;
    KeyNumbering<std::array<uint32_t, 3>> m_directions;
    std::vector<uint32_t> m_direction_count, m_direction_sum;
};

}  // namespace

double mesh_build_bytes(double triangles, double vertices) {
    // Per triangle the pending one, its output indices, material and edge flags, and the
    // computed normals' face normal, corner angles and shared sums, and per corner its normal,
    // variant, number and a flag (the parallel numbering of output vertices); per vertex its
    // output attributes and the bookkeeping of normal variants (about 40 bytes).
    return triangles * (sizeof(PendingTriangle) + 53.0 + 3.0 * (sizeof(Vec3) + 9.0)) +
           40.0 * vertices;
}

namespace {

/// The output vertices, in order of first use: one per distinct (input vertex, normal) pair (a
/// vertex is split along creases), numbered as a walk over the corners in order would number
/// them when it met each pair the first time; and each triangle's indices, material and edge
/// flags. In parallel: a corner whose normal equals that of its vertex's first corner (all but
/// the crease corners of a smooth mesh) is that variant at once; the rest are sorted out by a
/// walk over them alone, in corner order.
void number_output_vertices(const PolygonMesh& mesh, const PendingTriangles& triangles,
                            const WorkArray<Vec3>& corner_normal, MeshData& out) {
    constexpr uint32_t k_none = UINT32_MAX;
    const size_t corners = 3 * triangles.size();
    const auto vertex_of = [&](size_t c) { return triangles[c / 3].v[c % 3]; };
    // the first corner of each vertex
    WorkArray<uint32_t> first_corner(mesh.positions.size());
    hikari::parallel_for(size_t{0}, first_corner.size(),
                         [&](size_t v) { first_corner[v] = k_none; });
    hikari::parallel_for(size_t{0}, corners, [&](size_t c) {
        std::atomic_ref<uint32_t> first(first_corner[vertex_of(c)]);
        uint32_t seen = first.load(std::memory_order_relaxed);
        while (c < seen &&
               !first.compare_exchange_weak(seen, uint32_t(c), std::memory_order_relaxed)) {
        }
    });
    // variant[c]: the corner that first used c's pair (itself where c is a first use)
    WorkArray<uint32_t> variant(corners);
    WorkArray<uint8_t> other_normal(corners);
    hikari::parallel_for(size_t{0}, corners, [&](size_t c) {
        const uint32_t head = first_corner[vertex_of(c)];
        other_normal[c] = !same_bits(corner_normal[c], corner_normal[head]);
        variant[c] = head;
    });
    // Corners with another normal than their vertex's first: each vertex's further variants in
    // a short chain, met in corner order.
    std::vector<uint32_t> chain_head(mesh.positions.size(), k_none), chain_next;
    std::vector<uint32_t> chain_corner;
    for (size_t c = 0; c < corners; ++c) {
        if (!other_normal[c]) continue;
        if (c % 65536 == 0) throw_if_cancelled();  // SIGINT / SIGTERM
        const uint32_t v = vertex_of(c);
        uint32_t last = k_none, at = chain_head[v];
        while (at != k_none && !same_bits(corner_normal[chain_corner[at]], corner_normal[c])) {
            last = at;
            at = chain_next[at];
        }
        if (at == k_none) {
            at = uint32_t(chain_corner.size());
            (last == k_none ? chain_head[v] : chain_next[last]) = at;
            chain_next.push_back(k_none);
            chain_corner.push_back(uint32_t(c));
        }
        variant[c] = chain_corner[at];
    }
    // number the first uses in corner order (a prefix sum), then fill everything in parallel
    WorkArray<uint32_t> number(corners);
    uint32_t count = 0;
    for (size_t c = 0; c < corners; ++c) {
        number[c] = count;
        count += variant[c] == c;
    }
    const bool has_uvs = !mesh.uvs.empty(), has_colors = !mesh.colors.empty();
    mapped_resize(out.positions, count);
    mapped_resize(out.normals, count);
    if (has_uvs) mapped_resize(out.uvs, count);
    if (has_colors) mapped_resize(out.colors, count);
    mapped_resize(out.indices, triangles.size());
    mapped_resize(out.material, triangles.size());
    mapped_resize(out.edge_flags, triangles.size());
    hikari::parallel_for(size_t{0}, triangles.size(), [&](size_t t) {
        const PendingTriangle& tri = triangles[t];
        for (int slot = 0; slot < 3; ++slot) {
            const size_t c = 3 * t + slot;
            const uint32_t v = tri.v[slot];
            out.indices[t][slot] = number[variant[c]];
            if (variant[c] != c) continue;
            const uint32_t n = number[c];
            out.positions[n] = mesh.positions[v];
            out.normals[n] = corner_normal[c];
            if (has_uvs) out.uvs[n] = mesh.uvs[v];
            if (has_colors) out.colors[n] = mesh.colors[v];
        }
        out.material[t] = mesh.face_material.empty() ? -1 : mesh.face_material[tri.face];
        out.edge_flags[t] = tri.edge_flags;
    });
}

}  // namespace

MeshData build_mesh(const std::filesystem::path& file, PolygonMesh mesh,
                    const MeshOptions& options) {
    MeshData out;
    out.warnings = std::move(mesh.warnings);
    const size_t corners = mesh.corners.size(), faces = mesh.face_count();
    const double triangle_count =
        corners >= 2 * faces ? static_cast<double>(corners - 2 * faces) : 0.0;
    check_memory_need(mesh_build_bytes(triangle_count, static_cast<double>(mesh.positions.size())),
                      fmt::format("{}: building {:.0f} triangles", file.string(), triangle_count));
    PendingTriangles triangles = triangulate_faces(file, mesh, out);
    if (const size_t repeats = drop_repeated_triangles(mesh, triangles); repeats > 0) {
        out.warnings.push_back(fmt::format(
            "{}: skipped {} repeated triangle(s) (the same corners and material as an earlier one)",
            file.string(), repeats));
    }
    if (triangles.empty()) {
        throw InputError(fmt::format(
            "{}: {}", file.string(),
            out.degenerate_skipped > 0
                ? fmt::format("no usable triangles: all {} are degenerate", out.degenerate_skipped)
                : std::string("no faces: the file defines no triangles or polygons")));
    }
    if (triangles.size() > UINT32_MAX / 3)
        throw InputError(fmt::format("{}: too many triangles", file.string()));

    const size_t vertex_count = mesh.positions.size();
    std::vector<uint8_t> has_own_normal(vertex_count, 0);
    std::atomic<bool> any_computed = mesh.normals.empty();
    if (!mesh.normals.empty()) {
        hikari::parallel_for(size_t{0}, vertex_count, [&](size_t v) {
            has_own_normal[v] = is_usable_normal(mesh.normals[v]);
        });
        hikari::parallel_for(size_t{0}, triangles.size(), [&](size_t t) {
            for (uint32_t v : triangles[t].v)
                if (!has_own_normal[v]) any_computed.store(true, std::memory_order_relaxed);
        });
    }
    std::optional<CornerNormals> computed;
    if (any_computed) computed.emplace(mesh, triangles, options);
    // Every corner's normal, in parallel (each is a function of the mesh alone).
    WorkArray<Vec3> corner_normal;
    throw_if_cancelled();  // SIGINT / SIGTERM
    if (computed)
        computed->all_normals(corner_normal);
    else
        corner_normal.resize(3 * triangles.size());
    if (!mesh.normals.empty())
        hikari::parallel_for(size_t{0}, triangles.size(), [&](size_t t) {
            for (int slot = 0; slot < 3; ++slot) {
                const uint32_t v = triangles[t].v[slot];
                if (has_own_normal[v]) corner_normal[3 * t + slot] = normalize(mesh.normals[v]);
            }
        });
    throw_if_cancelled();  // SIGINT / SIGTERM
    number_output_vertices(mesh, triangles, corner_normal, out);
    out.materials = std::move(mesh.materials);
    return out;
}

}  // namespace hikari
