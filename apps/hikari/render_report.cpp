#include "render_report.h"

#include <fmt/format.h>

#include "console.h"
#include "hikari/core/simd_level.h"

namespace hikari::cli {

namespace {

/// The first --stats line: phase times, rays and paths per second.
void print_phase_stats(const std::string& prefix, const PhaseTimes& times,
                       const RenderStats& stats) {
    std::string text = fmt::format("{}: load {:.1f} ms, render {:.1f} ms, write {:.1f} ms", prefix,
                                   1e3 * times.load, 1e3 * times.render, 1e3 * times.write);
    if (const uint64_t rays = stats.rays_traced.load(); rays > 0)
        text += fmt::format("; {} rays, {:.2f} Mrays/s", rays, 1e-6 * double(rays) / times.render);
    if (const uint64_t paths = stats.paths_traced.load(); paths > 0)
        text += fmt::format("; {} paths, {:.2f} Mpaths/s, {} NaN/Inf samples", paths,
                            1e-6 * double(paths) / times.render, stats.bad_samples.load());
    print_err("{}\n", text);
}

/// The raster methods' lines: the vertex stage (Fig 4.2-4.3) and the hidden-surface work.
void print_raster_stats(const std::string& prefix, const RenderStats& stats, const Method& method) {
    const uint64_t exact_spheres = stats.raster_exact_spheres.load();
    const uint64_t in = stats.raster_triangles.load();
    if (in == 0 && exact_spheres == 0) return;
    print_err(
        "{}: vertex stage: {} triangles in, {} culled (back faces), {} clipped away, "
        "{} cut by clipping; {} screen triangles\n",
        prefix, in, stats.raster_culled.load(), stats.raster_clipped_away.load(),
        stats.raster_cut.load(), stats.raster_screen_triangles.load());
    if (exact_spheres > 0)
        print_err("{}: {} exact sphere(s) drawn per pixel\n", prefix, exact_spheres);
    const uint64_t covered = stats.raster_covered_pixels.load();
    const uint64_t work = stats.raster_fragments.load();
    std::string text = fmt::format("{}: hidden surfaces: {} pixels covered", prefix, covered);
    if (work > 0)
        text += fmt::format("; {} {} ({:.2f} per covered pixel)", work, method.stats.work,
                            covered ? double(work) / double(covered) : 0.0);
    if (const uint64_t splits = stats.depth_sort_splits.load(); splits > 0 || method.stats.splits)
        text += fmt::format("; {} depth-sort splits", splits);
    if (const uint64_t polygons = stats.depth_sort_polygons.load(); polygons > 0)
        text += fmt::format("; {} polygons in the painting order", polygons);
    print_err("{}\n", text);
}

/// The raster methods' shadow pass, apart from the picture's render (its time is inside the
/// render time): shadow maps drawn from the lights, shadow-volume stencils or analytic occluders.
void print_shadow_pass_stats(const std::string& prefix, const RenderStats& stats) {
    const uint64_t us = stats.shadow_pass_us.load();
    const uint64_t kept = stats.shadow_maps_kept.load();
    if (us == 0 && kept == 0) return;
    std::string what = "analytic occluders";
    if (const uint64_t faces = stats.shadow_map_faces.load(); faces > 0 || kept > 0) {
        what = fmt::format("{} shadow-map face{}, {} texels drawn", faces, faces == 1 ? "" : "s",
                           stats.shadow_map_texels.load());
        if (kept > 0)
            what +=
                fmt::format("; {} map{} kept from an earlier render", kept, kept == 1 ? "" : "s");
    } else if (const uint64_t stencils = stats.shadow_volume_stencils.load(); stencils > 0)
        what = fmt::format("{} shadow-volume stencil{}", stencils, stencils == 1 ? "" : "s");
    print_err("{}: shadow pass: {}, {:.1f} ms (within the render time)\n", prefix, what,
              1e-3 * double(us));
}

/// The BVH lines: triangles and spheres, nodes, bytes, build time and kernels.
void print_bvh_stats(const std::string& prefix, const RenderStats& stats) {
    if (const uint64_t triangles = stats.bvh_triangles.load(); triangles > 0)
        print_err(
            "{}: BVH {} triangles, {} nodes (8-wide), {:.1f} bytes/triangle, {}, {} "
            "kernels\n",
            prefix, triangles, stats.bvh_nodes.load(),
            double(stats.bvh_bytes.load()) / double(triangles),
            stats.bvh_reused.load()
                ? std::string("kept from the session's first render")
                : fmt::format("built in {:.1f} ms", 1e-3 * double(stats.bvh_build_us.load())),
            simd_level_name(best_simd_level()));
    if (const uint64_t spheres = stats.bvh_spheres.load(); spheres > 0)
        print_err("{}: sphere BVH {} spheres, {} nodes (8-wide), {:.1f} bytes/sphere\n", prefix,
                  spheres, stats.bvh_sphere_nodes.load(),
                  double(stats.bvh_sphere_bytes.load()) / double(spheres));
}

}  // namespace

void print_summary(const std::string& output, int width, int height, const Method& method,
                   const Scene& scene, const PhaseTimes& times, const RenderStats& stats) {
    std::string text =
        fmt::format("hikari: wrote {} ({}x{}, {}; ", output, width, height, method.name);
    const size_t triangles = scene.triangles.indices.size();
    text += fmt::format("{} triangle{}", triangles, triangles == 1 ? "" : "s");
    if (const size_t spheres = scene.spheres.size(); spheres > 0)
        text += fmt::format(", {} sphere{}", spheres, spheres == 1 ? "" : "s");
    text += fmt::format("; load {:.3f} s", times.load);
    if (const uint64_t us = stats.bvh_build_us.load(); us > 0)
        text += fmt::format(", BVH {:.1f} ms", 1e-3 * double(us));
    else if (stats.bvh_reused.load())
        text += ", BVH kept";
    text += fmt::format(", render {:.3f} s)", times.render);
    print_err("{}\n", text);
}

void print_stats(const PhaseTimes& times, const RenderStats& stats, const Method& method) {
    // Each line names its method: `-m a,b` prints one block per method.
    const std::string prefix = fmt::format("hikari: stats ({})", method.name);
    print_phase_stats(prefix, times, stats);
    print_raster_stats(prefix, stats, method);
    print_shadow_pass_stats(prefix, stats);
    print_bvh_stats(prefix, stats);
}

}  // namespace hikari::cli
