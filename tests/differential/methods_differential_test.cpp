// The differential suite: seeded random scenes of spheres, planes, triangles and small meshes,
// with the hard cases (cameras just above a floor, grazing floors, far walls, wide and narrow
// fields of view, nested spheres, coincident faces, triangles edge-on through the eye), rendered
// by every method that fills id and depth buffers, and compared pixel by pixel with each other
// and with a small independent caster in double precision written here. Every failure prints
// its seed; `HIKARI_DIFFERENTIAL_SEEDS=N` runs more seeds.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "hikari/io/scene/scene_json.h"
#include "hikari/methods/registry.h"

namespace hikari {
namespace {

struct V3 {
    double x = 0, y = 0, z = 0;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(double s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
V3 unit(V3 a) { return (1.0 / std::sqrt(dot(a, a))) * a; }
V3 from(Vec3 v) { return {v.x, v.y, v.z}; }

/// The nearest surface a ray from the eye meets: its primitive id (k_none for none) and the
/// distance.
struct CastHit {
    static constexpr uint32_t k_none = std::numeric_limits<uint32_t>::max();
    uint32_t id = k_none;
    double t = std::numeric_limits<double>::infinity();
};

/// An independent ray caster in double precision: the scene's spheres (the quadratic), planes
/// and triangles (Möller & Trumbore 1997), nothing shared with hikari's own intersection code.
class DoubleCaster {
  public:
    explicit DoubleCaster(const Scene& scene) : m_scene(scene) {
        const Camera& c = scene.camera;
        m_eye = from(c.eye);
        m_forward = unit(from(c.look_at) - m_eye);
        m_right = unit(cross(m_forward, from(c.up)));
        m_up = cross(m_right, m_forward);
        m_tan = std::tan(c.fov_y_degrees * M_PI / 360.0);
    }

    CastHit pixel(int i, int j) const {
        const Camera& c = m_scene.camera;
        const double aspect = static_cast<double>(c.width) / c.height;
        const double x = (2.0 * (i + 0.5) / c.width - 1.0) * m_tan * aspect;
        const double y = (1.0 - 2.0 * (j + 0.5) / c.height) * m_tan;
        const V3 d = unit(m_forward + x * m_right + y * m_up);
        CastHit best;
        const auto keep = [&](double t, uint32_t id) {
            if (t > 1e-9 && t < best.t) best = {id, t};
        };
        for (const Sphere& s : m_scene.spheres) {
            const V3 f = m_eye - from(s.center);
            const double b = dot(f, d), cc = dot(f, f) - double(s.radius) * s.radius;
            const double disc = b * b - cc;
            if (disc < 0) continue;
            const double root = std::sqrt(disc);
            keep(-b - root > 1e-9 ? -b - root : -b + root, s.id);
        }
        for (const Plane& p : m_scene.planes) {
            const double dn = dot(d, from(p.normal));
            if (dn != 0) keep(dot(from(p.point) - m_eye, from(p.normal)) / dn, p.id);
        }
        const TriangleSet& tris = m_scene.triangles;
        for (size_t k = 0; k < tris.size(); ++k) {
            const V3 p0 = from(tris.positions[tris.indices[k][0]]);
            const V3 e1 = from(tris.positions[tris.indices[k][1]]) - p0;
            const V3 e2 = from(tris.positions[tris.indices[k][2]]) - p0;
            const V3 pv = cross(d, e2);
            const double det = dot(e1, pv);
            if (std::abs(det) < 1e-14 * std::sqrt(dot(e1, e1) * dot(e2, e2))) continue;
            const V3 tv = m_eye - p0;
            const double u = dot(tv, pv) / det;
            const V3 qv = cross(tv, e1);
            const double v = dot(d, qv) / det;
            if (u < 0 || v < 0 || u + v > 1) continue;
            keep(dot(e2, qv) / det, tris.id[k]);
        }
        return best;
    }

  private:
    const Scene& m_scene;
    V3 m_eye, m_forward, m_right, m_up;
    double m_tan = 1;
};

/// A random scene as scene JSON, and which primitive (if any) the last one coincides with.
struct RandomScene {
    std::string json;
    std::optional<uint32_t> coincident;  ///< a primitive another lies exactly on
    uint32_t twin = 0;                   ///< that other one
};

/// A random scene for `seed`.
RandomScene random_scene(uint32_t seed) {
    std::mt19937 rng(seed);
    const auto uniform = [&](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(rng);
    };
    const auto pick = [&](std::initializer_list<double> values) {
        return *(values.begin() + std::uniform_int_distribution<size_t>(0, values.size() - 1)(rng));
    };
    const double height = pick({0.001, 0.01, 0.3, 1.5, 4.0});
    const double fov = pick({5.0, 30.0, 60.0, 100.0, 150.0, 179.0});
    std::string objects =
        R"({"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "m"})";
    uint32_t count = 1;  // objects so far: each is one primitive, numbered in order
    std::string first_triangle;
    uint32_t first_triangle_id = 0;
    if (uniform(0, 1) < 0.5) {  // a far wall, far beyond everything else
        objects +=
            R"(, {"type": "plane", "point": [0, 0, -60], "normal": [0, 0, 1], "material": "m"})";
        ++count;
    }
    const int spheres = std::uniform_int_distribution<int>(1, 4)(rng);
    for (int s = 0; s < spheres; ++s) {
        const double r = uniform(0.2, 1.0);
        const double x = uniform(-3, 3), y = uniform(0.2, 2.0), z = uniform(-9, -2);
        objects += fmt::format(
            R"(, {{"type": "sphere", "center": [{}, {}, {}], "radius": {}, "material": "m"}})", x,
            y, z, r);
        ++count;
        if (uniform(0, 1) < 0.3) {  // nested: a smaller sphere inside, never seen
            objects += fmt::format(
                R"(, {{"type": "sphere", "center": [{}, {}, {}], "radius": {}, "material": "m"}})",
                x, y, z, 0.5 * r);
            ++count;
        }
    }
    const int triangles = std::uniform_int_distribution<int>(1, 5)(rng);
    for (int t = 0; t < triangles; ++t) {
        const double cx = uniform(-3, 3), cy = uniform(0.1, 2.5), cz = uniform(-9, -2);
        std::string v;
        for (int k = 0; k < 3; ++k)
            v += fmt::format("{}[{}, {}, {}]", k ? ", " : "", cx + uniform(-1.5, 1.5),
                             cy + uniform(-1.0, 1.0), cz + uniform(-1.5, 1.5));
        objects += fmt::format(R"(, {{"type": "triangle", "vertices": [{}], "material": "m"}})", v);
        if (t == 0) first_triangle = v, first_triangle_id = count;
        ++count;
    }
    // A small closed mesh: an axis-aligned box as 12 triangles, wound outward.
    {
        const double x0 = uniform(-3, 2), y0 = uniform(0, 1), z0 = uniform(-9, -3);
        const double x1 = x0 + uniform(0.3, 1.5), y1 = y0 + uniform(0.3, 1.5),
                     z1 = z0 + uniform(0.3, 1.5);
        const double c[8][3] = {{x0, y0, z0}, {x1, y0, z0}, {x1, y1, z0}, {x0, y1, z0},
                                {x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}};
        const int faces[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                                  {3, 6, 2}, {3, 7, 6}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};
        for (const auto& f : faces) {
            objects += fmt::format(
                R"(, {{"type": "triangle", "vertices": [[{}, {}, {}], [{}, {}, {}], [{}, {}, {}]], "material": "m"}})",
                c[f[0]][0], c[f[0]][1], c[f[0]][2], c[f[1]][0], c[f[1]][1], c[f[1]][2], c[f[2]][0],
                c[f[2]][1], c[f[2]][2]);
            ++count;
        }
    }
    // Sometimes a triangle edge-on through the eye (its plane contains the eye: never seen).
    if (uniform(0, 1) < 0.5) {
        objects += fmt::format(
            R"(, {{"type": "triangle", "vertices": [[-30, {0}, 30], [30, {0}, 30], [0, {0}, -40]], "material": "m"}})",
            height);
        ++count;
    }
    // Sometimes a coincident face: the first triangle again, last (either may be seen).
    std::optional<uint32_t> coincident;
    uint32_t twin = 0;
    if (uniform(0, 1) < 0.4) {
        objects += fmt::format(R"(, {{"type": "triangle", "vertices": [{}], "material": "m"}})",
                               first_triangle);
        coincident = first_triangle_id;
        twin = count++;
    }
    const double look_y = height * uniform(0.0, 1.0);
    return {
        fmt::format(
            R"({{"camera": {{"eye": [0, {}, 0], "look_at": [{}, {}, -4], "fov_y": {}, "width": 48, "height": 36}},
            "materials": {{"m": {{"kd": 0.5}}}},
            "lights": [{{"type": "directional", "direction": [0.2, -1, -0.3], "intensity": 1}}],
            "objects": [{}]}})",
            height, uniform(-0.5, 0.5), look_y, fov, objects),
        coincident, twin};
}

