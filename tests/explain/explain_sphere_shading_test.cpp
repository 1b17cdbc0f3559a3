// hikari explain -m raytrace on a sphere: the assignment's quantities it prints (the lecture's
// A, B, C, D, t, P, N, cos α, R, cos γ, cosⁿγ, I_d, I_s, the sum and the 8-bit values) agree with
// the lecture's formulas worked out here, in double precision, from the scene's numbers alone.

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "../io/scene_test_util.h"
#include "hikari/explain/explain.h"

namespace hikari {
namespace {

// Not the assignment's numbers: an off-axis sphere, a slanted light, a wide image.
const std::string k_scene = R"({
  "camera": {"eye": [0.2, 0.1, 0.5], "look_at": [0, 0, -3], "up": [0, 1, 0], "fov_y": 50,
             "width": 64, "height": 48},
  "background": [0.05, 0.1, 0.2], "ambient": [0.2, 0.15, 0.1],
  "materials": {"m": {"ka": [0.7, 0.4, 0.3], "kd": [0.6, 0.5, 0.2], "ks": [0.5, 0.5, 0.4],
                      "shininess": 17}},
  "lights": [{"type": "directional", "direction": [0.8, -0.5, -1.2], "intensity": [0.9, 1, 0.8]}],
  "objects": [{"type": "sphere", "center": [0.3, -0.2, -3.2], "radius": 1.1, "material": "m"}]
})";

