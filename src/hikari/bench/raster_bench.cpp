#include "hikari/bench/raster_bench.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>

#include "hikari/core/mat4.h"
#include "hikari/core/parallel.h"
#include "hikari/raster/shade_visibility.h"
#include "hikari/raster/vertex_pipeline.h"
#include "hikari/raster/zbuffer.h"

namespace hikari {
namespace {

using Clock = std::chrono::steady_clock;

/// SPEC §6: the clear colour (0.2, 0.25, 0.3) as the 8-bit framebuffer holds it.
constexpr std::array<uint8_t, 3> k_clear_bytes{51, 64, 76};
constexpr float k_shadow_bias = 0.002f;  ///< SPEC §6, in window depth [0, 1]

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

/// The B1 camera (SPEC §2) as gluPerspective(45°, W/H, 0.05 d, 5 d) sees it.
RasterView camera_view(const BenchMesh& mesh, int width, int height) {
    const Vec3 c = bench_center(mesh);
    const auto d = static_cast<float>(mesh.diagonal);
    RasterView v;
    v.eye = b1_eye(mesh);
    v.forward = Vec3(0.0f, 0.0f, -1.0f);
    v.width = width;
    v.height = height;
    v.near_plane = 0.05f * d;
    v.far_plane = 5.0f * d;
    v.view_from_world = look_at(v.eye, c, Vec3(0.0f, 1.0f, 0.0f));
    v.clip_from_view = perspective(45.0f, static_cast<float>(width) / static_cast<float>(height),
                                   v.near_plane, v.far_plane);
    v.screen_from_clip = viewport(width, height);
    v.clip_from_world = v.clip_from_view * v.view_from_world;
    return v;
}

/// SPEC §6's light view: orthographic, eye c + L d looking at c, ±d/2, near 0.4 d, far 1.6 d.
RasterView light_view(const BenchMesh& mesh, int size) {
    const Vec3 c = bench_center(mesh);
    const auto d = static_cast<float>(mesh.diagonal);
    RasterView v;
    v.eye = c + light_direction() * d;
    v.forward = -light_direction();
    v.width = v.height = size;
    v.orthographic = true;
    v.near_plane = 1.0f;  // the depth key's scale under a parallel projection (RasterView)
    v.far_plane = 1.6f * d;
    v.view_from_world = look_at(v.eye, c, Vec3(0.0f, 1.0f, 0.0f));
    v.clip_from_view = orthographic(-0.5f * d, 0.5f * d, -0.5f * d, 0.5f * d, 0.4f * d, 1.6f * d);
    v.screen_from_clip = viewport(size, size);
    v.clip_from_world = v.clip_from_view * v.view_from_world;
    return v;
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

/// Everything a frame writes, kept between frames: a frame allocates nothing once warm.
struct FrameBuffers {
    ScreenProjection camera, light;
    ZBufferWorkspace camera_z, light_z;
    std::vector<uint32_t> nearest;
    std::vector<float> light_depth;
};

/// The inputs of the shading pass.
struct ShadeInputs {
    const BenchMesh& mesh;
    const std::vector<Vec3>& normals;
    const RasterView& view;
    const RasterView* light;  ///< null: no shadow pass
    const GammaEncoder& gamma;
};

/// SPEC §6's fragment shader over the visible pixels of a frame. One per range of rows: its
/// pointers are its own copies (the byte stores into the image cannot alias them), and it keeps
/// the last triangle's interpolation set up, since neighbouring pixels mostly see the same one.
class FrameShader {
  public:
    FrameShader(const ShadeInputs& in, const FrameBuffers& frame)
        : m_positions(in.mesh.positions.data()),
          m_indices(in.mesh.indices.data()),
          m_normals(in.normals.data()),
          m_screen(frame.camera.triangles.data()),
          m_indexed(frame.camera.indexed),
          m_vertices(frame.camera.screen.data()),
          m_clip(frame.camera.clip_positions.data()),
          m_inside(frame.camera.vertex_inside.data()),
          m_light_depth(frame.light_depth.data()),
          m_view(in.view),
          m_light(in.light),
          m_gamma(in.gamma),
          m_to_light(light_direction()) {}

    /// Pixels lit together: the lighting below runs as loops over this many lanes, which the
    /// compiler turns into SIMD.
    static constexpr int k_lanes = 8;

    /// The interpolated surface of k_lanes pixels, lane by lane.
    struct Lanes {
        alignas(32) float nx[k_lanes], ny[k_lanes], nz[k_lanes];  ///< normal, not unit
        alignas(32) float px[k_lanes], py[k_lanes], pz[k_lanes];  ///< world position
        alignas(32) float visibility[k_lanes];
        alignas(32) float r[k_lanes], g[k_lanes], b[k_lanes];
    };

    /// The perspective-correct normal and position at pixel (x, y), which sees screen
    /// triangle t, into lane k.
    void interpolate(uint32_t t, int x, int y, Lanes& lanes, int k) {
        if (t != m_triangle) set_up(t);
        std::array<float, 3> b{};
        if (m_from_screen) {
            // b_i / w_i from the screen-space edge functions, normalised (perspective-correct).
            const float dx = static_cast<float>(x) + 0.5f - m_origin.x;
            const float dy = static_cast<float>(y) + 0.5f - m_origin.y;
            for (int i = 0; i < 3; ++i) b[i] = m_ax[i] * dx + m_ay[i] * dy + m_a0[i];
            const float sum = b[0] + b[1] + b[2];
            const float inv_sum = sum != 0.0f ? 1.0f / sum : 0.0f;
            for (float& w : b) w *= inv_sum;
        } else {
            // A clipped piece's corners are not the mesh's: the source triangle's weights come
            // from clip space.
            const auto& idx = m_indices[screen_triangle(t).source];
            const double ndc_x = 2.0 * (x + 0.5) / m_view.width - 1.0;
            const double ndc_y = 1.0 - 2.0 * (y + 0.5) / m_view.height;
            perspective_barycentrics(m_clip[idx[0]], m_clip[idx[1]], m_clip[idx[2]], ndc_x, ndc_y,
                                     b);
        }
        const Vec3 n = b[0] * m_n[0] + b[1] * m_n[1] + b[2] * m_n[2];
        const Vec3 p = b[0] * m_p[0] + b[1] * m_p[1] + b[2] * m_p[2];
        lanes.nx[k] = n.x, lanes.ny[k] = n.y, lanes.nz[k] = n.z;
        lanes.px[k] = p.x, lanes.py[k] = p.y, lanes.pz[k] = p.z;
        lanes.visibility[k] = m_light && !lit(p) ? 0.0f : 1.0f;
    }

    /// SPEC §6's fragment shader over all lanes (lanes of uncovered pixels compute garbage that
    /// the caller ignores): r, g, b linear.
    void light(Lanes& lanes) const {
        const float lx = m_to_light.x, ly = m_to_light.y, lz = m_to_light.z;
        const float ex = m_view.eye.x, ey = m_view.eye.y, ez = m_view.eye.z;
        for (int k = 0; k < k_lanes; ++k) {
            float nx = lanes.nx[k], ny = lanes.ny[k], nz = lanes.nz[k];
            const float n_len2 = nx * nx + ny * ny + nz * nz;
            const float n_scale = n_len2 > 0.0f ? 1.0f / std::sqrt(n_len2) : 0.0f;
            nx *= n_scale, ny *= n_scale, nz *= n_scale;
            float vx = ex - lanes.px[k], vy = ey - lanes.py[k], vz = ez - lanes.pz[k];
            const float v_scale = 1.0f / std::sqrt(vx * vx + vy * vy + vz * vz);
            vx *= v_scale, vy *= v_scale, vz *= v_scale;
            // Two-sided: the normal turned toward the eye.
            const float side = nx * vx + ny * vy + nz * vz < 0.0f ? -1.0f : 1.0f;
            nx *= side, ny *= side, nz *= side;
            const float n_dot_l = nx * lx + ny * ly + nz * lz;
            // reflect(−L, N) = −L + 2 (N·L) N
            const float rx = 2.0f * n_dot_l * nx - lx, ry = 2.0f * n_dot_l * ny - ly,
                        rz = 2.0f * n_dot_l * nz - lz;
            float spec = rx * vx + ry * vy + rz * vz;
            spec = spec > 0.0f ? spec : 0.0f;
            for (int i = 0; i < 5; ++i) spec *= spec;  // ^32
            spec = n_dot_l > 0.0f ? spec : 0.0f;
            const float diffuse = 0.7f * (n_dot_l > 0.0f ? n_dot_l : 0.0f);
            const float vis = lanes.visibility[k];
            lanes.r[k] = 0.1f * 0.8f + vis * (diffuse * 0.8f + 0.3f * spec);
            lanes.g[k] = 0.1f * 0.75f + vis * (diffuse * 0.75f + 0.3f * spec);
            lanes.b[k] = 0.1f * 0.7f + vis * (diffuse * 0.7f + 0.3f * spec);
        }
    }

    const GammaEncoder& gamma() const { return m_gamma; }

    /// Starts loading screen triangle t, which a coming pixel sees.
    void prefetch(uint32_t t) const {
        if (m_indexed)
            __builtin_prefetch(m_indices + t);
        else
            __builtin_prefetch(m_screen + t);
    }

  private:
    /// The interpolation of screen triangle t: its source's corner attributes and, when the
    /// piece is the whole triangle, the edge functions relative to its first corner.
    void set_up(uint32_t t) {
        m_triangle = t;
        const ScreenTriangle st = screen_triangle(t);
        const auto& idx = m_indices[st.source];
        for (int i = 0; i < 3; ++i) {
            m_n[i] = m_normals[idx[i]];
            m_p[i] = m_positions[idx[i]];
        }
        m_from_screen = m_inside[idx[0]] && m_inside[idx[1]] && m_inside[idx[2]];
        m_origin = Vec2{st.v[0].position.x, st.v[0].position.y};
        for (int i = 0; i < 3; ++i) {
            // E_i(d) = (p − d) × (q − d) over the edge (p, q) opposite corner i, d relative to
            // the first corner: small numbers, so no cancellation for small triangles.
            const Vec3 a = st.v[(i + 1) % 3].position, c = st.v[(i + 2) % 3].position;
            const float px = a.x - m_origin.x, py = a.y - m_origin.y;
            const float qx = c.x - m_origin.x, qy = c.y - m_origin.y;
            const float w = st.v[i].inv_w;
            m_ax[i] = (py - qy) * w;
            m_ay[i] = (qx - px) * w;
            m_a0[i] = (px * qy - qx * py) * w;
        }
    }

    /// SPEC §6's one shadow tap: nearest texel, clamped to the edge, window depth 2 − inv_w
    /// (RasterView's depth key 1.5 − 0.5 z_ndc against 0.5 z_ndc + 0.5), bias k_shadow_bias.
    bool lit(Vec3 p) const {
        const Vec4 c = m_light->clip_from_world * Vec4(p, 1.0f);
        const int size = m_light->width;
        const int tx =
            std::clamp(static_cast<int>(std::floor((c.x * 0.5f + 0.5f) * size)), 0, size - 1);
        const int ty =
            std::clamp(static_cast<int>(std::floor((0.5f - c.y * 0.5f) * size)), 0, size - 1);
        const float stored_key = m_light_depth[static_cast<size_t>(ty) * size + tx];
        const float stored = 2.0f - 1.0f / stored_key;  // +∞ (nothing): 2, beyond every point
        return c.z * 0.5f + 0.5f - k_shadow_bias <= stored;
    }

    const Vec3* m_positions;
    const std::array<uint32_t, 3>* m_indices;
    const Vec3* m_normals;
    /// Screen triangle t: stored, or its source's corners when the frame is indexed.
    ScreenTriangle screen_triangle(uint32_t t) const {
        if (!m_indexed) return m_screen[t];
        return IndexedScreenTriangles{m_vertices, m_indices, t + 1}[t];
    }

    const ScreenTriangle* m_screen;
    bool m_indexed;
    const ScreenVertex* m_vertices;
    const Vec4* m_clip;
    const uint8_t* m_inside;
    const float* m_light_depth;
    const RasterView& m_view;
    const RasterView* m_light;
    const GammaEncoder& m_gamma;
    Vec3 m_to_light;
    uint32_t m_triangle = k_no_triangle;
    bool m_from_screen = false;
    Vec2 m_origin;
    std::array<Vec3, 3> m_n, m_p;
    std::array<float, 3> m_ax{}, m_ay{}, m_a0{};
};

/// The Z-buffer over a projection, indexed or stored.
void draw(const ScreenProjection& projection, const TriangleSet& tris, int width, int height,
          ZBufferWorkspace& workspace, uint32_t* nearest, float* depth, SimdLevel simd) {
    if (projection.indexed)
        zbuffer_draw(IndexedScreenTriangles{projection.screen.data(), tris.indices.data(),
                                            tris.indices.size()},
                     width, height, workspace, nearest, depth, nullptr, simd);
    else
        zbuffer_draw(projection.triangles, width, height, workspace, nearest, depth, nullptr, simd);
}

/// One B4 frame into `rgb` (3 bytes per pixel); returns the covered and shadowed pixel counts.
std::pair<size_t, size_t> draw_frame(const ShadeInputs& in, const TriangleSet& tris,
                                     FrameBuffers& frame, SimdLevel simd, uint8_t* rgb) {
    const int width = in.view.width, height = in.view.height;
    if (in.light) {
        project_to_screen(tris, *in.light, /*cull_back_faces=*/false, frame.light);
        draw(frame.light, tris, in.light->width, in.light->height, frame.light_z, nullptr,
             frame.light_depth.data(), simd);
    }
    project_to_screen(tris, in.view, /*cull_back_faces=*/false, frame.camera);
    draw(frame.camera, tris, width, height, frame.camera_z, frame.nearest.data(), nullptr, simd);
    // Deferred shading of the visible pixels; the clear colour elsewhere.
    return hikari::parallel_reduce(
        tbb::blocked_range<int>(0, height, 8), std::pair<size_t, size_t>{0, 0},
        [&](const tbb::blocked_range<int>& rows, std::pair<size_t, size_t> counts) {
            FrameShader shader(in, frame);
            FrameShader::Lanes lanes{};
            const uint32_t* nearest = frame.nearest.data();
            const GammaEncoder& gamma = shader.gamma();
            for (int y = rows.begin(); y != rows.end(); ++y) {
                uint8_t* out = rgb + static_cast<size_t>(y) * width * 3;
                const uint32_t* seen = nearest + static_cast<size_t>(y) * width;
                for (int x0 = 0; x0 < width; x0 += FrameShader::k_lanes) {
                    const int count = std::min(FrameShader::k_lanes, width - x0);
                    // The next group's triangles: their screen corners are read next.
                    for (int k = FrameShader::k_lanes; k < 2 * FrameShader::k_lanes; ++k)
                        if (x0 + k < width && seen[x0 + k] != k_no_triangle)
                            shader.prefetch(seen[x0 + k]);
                    int covered = 0;
                    for (int k = 0; k < count; ++k)
                        if (seen[x0 + k] != k_no_triangle) {
                            shader.interpolate(seen[x0 + k], x0 + k, y, lanes, k);
                            ++covered;
                        }
                    if (!covered) {  // background: the clear colour, 8 pixels at a time
                        for (int k = 0; k < count; ++k)
                            std::copy(k_clear_bytes.begin(), k_clear_bytes.end(),
                                      out + 3 * (x0 + k));
                        continue;
                    }
                    shader.light(lanes);
                    for (int k = 0; k < count; ++k) {
                        uint8_t r = k_clear_bytes[0], g = k_clear_bytes[1], b = k_clear_bytes[2];
                        if (seen[x0 + k] != k_no_triangle) {
                            r = gamma(lanes.r[k]), g = gamma(lanes.g[k]), b = gamma(lanes.b[k]);
                            counts.second += lanes.visibility[k] == 0.0f;
                            // Byte by byte: comparing the three as one array stalls on the
                            // stores just made.
                            counts.first += (r != k_clear_bytes[0]) | (g != k_clear_bytes[1]) |
                                            (b != k_clear_bytes[2]);
                        }
                        uint8_t* o = out + 3 * (x0 + k);
                        o[0] = r;
                        o[1] = g;
                        o[2] = b;
                    }
                }
            }
            return counts;
        },
        [](std::pair<size_t, size_t> a, std::pair<size_t, size_t> b) {
            return std::pair<size_t, size_t>{a.first + b.first, a.second + b.second};
        });
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

    // The vertex buffer, made once (llvmpipe's is uploaded before timing).
    TriangleSet tris;
    tris.positions = mesh.positions;
    tris.indices = mesh.indices;
    const std::vector<Vec3> normals = vertex_normals(mesh);
    const RasterView view = camera_view(mesh, settings.width, settings.height);
    const RasterView light = light_view(mesh, settings.shadow_map_size);
    const auto gamma = std::make_unique<GammaEncoder>();
    const ShadeInputs inputs{mesh, normals, view, settings.shadow ? &light : nullptr, *gamma};

    FrameBuffers frame;
    frame.camera.indexed_allowed = frame.light.indexed_allowed = true;
    frame.nearest.resize(static_cast<size_t>(settings.width) * settings.height);
    if (settings.shadow)
        frame.light_depth.resize(static_cast<size_t>(settings.shadow_map_size) *
                                 settings.shadow_map_size);
    Srgb8Image local;
    Srgb8Image& out = image ? *image : local;
    out = Srgb8Image(settings.width, settings.height);
    for (int f = 0; f < settings.warmup_frames + settings.timed_frames; ++f) {
        const auto start = Clock::now();
        const auto [covered, shadowed] =
            draw_frame(inputs, tris, frame, settings.simd, out.bytes.data());
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        if (f >= settings.warmup_frames) result.frame_ms.push_back(ms);
        result.covered_pixels = covered;
        result.shadowed_pixels = shadowed;
    }
    return result;
}

}  // namespace hikari
