// Area lights (scene/light.h, shading/lights/area_light.h) and their analytic soft shadows
// (shading/soft_shadows/visible_light.h): Lambert's contour formula against closed forms, the
// visible part of the light against a brute-force integration over the light, and sampling
// converging toward it.
#include "hikari/shading/soft_shadows/visible_light.h"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../../support/pi.h"
#include "hikari/shading/light_integral.h"

namespace hikari {
namespace {

using testing::k_pi;

/// A square light of side `size` centred over (cx, height, cz), shining down.
AreaLight square_light(float size, float height, float cx = 0.0f, float cz = 0.0f) {
    return {{cx - size / 2, height, cz - size / 2}, {size, 0, 0}, {0, 0, size}, Vec3(1.0f)};
}

TEST(AreaLight, ShinesFromTheSideItsEdgesCrossTowardOnly) {
    const AreaLight down = square_light(1, 2);
    EXPECT_LT(down.area_normal().y, 0.0f);
    const Vec3 up(0, 1, 0);
    EXPECT_GT(visible_light(down, {0, 0, 0}, up, up, nullptr).cosine_solid_angle, 0.0f);
    // Above the light: its back, dark unless two-sided.
    const Vec3 below(0, -1, 0);
    EXPECT_EQ(visible_light(down, {0, 4, 0}, below, below, nullptr).cosine_solid_angle, 0.0f);
    AreaLight both = down;
    both.two_sided = true;
    EXPECT_NEAR(visible_light(both, {0, 4, 0}, below, below, nullptr).cosine_solid_angle,
                visible_light(both, {0, 0, 0}, up, up, nullptr).cosine_solid_angle, 1e-6);
    EXPECT_EQ(max_component(sample_area_light<float>(down, Vec3(0, 4, 0), 0.5f, 0.5f).irradiance),
              0.0f);
}

TEST(AreaLight, ContourFormulaMatchesClosedForms) {
    const Vec3 up(0, 1, 0);
    // A light covering the whole sky above: ∫ cos θ dω = π.
    EXPECT_NEAR(visible_light(square_light(1e4f, 1), {0, 0, 0}, up, up, nullptr).cosine_solid_angle,
                k_pi, 2e-3 * k_pi);
    // A small far light: A cos θ cos θ′ / r².
    const AreaLight small = square_light(0.01f, 10, 3, 0);
    const double r2 = 9 + 100, cos_both = 10 / std::sqrt(r2);
    EXPECT_NEAR(visible_light(small, {0, 0, 0}, up, up, nullptr).cosine_solid_angle,
                1e-4 * cos_both * cos_both / r2, 1e-3 * 1e-4 * cos_both * cos_both / r2);
    // The unit square at height 1 over its corner, against the midpoint rule.
    const AreaLight corner{{0, 1, 0}, {1, 0, 0}, {0, 0, 1}, Vec3(1.0f)};
    double sum = 0;
    constexpr int n = 1000;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double x = (i + 0.5) / n, z = (j + 0.5) / n, r2 = x * x + 1 + z * z;
            sum += 1.0 / (r2 * r2);  // cos θ cos θ′ / r² with both cosines 1 / r
        }
    EXPECT_NEAR(visible_light(corner, {0, 0, 0}, up, up, nullptr).cosine_solid_angle, sum / (n * n),
                1e-5);
    // Cut by the horizon: a light standing vertically beside the point counts only above it.
    const AreaLight wall{{1, -1, -1}, {0, 0, 2}, {0, 2, 0}, Vec3(1.0f)};
    const AreaLight upper{{1, 0, -1}, {0, 0, 2}, {0, 1, 0}, Vec3(1.0f)};
    const Vec3 p(0, 0, 0);
    EXPECT_NEAR(visible_light(wall, p, up, up, nullptr).cosine_solid_angle,
                visible_light(upper, p, up, up, nullptr).cosine_solid_angle, 1e-6);
}

/// Whether the segment from p to q crosses triangle (a, b, c).
bool segment_hits(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c) {
    const Vec3 d = q - p, e1 = b - a, e2 = c - a, pv = cross(d, e2);
    const double det = dot(e1, pv);
    if (std::abs(det) < 1e-12) return false;
    const Vec3 tv = p - a;
    const double u = dot(tv, pv) / det;
    const Vec3 qv = cross(tv, e1);
    const double v = dot(d, qv) / det, t = dot(e2, qv) / det;
    return u >= 0 && v >= 0 && u + v <= 1 && t > 0 && t < 1;
}

/// ∫ cos θ dω over the part of `light` that `p` (normal up) sees past triangle t, by the midpoint
/// rule on an n × n grid over the light: Σ cos θ cos θ′ / r² dA.
double brute_force(const AreaLight& light, Vec3 p, const Vec3 (&t)[3], int n) {
    const double area = length(light.area_normal());
    double sum = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Vec3 y =
                light.corner + ((i + 0.5f) / n) * light.edge1 + ((j + 0.5f) / n) * light.edge2;
            if (segment_hits(p, y, t[0], t[1], t[2])) continue;
            const Vec3 d = y - p;
            const double r2 = dot(d, d), r = std::sqrt(r2);
            const double cos_theta = d.y / r, cos_light = d.y / r;  // horizontal light
            if (cos_theta > 0) sum += cos_theta * cos_light / r2;
        }
    return sum * area / (static_cast<double>(n) * n);
}

