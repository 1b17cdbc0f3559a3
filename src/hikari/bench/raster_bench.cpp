#include "hikari/bench/raster_bench.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>

#include "hikari/core/build_cache.h"
#include "hikari/core/mat4.h"
#include "hikari/core/parallel.h"
#include "hikari/methods/registry.h"
#include "hikari/scene/scene.h"

namespace hikari {
namespace {

using Clock = std::chrono::steady_clock;

/// SPEC §6: the clear colour (0.2, 0.25, 0.3) as the 8-bit framebuffer holds it.
constexpr std::array<uint8_t, 3> k_clear_bytes{51, 64, 76};

/// The SPEC's directional light, towards the light.
Vec3 light_direction() { return normalize(Vec3(-0.5f, 1.0f, 0.6f)); }

/// Vertex normals as the SPEC's vertex buffer has them: the normalised sum of the unnormalised
/// face normals (v1 − v0) × (v2 − v0) of the faces around each vertex.
std::vector<Vec3> vertex_normals(const BenchMesh& mesh) {
    std::vector<Vec3> sum(mesh.positions.size(), Vec3(0.0f));
    for (const auto& t : mesh.indices) {
        const Vec3 n = cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                             mesh.positions[t[2]] - mesh.positions[t[0]]);
        for (const uint32_t v : t) sum[v] += n;
    }
    for (Vec3& n : sum) {
        const float len = length(n);
        n = len > 0.0f ? n / len : Vec3(0.0f, 0.0f, 1.0f);
    }
    return sum;
}

/// SPEC §6's frame as a scene: the mesh with the SPEC's vertex normals in its one material, the
/// B1 camera (gluPerspective(45°, W/H, ...): hikari fits near and far itself), the directional
/// light and the clear colour. The fragment shader's terms are the lecture's Phong model:
/// 0.1 · albedo ambient (ka = albedo under Ia = 0.1), 0.7 · albedo · N·L diffuse
/// (kd = 0.7 · albedo) and 0.3 · (R·V)^32 specular (ks = 0.3, n = 32) from a light of intensity 1.
Scene spec_scene(const BenchMesh& mesh, const RasterBenchSettings& settings) {
    Scene scene;
    scene.camera.eye = b1_eye(mesh);
    scene.camera.look_at = bench_center(mesh);
    scene.camera.up = Vec3(0.0f, 1.0f, 0.0f);
    scene.camera.fov_y_degrees = 45.0f;
    scene.camera.width = settings.width;
    scene.camera.height = settings.height;
    // glClear writes the clear colour's bytes as they are, not gamma-encoded: the background is
    // the linear colour whose encoding (GammaEncoder) gives those bytes.
    for (int c = 0; c < 3; ++c)
        scene.background[c] = std::pow(static_cast<float>(k_clear_bytes[c]) / 255.0f, 2.2f);
    scene.ambient = Vec3(0.1f);
    const Vec3 albedo(0.8f, 0.75f, 0.7f);
    Material material;
    material.name = "spec";
    material.ka = albedo;
    material.kd = 0.7f * albedo;
    material.ks = Vec3(0.3f);
    material.shininess = 32.0f;
    scene.materials = {material};
    scene.lights = {DirectionalLight{-light_direction(), Vec3(1.0f)}};
    TriangleSet& t = scene.triangles;
    t.positions = mesh.positions;
    t.normals = vertex_normals(mesh);
    t.indices = mesh.indices;
    t.material.assign(mesh.indices.size(), 0);
    t.id.assign(mesh.indices.size(), 0);
    scene.primitive_count = 1;
    return scene;
}

/// 8-bit encoding of pow(clamp(c, 0, 1), 1/2.2) rounded as a unorm8 store rounds, without a
/// pow per channel: byte k covers the linear values from threshold k − 1 up to threshold k, and a
/// table over 2^16 buckets of [0, 1] gives the byte at each bucket's start, so at most a step
/// or two up remain (the thresholds crowd only near 0).
class GammaEncoder {
  public:
    GammaEncoder() {
        for (int k = 0; k < 255; ++k)
            m_threshold[k] = std::pow((static_cast<float>(k) + 0.5f) / 255.0f, 2.2f);
        m_threshold[255] = k_infinity;
        int byte = 0;
        for (int i = 0; i < k_buckets; ++i) {
            const float start = static_cast<float>(i) / static_cast<float>(k_buckets - 1);
            while (m_threshold[byte] <= start) ++byte;
            m_first[i] = static_cast<uint8_t>(byte);
        }
    }
    uint8_t operator()(float c) const {
        if (!(c > 0.0f)) return 0;  // NaN too
        c = std::min(c, 1.0f);
        // One bucket down: the product's rounding cannot put c below that bucket's start.
        const int i = std::max(static_cast<int>(c * static_cast<float>(k_buckets - 1)) - 1, 0);
        int byte = m_first[i];
        // Two buckets hold at most two thresholds: three steps without branches, and a loop
        // that never runs for any c as a guarantee.
        for (int step = 0; step < 3; ++step) byte += m_threshold[byte] <= c ? 1 : 0;
        while (m_threshold[byte] <= c) ++byte;
        return static_cast<uint8_t>(byte);
    }

