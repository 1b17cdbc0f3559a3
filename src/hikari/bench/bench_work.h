#pragma once
// The work of the peer benchmarks B1 and B2 (../bench/SPEC.md §1-4), exactly: the mesh as the
// peers load it, the B1 camera rays and the B2 occlusion rays. Pure functions, no timing, so
// tests can check them against brute force; `bench_runner.h` times them. Also the median every
// benchmark (B5 too) reports.

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "hikari/core/ray.h"
#include "hikari/core/vec.h"

namespace hikari {

/// A mesh as SPEC §1 defines it: float32 positions in file order, position indices of the
/// faces in file order (polygons fanned), nothing else.
struct BenchMesh {
    std::vector<Vec3> positions;
    std::vector<std::array<uint32_t, 3>> indices;
    std::array<double, 3> center{};  ///< (bmin + bmax) / 2, in double
    double diagonal = 0;             ///< |bmax - bmin|, in double
};

/// Loads an OBJ file the SPEC's way (io/obj_loader.h's load_obj_triangles: tinyobjloader, `v`
/// and `f` only, file order). Throws InputError.
BenchMesh load_bench_mesh(const std::filesystem::path& file);

/// Computes center and diagonal from the positions (SPEC §1).
void set_bench_bounds(BenchMesh& mesh);

/// The mesh's centre c, rounded to float.
Vec3 bench_center(const BenchMesh& mesh);

/// SPEC §2's eye c + (0, 0, 1.1 d), computed in double and rounded to float (B1, B2, B4).
Vec3 b1_eye(const BenchMesh& mesh);

/// A batch of rays, each with its own far limit (the near limit is always 0).
struct BenchRays {
    std::vector<Ray> rays;
    float t_far = k_infinity;
};

/// SPEC §2-3: one ray per pixel centre of a width x height image, row-major from the top row,
/// from eye = c + (0, 0, 1.1 d) with unit directions computed in double and rounded to float.
BenchRays make_b1_rays(const BenchMesh& mesh, int width, int height);

/// SPEC §4: four cosine-distributed occlusion rays per B1 hit, in pixel order. `hit_t[i]` is
/// the B1 distance of pixel i (+inf for a miss), `hit_triangle[i]` the triangle hit.
BenchRays make_b2_rays(const BenchMesh& mesh, const BenchRays& b1, const std::vector<float>& hit_t,
                       const std::vector<uint32_t>& hit_triangle);

/// The median of `values` (the mean of the middle two for an even count; 0 for none): the
/// figure every benchmark reports.
double median(std::vector<double> values);

}  // namespace hikari
