// The lecture's assignment (課題：球体をレンダリングする) at one pixel, in the lecture's own
// notation: the ray P_E + tÊ, the sphere test ||P_E + tÊ − S|| = r as At² + Bt + C = 0 with D = B²
// − 4AC, the visible point P and normal N, then Lambert I_d = I₀ k_d cos α and Phong I_s = I₀ k_s
// cosⁿγ with R = L + 2aN, a = −L·N (Fig 4.29, 4.39), and the 8-bit value the pixel gets in the
// file.

#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "hikari/core/color.h"
#include "hikari/explain/explain.h"
#include "hikari/shading/lights.h"
#include "hikari/shading/phong.h"

namespace hikari {

namespace {

std::string num(double v) { return fmt::format("{:.6g}", v); }

std::string vec(Vec3 v) { return fmt::format("({:.6g}, {:.6g}, {:.6g})", v.x, v.y, v.z); }

/// One light as the lecture's L and I₀ at point `p`: L the direction the light travels (from
/// the light toward P), I₀ what arrives (a point light's intensity / d² when it falls off).
struct LectureLight {
    Vec3 travel;
    Vec3 arriving;
    std::string_view kind;
};

std::optional<LectureLight> lecture_light(const Light& light, Vec3 p) {
    if (const auto* d = light_as<DirectionalLight>(light))
        return LectureLight{normalize(d->direction), d->intensity, "directional"};
    if (const auto* pl = light_as<PointLight>(light)) {
        const Vec3 to_p = p - pl->position;
        const float d2 = dot(to_p, to_p);
        return LectureLight{normalize(to_p),
                            pl->inverse_square ? pl->intensity / d2 : pl->intensity, "point"};
    }
    return std::nullopt;  // area and environment lights are sums of many such lights
}

/// Ray–sphere, the lecture's way: A, B, C, D and, when D ≥ 0, the roots.
struct SphereTest {
    double a = 0, b = 0, c = 0, d = 0;
};

SphereTest sphere_test(const Ray& ray, const Sphere& s) {
    const Vec3 m = ray.origin - s.center;
    SphereTest q;
    q.a = dot(ray.direction, ray.direction);
    q.b = 2.0 * dot(ray.direction, m);
    q.c = double(dot(m, m)) - double(s.radius) * s.radius;
    q.d = q.b * q.b - 4.0 * q.a * q.c;
    return q;
}

void append_sphere_test(std::string& out, const SphereTest& q) {
    out += fmt::format("  A = Ê·Ê = {}\n", num(q.a));
    out += fmt::format("  B = 2Ê·(P_E − S) = {}\n", num(q.b));
    out += fmt::format("  C = ||P_E − S||² − r² = {}\n", num(q.c));
    out += fmt::format("  D = B² − 4AC = {}{}\n", num(q.d),
                       q.d >= 0 ? " (≥ 0: the ray meets the sphere)" : " (< 0: no intersection)");
    if (q.d < 0) return;
    const double root = std::sqrt(q.d);
    out +=
        fmt::format("  t = (−B − √D) / 2A = {} (the nearer root; the other, (−B + √D) / 2A = {})\n",
                    num((-q.b - root) / (2 * q.a)), num((-q.b + root) / (2 * q.a)));
}

/// The ray and the sphere, as the lecture writes them.
void append_ray(std::string& out, const Scene& scene, int x, int y, const Ray& ray) {
    const CameraFrame f = make_camera_frame(scene.camera);
    const double xs = (2.0 * (x + 0.5) / f.width - 1.0) * f.tan_half_fov_y * f.aspect;
    const double ys = (1.0 - 2.0 * (y + 0.5) / f.height) * f.tan_half_fov_y;
    out += fmt::format(
        "  pixel centre on the screen one unit in front of the eye:\n"
        "    xs = (2(x + 0.5)/W − 1)·tan(fov_y/2)·W/H = {}, ys = (1 − 2(y + 0.5)/H)·tan(fov_y/2) "
        "= {}\n",
        num(xs), num(ys));
    out += fmt::format("  ray P_E + tÊ: P_E = {}, Ê = {}\n", vec(ray.origin), vec(ray.direction));
}

/// The shading at P from one light: cos α, R, cos γ, cosⁿγ, I_d and I_s; returns I_d + I_s.
Vec3 append_light(std::string& out, uint32_t index, const LectureLight& l, const Material& m,
                  Vec3 n, Vec3 v, bool blocked) {
    out += fmt::format("  light {} ({}): L = {} (the direction the light travels), I₀ = {}\n",
                       index, l.kind, vec(l.travel), vec(l.arriving));
    const float a = -dot(l.travel, n);
    out += fmt::format("    cos α = −L·N = {}\n", num(a));
    if (a <= 0.0f) {
        out += "    cos α ≤ 0: the light is behind the surface, I_d = I_s = 0\n";
        return Vec3(0.0f);
    }
    if (blocked) {
        out += "    the shadow ray is blocked (影): I_d = I_s = 0\n";
        return Vec3(0.0f);
    }
    const Vec3 r = l.travel + 2.0f * a * n;
    const float cos_gamma = dot(r, v);
    const float power = phong_power(std::max(cos_gamma, 0.0f), m.shininess);
    const Vec3 diffuse = l.arriving * m.kd * a, specular = l.arriving * m.ks * power;
    out += fmt::format("    a = −L·N = {}\n    R = L + 2aN = {}\n", num(a), vec(r));
    out += fmt::format("    cos γ = R·V = {}\n", num(cos_gamma));
    out += fmt::format("    cosⁿγ = max(0, cos γ)ⁿ, n = {} : {}\n", num(m.shininess), num(power));
    out += fmt::format("    I_d = I₀ k_d cos α = {}\n", vec(diffuse));
    out += fmt::format("    I_s = I₀ k_s cosⁿγ = {}\n", vec(specular));
    return diffuse + specular;
}

std::string encoded(Vec3 c) {
    const auto linear = [](float v) { return std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f); };
    return fmt::format(
        "  written to the file (8 bits): sRGB ({}, {}, {}) (the default); --encoding linear, "
        "round(255·I): ({}, {}, {})\n",
        linear_to_srgb8(c.x), linear_to_srgb8(c.y), linear_to_srgb8(c.z), linear(c.x), linear(c.y),
        linear(c.z));
}

const Sphere* sphere_with_id(const Scene& scene, PrimitiveId id) {
    for (const Sphere& s : scene.spheres)
        if (s.id == id) return &s;
    return nullptr;
}

/// A camera ray that meets no sphere: each sphere's D says why (a few at most).
void append_misses(std::string& out, const Scene& scene, const RayTreeNode& node) {
    constexpr size_t k_max_spheres = 4;
    for (size_t i = 0; i < scene.spheres.size() && i < k_max_spheres; ++i) {
        const Sphere& s = scene.spheres[i];
        out += fmt::format("  sphere (primitive {}): S = {}, r = {}\n", s.id, vec(s.center),
                           num(s.radius));
        append_sphere_test(out, sphere_test(node.ray, s));
    }
    out += fmt::format("  I = background {}\n", vec(node.total));
    out += encoded(node.total);
}

}  // namespace