struct TriangleOccluderScene {
    AreaLight light{{-0.5f, 2.0f, -0.5f}, {1, 0, 0}, {0, 0, 1}, Vec3(1.0f)};
    Vec3 triangle[3] = {{-0.3f, 1.0f, -0.2f}, {0.4f, 1.1f, -0.1f}, {0.0f, 0.9f, 0.5f}};
    std::vector<Vec3> positions{triangle[0], triangle[1], triangle[2]};
    std::vector<std::array<uint32_t, 3>> indices{{0, 1, 2}};
    OccluderSet occluders{positions, indices, {}, {}, {}};

    /// Ground points across the shadow and penumbra.
    std::vector<Vec3> ground() const {
        std::vector<Vec3> points;
        for (int i = 0; i < 12; ++i)
            for (int j = 0; j < 12; ++j)
                points.push_back({-1.2f + 0.2f * i, 0.0f, -1.1f + 0.2f * j});
        return points;
    }
};

TEST(AreaLight, AnalyticShadowMatchesNumericalIntegration) {
    const TriangleOccluderScene s;
    const Vec3 up(0, 1, 0);
    double err2 = 0, ref2 = 0;
    bool some_penumbra = false;
    for (const Vec3 p : s.ground()) {
        const double analytic = visible_light(s.light, p, up, up, &s.occluders).cosine_solid_angle;
        const double reference = brute_force(s.light, p, s.triangle, 400);
        const double open = visible_light(s.light, p, up, up, nullptr).cosine_solid_angle;
        some_penumbra |= reference > 0.2 * open && reference < 0.8 * open;
        err2 += (analytic - reference) * (analytic - reference);
        ref2 += reference * reference;
    }
    EXPECT_TRUE(some_penumbra);
    EXPECT_LT(std::sqrt(err2 / ref2), 0.002);
}

TEST(AreaLight, SamplingConvergesToTheAnalyticShadow) {
    const TriangleOccluderScene s;
    SurfacePoint<float> point;
    point.normal = point.geometric_normal = point.to_eye = {0, 1, 0};
    MaterialSample<float> m;
    m.kd = Vec3(1.0f);
    const Light light = s.light;
    const auto visible = [&](size_t, const LightSample& sample, const SurfacePoint<float>& at,
                             bool) {
        const Vec3 q = at.position + sample.distance * sample.to_light;
        return !segment_hits(at.position, q, s.triangle[0], s.triangle[1], s.triangle[2]);
    };
    double err[2] = {0, 0};
    const int counts[2] = {4, 64};
    for (const Vec3 p : s.ground()) {
        point.position = p;
        const double exact =
            visible_light(s.light, p, point.normal, point.normal, &s.occluders).cosine_solid_angle;
        for (int k = 0; k < 2; ++k) {
            int32_t tested = 0;
            const double sampled =
                SampledLights{counts[k]}(0, light, point, m, false, visible, tested).x;
            err[k] += (sampled - exact) * (sampled - exact);
        }
    }
    EXPECT_LT(err[1], 0.25 * err[0]);  // stratified: faster than 1/N in squared error
}

