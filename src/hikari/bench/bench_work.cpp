#include "hikari/bench/bench_work.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "hikari/core/rng.h"
#include "hikari/io/models/obj_loader.h"

namespace hikari {

BenchMesh load_bench_mesh(const std::filesystem::path& file) {
    ObjTriangles obj = load_obj_triangles(file);
    BenchMesh mesh{std::move(obj.positions), std::move(obj.indices), {}, 0};
    set_bench_bounds(mesh);
    return mesh;
}

void set_bench_bounds(BenchMesh& mesh) {
    Vec3 lo(k_infinity), hi(-k_infinity);
    for (const Vec3& p : mesh.positions) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    double d2 = 0;
    for (int a = 0; a < 3; ++a) {
        mesh.center[a] = 0.5 * (double(lo[a]) + double(hi[a]));
        const double e = double(hi[a]) - double(lo[a]);
        d2 += e * e;
    }
    mesh.diagonal = std::sqrt(d2);
}

Vec3 bench_center(const BenchMesh& mesh) {
    return {float(mesh.center[0]), float(mesh.center[1]), float(mesh.center[2])};
}

Vec3 b1_eye(const BenchMesh& mesh) {
    return {float(mesh.center[0]), float(mesh.center[1]),
            float(mesh.center[2] + 1.1 * mesh.diagonal)};
}

BenchRays make_b1_rays(const BenchMesh& mesh, int width, int height) {
    // The view direction is -z, so right = +x and up = +y exactly (SPEC §2).
    const double tan_half = std::tan(45.0 * M_PI / 360.0);
    const Vec3 eye = b1_eye(mesh);
    BenchRays out;
    out.rays.resize(size_t(width) * size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const double sx = (2.0 * (x + 0.5) / width - 1.0) * tan_half * (double(width) / height);
            const double sy = (1.0 - 2.0 * (y + 0.5) / height) * tan_half;
            const double length = std::sqrt(sx * sx + sy * sy + 1.0);
            out.rays[size_t(y) * width + x] = {
                eye, {float(sx / length), float(sy / length), float(-1.0 / length)}};
        }
    return out;
}

namespace {

/// The unit geometric normal n = normalize(cross(v1 - v0, v2 - v0)), in double, then float,
/// with the peer build's fused multiply-adds (see make_b2_rays).
Vec3 geometric_normal(const BenchMesh& mesh, uint32_t triangle) {
    const auto& tri = mesh.indices[triangle];
    double e1[3], e2[3];
    for (int a = 0; a < 3; ++a) {
        e1[a] = double(mesh.positions[tri[1]][a]) - mesh.positions[tri[0]][a];
        e2[a] = double(mesh.positions[tri[2]][a]) - mesh.positions[tri[0]][a];
    }
    const auto cross_term = [&](int a, int b) { return std::fma(e1[a], e2[b], -(e1[b] * e2[a])); };
    const double n[3] = {cross_term(1, 2), cross_term(2, 0), cross_term(0, 1)};
    const double length = std::sqrt(std::fma(n[2], n[2], std::fma(n[0], n[0], n[1] * n[1])));
    return {float(n[0] / length), float(n[1] / length), float(n[2] / length)};
}

}  // namespace

BenchRays make_b2_rays(const BenchMesh& mesh, const BenchRays& b1, const std::vector<float>& hit_t,
                       const std::vector<uint32_t>& hit_triangle) {
    // SPEC §4's float32 formulas, each a + b c evaluated as one fused multiply-add in the order
    // the peer's build evaluates it: `g++ -O2 -march=native` contracts them (GNU C++ defaults to
    // -ffp-contract=fast). Written out, the rays equal the peer's bit for bit wherever the two
    // B1 hits agree (all directions, and every origin with the same t), so the occluded counts
    // differ only where the triangle tests disagree at an edge (docs/performance.md).
    const auto eps = float(1e-4 * mesh.diagonal);
    BenchRays out;
    out.t_far = float(0.3 * mesh.diagonal);
    for (size_t i = 0; i < b1.rays.size(); ++i) {
        if (!(hit_t[i] < k_infinity)) continue;
        const Ray& primary = b1.rays[i];
        const Vec3 d = primary.direction;
        Vec3 n = geometric_normal(mesh, hit_triangle[i]);
        if (std::fma(n.z, d.z, std::fma(n.x, d.x, n.y * d.y)) > 0.0f) n = -n;
        const float t = hit_t[i];
        // p = org + t dir, then origin = p + eps n.
        const auto offset = [&](float o, float dir, float normal) {
            return std::fma(eps, normal, std::fma(t, dir, o));
        };
        const Vec3 origin{offset(primary.origin.x, d.x, n.x), offset(primary.origin.y, d.y, n.y),
                          offset(primary.origin.z, d.z, n.z)};
        // Duff et al. 2017, "Building an orthonormal basis, revisited".
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float b = n.x * n.y * a;
        const Vec3 tangent{std::fma(sign * n.x * n.x, a, 1.0f), sign * b, -sign * n.x};
        const Vec3 bitangent{b, std::fma(n.y * n.y, a, sign), -n.y};
        Pcg32 rng(i, 0xB2);
        for (int s = 0; s < 4; ++s) {
            const float u1 = rng.next_float(), u2 = rng.next_float();
            const float r = std::sqrt(u1), phi = 6.2831853071795864769f * u2;
            const float lx = r * std::cos(phi), ly = r * std::sin(phi);
            const float lz = std::sqrt(std::max(0.0f, 1.0f - u1));
            // dir = lx T + ly B + lz n, summed from the ly B term.
            const auto mix = [&](float t_a, float b_a, float n_a) {
                return std::fma(lz, n_a, std::fma(lx, t_a, ly * b_a));
            };
            out.rays.push_back({origin,
                                {mix(tangent.x, bitangent.x, n.x), mix(tangent.y, bitangent.y, n.y),
                                 mix(tangent.z, bitangent.z, n.z)}});
        }
    }
    return out;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace hikari