std::string explain_sphere_shading(const Scene& scene, int x, int y, const RayTreeNode& node) {
    std::string out = fmt::format(
        "\nThe assignment's quantities at pixel ({}, {}) (課題: ray–sphere, Lambert, Phong):\n", x,
        y);
    append_ray(out, scene, x, y, node.ray);
    const Sphere* sphere = node.hit ? sphere_with_id(scene, node.surface.id) : nullptr;
    if (!node.hit) {
        append_misses(out, scene, node);
        return out;
    }
    if (!sphere) return out + "  the ray's first hit is not a sphere: see the ray tree above\n";
    const Material& m = scene.materials[sphere->material];
    if (m.texture || m.vertex_colours)
        return out + "  the sphere's k_d comes from a texture: see the ray tree above\n";
    out += fmt::format("  sphere ||P_E + tÊ − S|| = r: S = {}, r = {}\n", vec(sphere->center),
                       num(sphere->radius));
    append_sphere_test(out, sphere_test(node.ray, *sphere));
    const Vec3 p = node.ray.origin + node.surface.t * node.ray.direction;
    const Vec3 n = (p - sphere->center) / sphere->radius, v = -node.ray.direction;
    out +=
        fmt::format("  P = P_E + tÊ = {}\n  N = (P − S) / r = {}\n  V = −Ê = {} (toward the eye)\n",
                    vec(p), vec(n), vec(v));
    Vec3 sum = scene.ambient * m.ka;
    out += fmt::format("  ambient I_a k_a = {}\n", vec(sum));
    for (uint32_t l = 0; l < scene.lights.size(); ++l) {
        const std::optional<LectureLight> light = lecture_light(scene.lights[l], p);
        if (!light) {
            out +=
                fmt::format("  light {}: an area or environment light, sampled (see above)\n", l);
            continue;
        }
        bool blocked = false;
        for (const ShadowRayRecord& r : node.shadow_rays) blocked |= r.light == l && r.blocked;
        sum += append_light(out, l, *light, m, n, v, blocked);
    }
    out += fmt::format("  I = I_a k_a + Σ (I_d + I_s) = {}\n", vec(sum));
    if (m.reflectivity > 0 || m.transparency > 0)
        out += fmt::format("  plus the mirror and refracted rays: the pixel's colour is {}\n",
                           vec(node.total));
    out += encoded(node.total);
    return out;
}

}  // namespace hikari