  private:
    static constexpr int k_buckets = 1 << 16;
    std::array<float, 256> m_threshold{};
    std::array<uint8_t, k_buckets> m_first{};
};

/// The frame's 8-bit image, as glReadPixels gives it from the 8-bit framebuffer: each linear
/// colour gamma-encoded (SPEC §6: pow(c, 1/2.2)). Returns the pixels that differ from the clear
/// colour.
size_t encode_frame(const Image& linear, Vec3 background, const GammaEncoder& gamma, uint8_t* rgb) {
    return hikari::parallel_reduce(
        tbb::blocked_range<size_t>(0, linear.pixels.size(), 4096), size_t{0},
        [&](const tbb::blocked_range<size_t>& range, size_t covered) {
            for (size_t i = range.begin(); i != range.end(); ++i) {
                const Vec3 c = linear.pixels[i];
                uint8_t* o = rgb + 3 * i;
                if (c == background) {  // the clear colour's bytes, as glClear leaves them
                    std::copy(k_clear_bytes.begin(), k_clear_bytes.end(), o);
                    continue;
                }
                o[0] = gamma(c.x), o[1] = gamma(c.y), o[2] = gamma(c.z);
                covered += (o[0] != k_clear_bytes[0]) | (o[1] != k_clear_bytes[1]) |
                           (o[2] != k_clear_bytes[2]);
            }
            return covered;
        },
        std::plus<size_t>());
}

/// One B4 frame through the `zbuffer` method as `hikari render -m zbuffer` runs it: vertex
/// stage, binned tile Z-buffer, the shadow map when asked (drawn every frame: no session keeps
/// it), deferred shading in lanes. `film` is the frame's film, handed through and back, and
/// `cache` (bound to `scene`) keeps the Z-buffer's workspace, so that frames after the first
/// allocate no frame buffers.
void draw_frame(const Scene& scene, const MethodSettings& own, BuildCache& cache, Film& film) {
    // The SPEC draws the shadow map every frame: dropping what was built from the geometry
    // drops the maps, while the Z-buffer's workspace, which depends on nothing, is kept.
    cache.invalidate(SceneParts::geometry);
    RenderSettings settings;
    settings.aov_buffers = false;
    settings.cache = &cache;
    Framebuffer fb = render_scene(*find_method("zbuffer"), scene, std::move(film), settings, own);
    film = std::move(fb.film);
}

}  // namespace

std::string RasterBenchResult::to_json() const {
    const auto [low, high] = std::minmax_element(frame_ms.begin(), frame_ms.end());
    return fmt::format(
        "{{\"bench\": \"B4\", \"mesh\": \"{}\", \"threads\": {}, \"variant\": \"{}\", "
        "\"ms_per_frame\": {:.2f}, \"ms_min\": {:.2f}, \"ms_max\": {:.2f}, "
        "\"ms_all\": [{:.2f}], \"covered_pixels\": {}, \"shadowed_pixels\": {}, "
        "\"triangles\": {}, \"mtris_per_s\": {:.2f}, \"simd\": \"{}\"}}",
        mesh, threads, shadow ? "shadow" : "plain", median(frame_ms), frame_ms.empty() ? 0.0 : *low,
        frame_ms.empty() ? 0.0 : *high, fmt::join(frame_ms, ", "), covered_pixels, shadowed_pixels,
        triangles,
        frame_ms.empty() ? 0.0 : static_cast<double>(triangles) / (median(frame_ms) * 1e3), simd);
}

RasterBenchResult run_raster_bench(const BenchMesh& mesh, const std::string& mesh_name,
                                   const RasterBenchSettings& settings, Srgb8Image* image) {
    RasterBenchResult result;
    result.mesh = mesh_name;
    result.threads = settings.threads;
    result.shadow = settings.shadow;
    result.triangles = mesh.indices.size();
    result.simd = simd_level_name(settings.simd);

    // The scene, made once (llvmpipe's vertex buffer is uploaded before timing).
    const Scene scene = spec_scene(mesh, settings);
    MethodSettings own;
    own.shadows = settings.shadow ? ShadowMode::map : ShadowMode::none;
    own.raster.shadow_map_size = settings.shadow_map_size;
    own.raster.simd = settings.simd;
    const auto gamma = std::make_unique<GammaEncoder>();
    Film film(settings.width, settings.height, FilmFormat::linear);
    BuildCache cache;
    cache.bind(&scene);
    Srgb8Image local;
    Srgb8Image& out = image ? *image : local;
    out = Srgb8Image(settings.width, settings.height);
    for (int f = 0; f < settings.warmup_frames + settings.timed_frames; ++f) {
        const auto start = Clock::now();
        draw_frame(scene, own, cache, film);
        const size_t covered =
            encode_frame(film.linear(), scene.background, *gamma, out.bytes.data());
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        if (f >= settings.warmup_frames) result.frame_ms.push_back(ms);
        result.covered_pixels = covered;
    }
    if (settings.shadow) {
        // The covered pixels the shadow map darkened: those that differ from the same frame
        // drawn without it (after timing).
        MethodSettings unshadowed = own;
        unshadowed.shadows = ShadowMode::none;
        Film lit(settings.width, settings.height, FilmFormat::linear);
        draw_frame(scene, unshadowed, cache, lit);
        const auto& a = film.linear().pixels;
        const auto& b = lit.linear().pixels;
        for (size_t i = 0; i < a.size(); ++i) result.shadowed_pixels += !(a[i] == b[i]);
    }
    return result;
}

}  // namespace hikari