TEST(AreaLight, OccludingSpheresAndPlanesCutTheLight) {
    const AreaLight light = square_light(1, 2);
    const Vec3 up(0, 1, 0);
    const float open = visible_light(light, {0, 0, 0}, up, up, nullptr).cosine_solid_angle;
    // A big sphere between point and light hides all of it; a small one a share of its outline.
    const std::vector<Sphere> big{{{0, 1, 0}, 0.9f}}, small{{{0, 1, 0}, 0.1f}};
    const OccluderSet all_hidden({}, {}, {}, big, {});
    EXPECT_NEAR(visible_light(light, {0, 0, 0}, up, up, &all_hidden).cosine_solid_angle, 0.0, 1e-6);
    const OccluderSet some_hidden({}, {}, {}, small, {});
    const float seen = visible_light(light, {0, 0, 0}, up, up, &some_hidden).cosine_solid_angle;
    // The sphere's outline from the point subtends a cone of half-angle asin(0.1); the light's
    // cosine-weighted solid angle loses about that cone's, ≈ π sin² 0.1.
    EXPECT_NEAR(open - seen, k_pi * 0.01, 0.05 * k_pi * 0.01);
    // A point on the sphere itself is not shadowed by it beyond its horizon.
    EXPECT_GT(visible_light(light, {0, 1.1f, 0}, up, up, &some_hidden).cosine_solid_angle, 0.0f);
    // A wall plane x = 0: a point at x < 0 sees only the light's half with x < 0.
    const std::vector<Plane> wall{{{0, 0, 0}, {1, 0, 0}}};
    const OccluderSet walled({}, {}, {}, {}, wall);
    const AreaLight half{{-0.5f, 2, -0.5f}, {0.5f, 0, 0}, {0, 0, 1}, Vec3(1.0f)};
    EXPECT_NEAR(visible_light(light, {-0.01f, 0, 0}, up, up, &walled).cosine_solid_angle,
                visible_light(half, {-0.01f, 0, 0}, up, up, nullptr).cosine_solid_angle, 1e-5);
}

TEST(AreaLight, VisiblePiecesAnswerWhichLightPointsAreSeen) {
    const TriangleOccluderScene s;
    const Vec3 up(0, 1, 0), p(0.0f, 0.0f, 0.1f);
    const VisibleLight seen = visible_light(s.light, p, up, up, &s.occluders);
    ASSERT_GT(seen.piece_count(), 0u);
    int agree = 0, total = 0;
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 40; ++j) {
            const Vec2 ab{(i + 0.5f) / 40, (j + 0.5f) / 40};
            const Vec3 y = s.light.corner + ab.x * s.light.edge1 + ab.y * s.light.edge2;
            agree +=
                seen.sees(ab) == !segment_hits(p, y, s.triangle[0], s.triangle[1], s.triangle[2]);
            ++total;
        }
    EXPECT_GE(agree, total - 4);  // only points on the shadow's edge may differ
}

