#pragma once
// What the kernel tests (issue 46: Whitted, path, Z-buffer) share: the pixel-by-pixel comparison of
// a kernel render with the CPU renderer's, and the check that
// `--device cuda` without a device fails in one line.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "hikari/core/cuda_devices.h"
#include "hikari/core/error.h"
#include "hikari/frame/framebuffer.h"
#include "scene_files.h"

namespace hikari::testing {

/// How a kernel render differs from the reference: pixels whose colour differs by more than the
/// tolerance in some channel (relative to max(1, |reference|)), the largest such difference, and
/// pixels whose id, depth or normal differ at all.
struct KernelDifferences {
    size_t colour = 0, id = 0, depth = 0, normal = 0;
    float largest = 0;
};

inline KernelDifferences compare_kernel_render(const Framebuffer& kernels,
                                               const Framebuffer& reference, float tolerance) {
    KernelDifferences d;
    const auto& a = kernels.film.linear().pixels;
    const auto& b = reference.film.linear().pixels;
    EXPECT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
        float worst = 0.0f;
        for (int c = 0; c < 3; ++c)
            worst =
                std::max(worst, std::abs(a[i][c] - b[i][c]) / std::max(1.0f, std::abs(b[i][c])));
        d.largest = std::max(d.largest, worst);
        d.colour += (tolerance > 0.0f ? worst > tolerance : a[i] != b[i]) ? 1 : 0;
        if (!reference.id.empty()) {
            d.id += kernels.id[i] != reference.id[i] ? 1 : 0;
            const float da = kernels.depth[i], db = reference.depth[i];
            d.depth += (da != db && !(std::isinf(da) && std::isinf(db))) ? 1 : 0;
            d.normal += kernels.normal[i] != reference.normal[i] ? 1 : 0;
        }
    }
    return d;
}

/// `render()` on a CUDA device where there is none throws InputError in one line naming that.
template <class Render>
void expect_no_device_in_one_line(Render&& render) {
    if (find_cuda_devices().problem.empty()) GTEST_SKIP() << "a CUDA device is present";
    try {
        render();
        FAIL() << "rendered on a CUDA device that is not there";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("no CUDA device"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

}  // namespace hikari::testing