/// How many seeds to run (HIKARI_DIFFERENTIAL_SEEDS, default 60).
int seed_count() {
    const char* env = std::getenv("HIKARI_DIFFERENTIAL_SEEDS");
    return env ? std::max(1, std::atoi(env)) : 60;
}

/// The fraction of pixels where `fb`'s id agrees with the caster's, and the largest relative
/// depth difference over those pixels whose id is a plane or triangle (flat in every method).
struct Agreement {
    double ids = 0;
    double depth = 0;
    size_t worst_pixel = 0;  ///< where the depth differs most
};

Agreement compare(const Framebuffer& fb, const std::vector<CastHit>& cast, const Scene& scene,
                  const RandomScene& random) {
    size_t same = 0, worst_pixel = 0;
    double worst = 0;
    for (size_t i = 0; i < cast.size(); ++i) {
        const uint32_t expected = cast[i].id == CastHit::k_none ? 0 : cast[i].id + 1;
        // A coincident face may show instead of its twin.
        const bool twin =
            random.coincident && expected == *random.coincident + 1 && fb.id[i] == random.twin + 1;
        if (fb.id[i] != expected && !twin) continue;
        ++same;
        if (expected == 0) continue;
        bool sphere = false;
        for (const Sphere& s : scene.spheres) sphere |= s.id + 1 == expected;
        // Beyond 1000 units (a far wall met at grazing angles through a 179° lens) a float
        // direction's rounding alone moves the hit by more than the tolerance.
        const double error = std::abs(fb.depth[i] - cast[i].t) / cast[i].t;
        if (!sphere && cast[i].t < 1e3 && error > worst) worst = error, worst_pixel = i;
    }
    return {static_cast<double>(same) / cast.size(), worst, worst_pixel};
}