TEST(AreaLight, DenseOccludersAreIntegratedExactly) {
    // A checkerboard of 2 x 200 small triangles between the point and the light: more than
    // k_max_cut_occluders, so their union is integrated over its boundary.
    const AreaLight light = square_light(1, 2);
    std::vector<Vec3> positions;
    std::vector<std::array<uint32_t, 3>> indices;
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 20; ++j) {
            if ((i + j) % 2) continue;
            const float x = -0.5f + 0.05f * i, z = -0.5f + 0.05f * j;
            const auto base = static_cast<uint32_t>(positions.size());
            positions.insert(
                positions.end(),
                {{x, 1, z}, {x + 0.05f, 1, z}, {x + 0.05f, 1, z + 0.05f}, {x, 1, z + 0.05f}});
            indices.push_back({base, base + 1, base + 2});
            indices.push_back({base, base + 2, base + 3});
        }
    const OccluderSet occluders(positions, indices, {}, {}, {});
    const Vec3 up(0, 1, 0), p(0.1f, 0, 0.05f);
    const VisibleLight seen = visible_light(light, p, up, up, &occluders);
    const float whole = visible_light(light, p, up, up, nullptr).cosine_solid_angle;
    // Brute force: the cosine-weighted share of light points whose segment misses every square.
    double open = 0, visible = 0;
    constexpr int n = 300;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Vec3 y{-0.5f + (i + 0.5f) / n, 2, -0.5f + (j + 0.5f) / n};
            const Vec3 d = y - p;
            const double w = d.y * d.y / (dot(d, d) * dot(d, d));
            const Vec3 at = p + 0.5f * d;  // where the segment crosses y = 1
            const int cx = static_cast<int>(std::floor((at.x + 0.5f) / 0.05f));
            const int cz = static_cast<int>(std::floor((at.z + 0.5f) / 0.05f));
            const bool blocked = cx >= 0 && cx < 20 && cz >= 0 && cz < 20 && (cx + cz) % 2 == 0;
            open += w;
            visible += blocked ? 0 : w;
        }
    // 300 x 300 light points resolve the squares' edges to a third of a percent.
    EXPECT_NEAR(seen.cosine_solid_angle / whole, visible / open, 0.003);
    // The holes answer which light points are seen, as the pieces do with few occluders.
    int agree = 0;
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 40; ++j) {
            const Vec2 ab{(i + 0.5f) / 40, (j + 0.5f) / 40};
            const Vec3 at = p + 0.5f * (Vec3{-0.5f + ab.x, 2, -0.5f + ab.y} - p);
            const int cx = static_cast<int>(std::floor((at.x + 0.5f) / 0.05f));
            const int cz = static_cast<int>(std::floor((at.z + 0.5f) / 0.05f));
            const bool blocked = cx >= 0 && cx < 20 && cz >= 0 && cz < 20 && (cx + cz) % 2 == 0;
            agree += seen.sees(ab) == !blocked;
        }
    EXPECT_GE(agree, 1600 - 40);  // only points on a square's edge may differ
}

TEST(AreaLight, OverlappingOccludersHideTheirUnionOnce) {
    // 60 copies of one square, each cut in two triangles, and a second square that overlaps it
    // by half: the union is 1.5 squares, however many times they repeat.
    const AreaLight light = square_light(1, 2);
    std::vector<Vec3> positions;
    std::vector<std::array<uint32_t, 3>> indices;
    const auto square = [&](float x, float z, float size) {
        const auto base = static_cast<uint32_t>(positions.size());
        positions.insert(positions.end(),
                         {{x, 1, z}, {x + size, 1, z}, {x + size, 1, z + size}, {x, 1, z + size}});
        indices.push_back({base, base + 1, base + 2});
        indices.push_back({base, base + 2, base + 3});
    };
    for (int k = 0; k < 60; ++k) square(-0.1f, -0.1f, 0.2f);
    square(0.0f, -0.1f, 0.2f);
    const OccluderSet many(positions, indices, {}, {}, {});
    // The same union as one 0.3 x 0.2 rectangle (two triangles: cut out piece by piece).
    const std::vector<Vec3> rectangle = {
        {-0.1f, 1, -0.1f}, {0.2f, 1, -0.1f}, {0.2f, 1, 0.1f}, {-0.1f, 1, 0.1f}};
    const std::vector<std::array<uint32_t, 3>> halves = {{0, 1, 2}, {0, 2, 3}};
    const OccluderSet one(rectangle, halves, {}, {}, {});
    const Vec3 up(0, 1, 0), p(0.05f, 0, 0.02f);
    EXPECT_NEAR(visible_light(light, p, up, up, &many).cosine_solid_angle,
                visible_light(light, p, up, up, &one).cosine_solid_angle, 1e-5);
}

}  // namespace
}  // namespace hikari