struct D3 {
    double x, y, z;
};
D3 operator+(D3 a, D3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator*(double s, D3 a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 cross(D3 a, D3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
D3 unit(D3 a) { return (1.0 / std::sqrt(dot(a, a))) * a; }

/// The lecture's quantities at pixel (x, y) of k_scene, by hand.
struct Expected {
    double d = 0, t = 0, cos_alpha = 0, cos_gamma = 0, power = 0;
    D3 sum{};
};

Expected lecture(int px, int py) {
    const D3 eye{0.2, 0.1, 0.5}, s{0.3, -0.2, -3.2};
    const double r = 1.1, n = 17, h = std::tan(25.0 * std::numbers::pi / 180.0);
    const D3 forward = unit(D3{0, 0, -3} - eye), right = unit(cross(forward, {0, 1, 0}));
    const D3 up = cross(right, forward);
    const double xs = (2.0 * (px + 0.5) / 64 - 1.0) * h * 64.0 / 48.0;
    const double ys = (1.0 - 2.0 * (py + 0.5) / 48) * h;
    const D3 e = unit(forward + xs * right + ys * up);
    Expected out;
    const double a = dot(e, e), b = 2.0 * dot(e, eye - s), c = dot(eye - s, eye - s) - r * r;
    out.d = b * b - 4 * a * c;
    if (out.d < 0) {
        out.sum = {0.05, 0.1, 0.2};
        return out;
    }
    out.t = (-b - std::sqrt(out.d)) / (2 * a);
    const D3 p = eye + out.t * e, normal = (1.0 / r) * (p - s);
    const D3 l = unit({0.8, -0.5, -1.2});
    out.cos_alpha = -dot(l, normal);
    const D3 reflected = l + (2 * out.cos_alpha) * normal;
    out.cos_gamma = dot(reflected, -1.0 * e);
    out.power = std::pow(std::max(out.cos_gamma, 0.0), n);
    const D3 ka{0.7, 0.4, 0.3}, kd{0.6, 0.5, 0.2}, ia{0.2, 0.15, 0.1}, i0{0.9, 1, 0.8},
        ks{0.5, 0.5, 0.4};
    out.sum = {ia.x * ka.x, ia.y * ka.y, ia.z * ka.z};
    if (out.cos_alpha > 0)
        out.sum = out.sum + D3{i0.x * (kd.x * out.cos_alpha + ks.x * out.power),
                               i0.y * (kd.y * out.cos_alpha + ks.y * out.power),
                               i0.z * (kd.z * out.cos_alpha + ks.z * out.power)};
    return out;
}

/// The number after `label` on its line of `text`; fails the test when the label is missing.
double number_after(const std::string& text, const std::string& label) {
    const size_t at = text.find(label);
    EXPECT_NE(at, std::string::npos) << label << " missing in\n" << text;
    if (at == std::string::npos) return NAN;
    return std::strtod(text.c_str() + at + label.size(), nullptr);
}

/// The three numbers of "(a, b, c)" after `label`.
D3 triple_after(const std::string& text, const std::string& label) {
    const size_t at = text.find(label);
    EXPECT_NE(at, std::string::npos) << label << " missing in\n" << text;
    if (at == std::string::npos) return {NAN, NAN, NAN};
    const char* p = text.c_str() + text.find('(', at + label.size()) + 1;
    char* end = nullptr;
    const double x = std::strtod(p, &end);
    const double y = std::strtod(end + 1, &end);
    return {x, y, std::strtod(end + 1, nullptr)};
}

long srgb8(double v) {
    v = std::clamp(v, 0.0, 1.0);
    return std::lround(255 * (v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055));
}

TEST(ExplainSphereShading, PrintsTheLecturesQuantitiesAsTheFormulasGiveThem) {
    const Scene scene = testing::parse(k_scene);
    // A lit pixel near the highlight, one on the shaded side, one off the sphere.
    for (const auto& [x, y] : {std::pair{31, 21}, std::pair{51, 33}, std::pair{4, 44}}) {
        SCOPED_TRACE(::testing::Message() << "pixel " << x << "," << y);
        const std::string text = explain_raytrace_pixel(scene, WhittedSettings{}, x, y);
        const Expected e = lecture(x, y);
        EXPECT_NEAR(number_after(text, "D = B² − 4AC = "), e.d, 1e-4 * (1 + std::abs(e.d)));
        const D3 sum = e.d < 0 ? triple_after(text, "I = background")
                               : triple_after(text, "I = I_a k_a + Σ (I_d + I_s) = ");
        EXPECT_NEAR(sum.x, e.sum.x, 1e-4);
        EXPECT_NEAR(sum.y, e.sum.y, 1e-4);
        EXPECT_NEAR(sum.z, e.sum.z, 1e-4);
        const D3 file = triple_after(text, "written to the file (8 bits): sRGB");
        EXPECT_NEAR(file.x, srgb8(e.sum.x), 1.0);
        EXPECT_NEAR(file.z, srgb8(e.sum.z), 1.0);
        const D3 linear = triple_after(text, "round(255·I):");
        EXPECT_NEAR(linear.y, std::lround(255 * std::clamp(e.sum.y, 0.0, 1.0)), 1.0);
        if (e.d < 0) continue;
        EXPECT_NEAR(number_after(text, "t = (−B − √D) / 2A = "), e.t, 1e-4);
        EXPECT_NEAR(number_after(text, "cos α = −L·N = "), e.cos_alpha, 1e-4);
        if (e.cos_alpha <= 0) continue;
        EXPECT_NEAR(number_after(text, "cos γ = R·V = "), e.cos_gamma, 1e-4);
        EXPECT_NEAR(number_after(text, "n = 17 : "), e.power, 1e-4);
    }
}

TEST(ExplainSphereShading, TheChosenPixelsShowWhatTheyShouldShow) {
    // The test above is only as good as its pixels: one lit with a visible highlight, one in the
    // sphere's own shade, one missing it.
    EXPECT_GT(lecture(31, 21).power, 0.01);
    EXPECT_GE(lecture(31, 21).d, 0);
    EXPECT_LT(lecture(51, 33).cos_alpha, 0);
    EXPECT_GE(lecture(51, 33).d, 0);
    EXPECT_LT(lecture(4, 44).d, 0);
}

}  // namespace
}  // namespace hikari
