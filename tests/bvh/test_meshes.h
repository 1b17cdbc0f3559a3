#pragma once
// Meshes and rays shared by the bvh/ tests: random triangle soups, a tessellated sphere and
// brute-force reference answers. Everything is seeded, so failures reproduce.

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <vector>

#include "hikari/core/ray.h"
#include "hikari/core/rng.h"
#include "hikari/core/vec.h"
#include "hikari/geometry/triangle_intersect.h"
#include "hikari/scene/scene.h"

namespace hikari::testing {

/// An indexed triangle mesh, as build_wide_bvh takes it.
struct TestMesh {
    std::vector<Vec3> positions;
    std::vector<std::array<uint32_t, 3>> indices;
};

/// `mesh` as a scene's triangles: smooth vertex normals pointing away from near the origin,
/// triangle i with material `material_of(i)` and the next free id (`id` is advanced).
template <class MaterialOf>
void set_scene_triangles(TriangleSet& tris, const TestMesh& mesh, PrimitiveId& id,
                         MaterialOf material_of) {
    tris.positions = mesh.positions;
    tris.indices = mesh.indices;
    for (const Vec3& p : mesh.positions) tris.normals.push_back(normalize(p + Vec3(0.01f)));
    for (size_t i = 0; i < mesh.indices.size(); ++i) {
        tris.material.push_back(material_of(i));
        tris.id.push_back(id++);
    }
}

/// A point uniformly distributed in the cube [-r, r]^3.
inline Vec3 random_point(Pcg32& rng, float r) {
    return {r * (2 * rng.next_float() - 1), r * (2 * rng.next_float() - 1),
            r * (2 * rng.next_float() - 1)};
}

/// A unit vector uniformly distributed on the sphere.
inline Vec3 random_direction(Pcg32& rng) {
    const float z = 1 - 2 * rng.next_float();
    const float phi = 2 * std::numbers::pi_v<float> * rng.next_float();
    const float s = std::sqrt(std::max(0.0f, 1 - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
}

/// `count` unconnected triangles with centres in [-1, 1]^3 and edges up to `size` long.
inline TestMesh random_soup(uint32_t count, float size, uint64_t seed) {
    Pcg32 rng(seed, 1);
    TestMesh mesh;
    for (uint32_t i = 0; i < count; ++i) {
        const Vec3 c = random_point(rng, 1.0f);
        const auto base = static_cast<uint32_t>(mesh.positions.size());
        for (int k = 0; k < 3; ++k) mesh.positions.push_back(c + random_point(rng, 0.5f * size));
        mesh.indices.push_back({base, base + 1, base + 2});
    }
    return mesh;
}

/// A closed UV sphere of radius `radius` around the origin: `lon` segments, `lat` bands, poles
/// shared by fans, so every edge is shared by exactly two triangles.
inline TestMesh uv_sphere(uint32_t lon, uint32_t lat, float radius) {
    TestMesh mesh;
    const float pi = std::numbers::pi_v<float>;
    mesh.positions.push_back({0, radius, 0});
    for (uint32_t k = 1; k < lat; ++k) {
        const float theta = pi * float(k) / float(lat);
        for (uint32_t m = 0; m < lon; ++m) {
            const float phi = 2 * pi * float(m) / float(lon);
            mesh.positions.push_back(radius * Vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                                   std::sin(theta) * std::sin(phi)));
        }
    }
    const auto south = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.push_back({0, -radius, 0});
    const auto ring = [lon](uint32_t k, uint32_t m) { return 1 + (k - 1) * lon + m % lon; };
    for (uint32_t m = 0; m < lon; ++m) {
        mesh.indices.push_back({0, ring(1, m + 1), ring(1, m)});
        for (uint32_t k = 1; k + 1 < lat; ++k) {
            mesh.indices.push_back({ring(k, m), ring(k, m + 1), ring(k + 1, m)});
            mesh.indices.push_back({ring(k, m + 1), ring(k + 1, m + 1), ring(k + 1, m)});
        }
        mesh.indices.push_back({ring(lat - 1, m), ring(lat - 1, m + 1), south});
    }
    return mesh;
}

/// The nearest hit by testing every triangle in input order: the reference the BVH must match.
struct BruteForceHit {
    TriangleIntersection hit;
    uint32_t triangle = 0;
};

inline std::optional<BruteForceHit> brute_force_closest(const TestMesh& mesh, const Ray& ray,
                                                        Interval valid) {
    const WatertightRay shear(ray);
    std::optional<BruteForceHit> best;
    for (uint32_t i = 0; i < mesh.indices.size(); ++i) {
        const auto& tri = mesh.indices[i];
        const auto h = intersect_triangle(shear, mesh.positions[tri[0]], mesh.positions[tri[1]],
                                          mesh.positions[tri[2]], valid);
        if (h) {
            best = BruteForceHit{*h, i};
            valid.max = h->t;
        }
    }
    return best;
}

}  // namespace hikari::testing