/// The first pixels where `fb`'s id differs from the caster's, for the failure message.
std::string mismatches(const Framebuffer& fb, const std::vector<CastHit>& cast,
                       const RandomScene& random) {
    std::string out;
    int shown = 0;
    for (size_t i = 0; i < cast.size() && shown < 6; ++i) {
        const uint32_t expected = cast[i].id == CastHit::k_none ? 0 : cast[i].id + 1;
        if (fb.id[i] == expected || (random.coincident && expected == *random.coincident + 1 &&
                                     fb.id[i] == random.twin + 1))
            continue;
        out += fmt::format("\n  pixel {}: id {} at {}, caster id {} at {}", i, fb.id[i],
                           fb.depth[i], expected, cast[i].t);
        ++shown;
    }
    return out;
}

TEST(Differential, EveryMethodSeesWhatTheDoubleCasterSees) {
    for (uint32_t seed = 1; seed <= static_cast<uint32_t>(seed_count()); ++seed) {
        SCOPED_TRACE(fmt::format("seed {} (HIKARI_DIFFERENTIAL_SEEDS)", seed));
        std::vector<std::string> warnings;
        const RandomScene random = random_scene(seed);
        if (std::getenv("HIKARI_DIFFERENTIAL_PRINT"))
            std::printf("%s\ncoincident %d twin %u\n", random.json.c_str(),
                        random.coincident ? int(*random.coincident) : -1, random.twin);
        const Scene scene = parse_scene(random.json, "differential.json", ".", warnings);
        const DoubleCaster caster(scene);
        std::vector<CastHit> cast;
        for (int j = 0; j < scene.camera.height; ++j)
            for (int i = 0; i < scene.camera.width; ++i) cast.push_back(caster.pixel(i, j));
        MethodSettings own;
        own.shadows = ShadowMode::none;
        for (const char* name : {"raytrace", "zbuffer", "scanline", "depthsort"}) {
            SCOPED_TRACE(name);
            const bool ray = std::string(name) == "raytrace";
            const Framebuffer fb = render_scene(*find_method(name), scene,
                                                Film(scene.camera, FilmFormat::linear), {}, own);
            const Agreement a = compare(fb, cast, scene, random);
            // The ray tracer differs from the caster only where float and double rounding put a
            // pixel centre on different sides of an edge; the raster methods also where a
            // tessellated sphere's outline departs from the true one.
            EXPECT_GE(a.ids, ray ? 0.995 : 0.97) << mismatches(fb, cast, random);
            EXPECT_LE(a.depth, ray ? 1e-4 : 2e-3)
                << "pixel " << a.worst_pixel << ": id " << fb.id[a.worst_pixel] << ", depth "
                << fb.depth[a.worst_pixel] << " against " << cast[a.worst_pixel].t;
        }
    }
}

}  // namespace
}  // namespace hikari
