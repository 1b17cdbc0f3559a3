#include "hikari/bench/bench_runner.h"

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <thread>

#include "hikari/bvh/wide_bvh_builder.h"
#include "hikari/bvh/wide_bvh_packet.h"
#include "hikari/bvh/wide_bvh_traversal.h"

namespace hikari {
namespace {

constexpr int k_b1_size = 1024;          ///< B1 image: 1024 x 1024 rays
constexpr size_t k_b1_chunk = 8 * 1024;  ///< 8 image rows
constexpr uint32_t k_b1_chunk_rows = 8;  ///< the same 8 rows, as two rows of 4x4 packets
constexpr size_t k_b2_chunk = 4096;

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// SPEC §3: N threads pull chunks [b, b + chunk) of [0, n) from an atomic counter. Each item's
/// result depends only on the item, so the outcome is the same for any thread count.
/// Each thread runs its own copy of `work`, whose captures should be values (pointers, not
/// references to the caller's locals): a helper thread that reads, on every ray, a line of the
/// calling thread's stack that the caller writes on every ray of its own (a hit record one frame
/// down) runs at half speed. It did in about a third of B1's 2-thread runs, as the stack's
/// random offset decided whether the two shared a cache line.
template <typename Work>
void parallel_chunks(int threads, size_t n, size_t chunk, const Work& work) {
    std::atomic<size_t> next{0};
    const auto worker = [&next, n, chunk, work] {
        for (size_t b; (b = next.fetch_add(chunk)) < n;) work(b, std::min(n, b + chunk));
    };
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i) pool.emplace_back(worker);
    worker();  // the calling thread is worker 0
    for (auto& t : pool) t.join();
}

/// Builds the wide BVH on `threads` threads: one warm-up build, then `reps` timed ones.
WideBvh timed_builds(const BenchMesh& mesh, int threads, int reps, std::vector<double>& ms) {
    // TBB's default pool has one thread per core: more threads than cores must be allowed
    // first, or the arena runs with fewer and TBB prints a warning.
    const tbb::global_control allow(tbb::global_control::max_allowed_parallelism,
                                    static_cast<size_t>(threads));
    tbb::task_arena arena(threads);
    WideBvh bvh;
    for (int r = 0; r <= reps; ++r) {
        arena.execute([&] {
            const auto start = Clock::now();
            bvh = build_wide_bvh(mesh.positions, mesh.indices);
            if (r > 0) ms.push_back(ms_since(start));
        });
    }
    return bvh;
}

/// One warm-up pass of `pass`, then `reps` timed ones.
template <typename Pass>
std::vector<double> timed_passes(int reps, const Pass& pass) {
    pass();
    std::vector<double> ms;
    for (int r = 0; r < reps; ++r) {
        const auto start = Clock::now();
        pass();
        ms.push_back(ms_since(start));
    }
    return ms;
}

}  // namespace

void trace_closest(const WideBvh& bvh, const BenchRays& rays, int threads, size_t chunk,
                   SimdLevel simd, std::vector<float>& hit_t, std::vector<uint32_t>& hit_triangle) {
    hit_t.resize(rays.rays.size());
    hit_triangle.resize(rays.rays.size());
    const WideBvh* tree = &bvh;
    const Ray* ray = rays.rays.data();
    const float t_far = rays.t_far;
    float* t_out = hit_t.data();
    uint32_t* triangle_out = hit_triangle.data();
    parallel_chunks(threads, rays.rays.size(), chunk, [=](size_t b, size_t e) {
        for (size_t i = b; i < e; ++i) {
            TriangleHit hit;
            const bool found = intersect_closest(*tree, ray[i], {0.0f, t_far}, hit, simd);
            t_out[i] = found ? hit.t : k_infinity;
            triangle_out[i] = found ? hit.triangle : ~0u;
        }
    });
}

void trace_closest_packets(const WideBvh& bvh, const BenchRays& rays, uint32_t width, int threads,
                           uint32_t chunk_rows, SimdLevel simd, std::vector<float>& hit_t,
                           std::vector<uint32_t>& hit_triangle) {
    const size_t n = rays.rays.size();
    hit_t.resize(n);
    hit_triangle.resize(n);
    const size_t height = width ? n / width : 0;
    const WideBvh* tree = &bvh;
    const Ray* ray = rays.rays.data();
    const float t_far = rays.t_far;
    float* t_out = hit_t.data();
    uint32_t* triangle_out = hit_triangle.data();
    parallel_chunks(threads, height, chunk_rows, [=](size_t y0, size_t y1) {
        // The tile loop of intersect_closest_tile, writing B1's outputs directly.
        RayPacket packet{};
        PacketHit hits;
        for (size_t y = y0; y < y1; y += 4)
            for (uint32_t x = 0; x < width; x += 4) {
                const size_t first = y * width + x;
                const uint32_t active =
                    packet.load_block(ray + first, width, width - x,
                                      uint32_t(std::min<size_t>(4, y1 - y)), {0.0f, t_far});
                const uint32_t hit_mask =
                    intersect_closest_packet(*tree, packet, active, hits, simd);
                for (uint32_t k = 0; k < k_packet_size; ++k) {
                    if (!(active & (1u << k))) continue;
                    const size_t i = first + (k / 4) * width + k % 4;
                    const bool hit = (hit_mask >> k) & 1u;
                    t_out[i] = hit ? hits.t[k] : k_infinity;
                    triangle_out[i] = hit ? hits.triangle[k] : ~0u;
                }
            }
    });
}

