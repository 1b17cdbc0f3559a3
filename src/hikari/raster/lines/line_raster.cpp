#include "hikari/raster/lines/line_raster.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <tbb/enumerable_thread_specific.h>

#include "hikari/core/cancel.h"
#include "hikari/core/color.h"
#include "hikari/core/parallel.h"
#include "hikari/core/ray.h"

namespace hikari {

namespace {

constexpr int k_band_rows = 16;

/// The fraction of a unit pixel square whose projection onto a direction (c, s) falls below
/// `x`, the pixel's centre projecting to 0. The projection spreads the square's area as the
/// convolution of two boxes of widths |c| and |s| (a trapezoid); this is its integral.
float projected_square_cdf(float x, float c, float s) {
    float a = std::abs(c), b = std::abs(s);
    if (a < b) std::swap(a, b);
    const float u = x + 0.5f * (a + b);
    if (u <= 0.0f) return 0.0f;
    if (u >= a + b) return 1.0f;
    if (b < 1e-6f) return u / a;
    if (u <= b) return u * u / (2.0f * a * b);
    if (u <= a) return (u - 0.5f * b) / a;
    const float rest = a + b - u;
    return 1.0f - rest * rest / (2.0f * a * b);
}

/// The part of the pixel square (projected onto direction (c, s), centre at x) in [lo, hi].
float overlap(float x, float lo, float hi, float c, float s) {
    return projected_square_cdf(hi - x, c, s) - projected_square_cdf(lo - x, c, s);
}

/// A segment in its own frame: start, unit direction, unit normal, length.
struct SegmentFrame {
    float ax, ay, ux, uy, nx, ny, length;
};

SegmentFrame frame_of(const LineSegment& s) {
    const float dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
    const float len = std::hypot(dx, dy);
    const float ux = len > 0.0f ? dx / len : 1.0f, uy = len > 0.0f ? dy / len : 0.0f;
    return {s.a.x, s.a.y, ux, uy, -uy, ux, len};
}

/// The x range [x0, x1] of pixel centres on the row at height yc where the slab
/// lo ≤ kx·x + ky·yc ≤ hi holds; false when none does.
bool slab_range(float kx, float ky, float yc, float lo, float hi, float& x0, float& x1) {
    const float rest = ky * yc;
    if (std::abs(kx) < 1e-6f) return rest >= lo && rest <= hi;
    float p = (lo - rest) / kx, q = (hi - rest) / kx;
    if (p > q) std::swap(p, q);
    x0 = std::max(x0, p);
    x1 = std::min(x1, q);
    return x0 <= x1;
}

/// One band of rows being drawn: the colour so far, and the segment covering most of each pixel.
/// A pixel is touched once its best coverage is above 0; its colour, depth and id are set when it
/// is first touched (so only the coverage is cleared from band to band).
struct BandAccumulator {
    Vec3 background;          ///< sRGB-encoded
    std::vector<Vec3> color;  ///< sRGB-encoded; the background where first touched
    std::vector<float> best_coverage, best_depth;
    std::vector<uint32_t> best_id;
    LineOcclusion occlusion;  ///< the surfaces lines may be hidden behind (none when empty)
};

void draw_segment(const LineDrawing& d, const LineSegment& seg, int row0, int row1,
                  BandAccumulator& acc) {
    const SegmentFrame f = frame_of(seg);
    if (!(f.length > 0.0f)) return;
    const Vec3 color = encode_srgb(seg.color);
    const float reach = 0.5f * d.line_width + 0.75f;  // a pixel square reaches 1/√2 from its centre
    const int y0 = std::max(row0, static_cast<int>(std::floor(std::min(seg.a.y, seg.b.y) - reach)));
    const int y1 =
        std::min(row1 - 1, static_cast<int>(std::ceil(std::max(seg.a.y, seg.b.y) + reach)));
    for (int y = y0; y <= y1; ++y) {
        const float yc = float(y) + 0.5f;
        float x0 = 0.0f, x1 = float(d.width);
        const float across0 = f.nx * f.ax + f.ny * f.ay, along0 = f.ux * f.ax + f.uy * f.ay;
        if (!slab_range(f.nx, f.ny, yc, across0 - reach, across0 + reach, x0, x1) ||
            !slab_range(f.ux, f.uy, yc, along0 - 0.75f, along0 + f.length + 0.75f, x0, x1))
            continue;
        const int first = std::max(0, static_cast<int>(std::floor(x0 - 0.5f)));
        const int last = std::min(d.width - 1, static_cast<int>(std::ceil(x1 - 0.5f)));
        for (int x = first; x <= last; ++x) {
            const float px = float(x) + 0.5f - f.ax, py = yc - f.ay;
            const float along = f.ux * px + f.uy * py;
            const float c =
                line_coverage(f.nx * px + f.ny * py, along, f.length, d.line_width, f.ux, f.uy);
            if (!(c > 0.0f)) continue;
            if (!acc.occlusion.depth.empty()) {
                // Each segment is tested for itself: where a hidden edge and a visible one share
                // a pixel (a sphere's front and back equator seen edge-on), the visible one stays.
                const float s = std::clamp(along / f.length, 0.0f, 1.0f);
                const float depth = camera_distance(d.camera, segment_world_point(seg, s));
                const float surface = acc.occlusion.depth[static_cast<size_t>(y) * d.width + x];
                if (depth > surface * (1.0f + acc.occlusion.tolerance)) continue;
            }
            const size_t i = static_cast<size_t>(y - row0) * d.width + x;
            if (acc.best_coverage[i] == 0.0f) {  // first touched: start from the background
                acc.color[i] = acc.background;
                acc.best_depth[i] = k_infinity;
                acc.best_id[i] = k_background_id;
            }
            // Porter & Duff's "over", segment after segment, on sRGB-encoded colour: what SVG
            // renderers do with strokes, so that the SVG file shows this image.
            acc.color[i] += c * (color - acc.color[i]);
            if (c > acc.best_coverage[i]) {
                const float s = std::clamp(along / f.length, 0.0f, 1.0f);
                acc.best_coverage[i] = c;
                acc.best_depth[i] = camera_distance(d.camera, segment_world_point(seg, s));
                acc.best_id[i] = seg.id + 1;
            }
        }
    }
}

/// Segment indices per band of rows, each band's in drawing order.
std::vector<std::vector<uint32_t>> bin_segments(const LineDrawing& d, int bands) {
    std::vector<std::vector<uint32_t>> bins(static_cast<size_t>(bands));
    const float reach = 0.5f * d.line_width + 0.75f;
    for (uint32_t k = 0; k < d.segments.size(); ++k) {
        const LineSegment& s = d.segments[k];
        const float lo = std::min(s.a.y, s.b.y) - reach, hi = std::max(s.a.y, s.b.y) + reach;
        if (!(hi >= 0.0f) || !(lo < float(d.height))) continue;
        const int b0 = std::max(0, static_cast<int>(lo) / k_band_rows);
        const int b1 = std::min(bands - 1, static_cast<int>(hi) / k_band_rows);
        for (int b = b0; b <= b1; ++b) bins[static_cast<size_t>(b)].push_back(k);
    }
    return bins;
}

}  // namespace

float line_coverage(float across, float along, float length, float width, float ux, float uy) {
    const float half = 0.5f * width;
    // The square projects onto the normal (−uy, ux) and onto u with the same two box widths.
    return overlap(across, -half, half, ux, uy) * overlap(along, 0.0f, length, ux, uy);
}

Framebuffer rasterize_lines(const LineDrawing& d, Film film, bool aov_buffers,
                            LineOcclusion occlusion) {
    Framebuffer fb(std::move(film), d.width, d.height, aov_buffers);
    const int bands = (d.height + k_band_rows - 1) / k_band_rows;
    const std::vector<std::vector<uint32_t>> bins = bin_segments(d, bands);
    // Each thread reuses one band's buffers from band to band: no allocation (and no page faults
    // of fresh memory) per band.
    const Vec3 background = encode_srgb(d.background);
    tbb::enumerable_thread_specific<BandAccumulator> accumulators;
    tbb::enumerable_thread_specific<std::vector<Vec3>> rows;
    hikari::parallel_for(0, bands, [&](int band) {
        throw_if_cancelled();  // SIGINT, Ctrl-C in Python: once per band
        const int row0 = band * k_band_rows, row1 = std::min(d.height, row0 + k_band_rows);
        const size_t n = static_cast<size_t>(row1 - row0) * d.width;
        BandAccumulator& acc = accumulators.local();
        acc.background = background;
        acc.color.resize(n);
        acc.best_coverage.assign(n, 0.0f);
        acc.best_depth.resize(n);
        acc.best_id.resize(n);
        acc.occlusion = occlusion;
        for (const uint32_t k : bins[static_cast<size_t>(band)])
            draw_segment(d, d.segments[k], row0, row1, acc);
        std::vector<Vec3>& row = rows.local();
        row.resize(static_cast<size_t>(d.width));
        for (int y = row0; y < row1; ++y) {
            const size_t first = static_cast<size_t>(y - row0) * d.width;
            const size_t pixel = static_cast<size_t>(y) * d.width;
            for (int x = 0; x < d.width; ++x) {
                const size_t i = first + x;
                row[x] = acc.best_coverage[i] > 0.0f ? decode_srgb(acc.color[i]) : d.background;
            }
            fb.set_colors(pixel, row.data(), row.size());
            if (!aov_buffers) continue;
            for (int x = 0; x < d.width; ++x) {
                const bool touched = acc.best_coverage[first + x] > 0.0f;
                fb.depth[pixel + x] = touched ? acc.best_depth[first + x] : k_infinity;
                fb.id[pixel + x] = touched ? acc.best_id[first + x] : k_background_id;
            }
        }
    });
    return fb;
}

}  // namespace hikari