void trace_occluded(const WideBvh& bvh, const BenchRays& rays, int threads, size_t chunk,
                    SimdLevel simd, std::vector<uint8_t>& occluded) {
    occluded.resize(rays.rays.size());
    const WideBvh* tree = &bvh;
    const Ray* ray = rays.rays.data();
    const float t_far = rays.t_far;
    uint8_t* out = occluded.data();
    parallel_chunks(threads, rays.rays.size(), chunk, [=](size_t b, size_t e) {
        for (size_t i = b; i < e; ++i)
            out[i] = intersect_any(*tree, ray[i], {0.0f, t_far}, simd) ? 1 : 0;
    });
}

BenchResult run_bench(const BenchMesh& mesh, const std::string& mesh_name,
                      const BenchSettings& settings) {
    if (settings.bench != "B1" && settings.bench != "B2")
        throw std::invalid_argument("unknown benchmark " + settings.bench);
    if (settings.packets && settings.bench != "B1")
        throw std::invalid_argument("packets are for B1 only");
    const int threads = std::max(1, settings.threads);
    BenchResult result;
    result.bench = settings.packets ? "B1p16" : settings.bench;
    result.mesh = mesh_name;
    result.threads = threads;
    result.triangles = mesh.indices.size();
    result.simd = simd_level_name(settings.simd);
    // On the heap, not in this frame: the trace threads read it on every ray (parallel_chunks).
    const auto tree = std::make_unique<const WideBvh>(
        timed_builds(mesh, threads, settings.repetitions, result.build_ms));
    const WideBvh& bvh = *tree;
    result.bvh_bytes = double(bvh.memory_bytes());

    const BenchRays b1 = make_b1_rays(mesh, k_b1_size, k_b1_size);
    std::vector<float> hit_t;
    std::vector<uint32_t> hit_triangle;
    if (settings.bench == "B1") {
        result.rays = b1.rays.size();
        result.trace_ms = timed_passes(settings.repetitions, [&] {
            if (settings.packets)
                trace_closest_packets(bvh, b1, k_b1_size, threads, k_b1_chunk_rows, settings.simd,
                                      hit_t, hit_triangle);
            else
                trace_closest(bvh, b1, threads, k_b1_chunk, settings.simd, hit_t, hit_triangle);
        });
        double sum = 0;
        for (float t : hit_t)
            if (t < k_infinity) ++result.hits, sum += t;
        result.mean_t = result.hits ? sum / double(result.hits) : 0.0;
        return result;
    }
    trace_closest(bvh, b1, threads, k_b1_chunk, settings.simd, hit_t, hit_triangle);
    const BenchRays b2 = make_b2_rays(mesh, b1, hit_t, hit_triangle);
    result.rays = b2.rays.size();
    std::vector<uint8_t> occluded;
    result.trace_ms = timed_passes(settings.repetitions, [&] {
        trace_occluded(bvh, b2, threads, k_b2_chunk, settings.simd, occluded);
    });
    for (uint8_t o : occluded) result.hits += o;
    return result;
}

std::string BenchResult::to_json() const {
    const double rays_m = double(rays) * 1e-3;  // rays per ms / 1e3 = Mrays/s
    const auto mrays = [&](double ms) { return ms > 0 ? rays_m / ms : 0.0; };
    const double med = median(trace_ms);
    const auto [fast, slow] = std::minmax_element(trace_ms.begin(), trace_ms.end());
    const auto [bmin, bmax] = std::minmax_element(build_ms.begin(), build_ms.end());
    std::string s = fmt::format(
        R"({{"bench": "{}", "mesh": "{}", "threads": {}, "triangles": {}, "rays": {}, )"
        R"("mrays_per_s": {:.3f}, "mrays_min": {:.3f}, "mrays_max": {:.3f}, "trace_ms": {:.3f}, )"
        R"("build_ms": {:.3f}, "build_ms_min": {:.3f}, "build_ms_max": {:.3f}, )"
        R"("bvh_bytes_per_triangle": {:.2f}, "simd": "{}", "build_samples_ms": [{:.3f}], )"
        R"("trace_samples_ms": [{:.3f}], )",
        bench, mesh, threads, triangles, rays, mrays(med), trace_ms.empty() ? 0.0 : mrays(*slow),
        trace_ms.empty() ? 0.0 : mrays(*fast), med, median(build_ms),
        build_ms.empty() ? 0.0 : *bmin, build_ms.empty() ? 0.0 : *bmax,
        triangles ? bvh_bytes / double(triangles) : 0.0, simd, fmt::join(build_ms, ", "),
        fmt::join(trace_ms, ", "));
    if (bench == "B1" || bench == "B1p16")
        s += fmt::format(R"("hits": {}, "mean_t": {:.6f}}})", hits, mean_t);
    else
        s += fmt::format(R"("occluded": {}, "occluded_fraction": {:.6f}}})", hits,
                         rays ? double(hits) / double(rays) : 0.0);
    return s;
}

}  // namespace hikari
